#include "verification/study/progress.hpp"

namespace stoneskip {

namespace {
class SilentTicker : public ProgressTicker {
 public:
  void tick(std::size_t) override {}
};
}  // namespace

std::unique_ptr<ProgressTicker> start_progress(const ProgressFactory& factory, const std::string& label,
                                               std::size_t total) {
  if (factory) {
    if (auto t = factory(label, total)) return t;
  }
  return std::make_unique<SilentTicker>();
}

}  // namespace stoneskip
