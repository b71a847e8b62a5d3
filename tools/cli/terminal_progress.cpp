#include "tools/cli/terminal_progress.hpp"

#include "tools/io/progress.hpp"

namespace stoneskip::cli {

namespace {
class TerminalTicker : public ProgressTicker {
 public:
  TerminalTicker(const std::string& label, std::size_t total) : progress_(label, total) {}
  void tick(std::size_t n) override { progress_.tick(n); }

 private:
  Progress progress_;
};
}  // namespace

ProgressFactory terminal_progress() {
  return [](const std::string& label, std::size_t total) -> std::unique_ptr<ProgressTicker> {
    return std::make_unique<TerminalTicker>(label, total);
  };
}

}  // namespace stoneskip::cli
