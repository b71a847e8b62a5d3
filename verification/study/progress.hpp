#pragma once
// Progress of long work, reported through a callback so that nothing in verification/ prints.
// A study asks its ProgressFactory for a ticker per unit of work it starts ("convergence", 120
// runs) and ticks it from any thread; the command line supplies a factory that draws a bar on
// stderr (tools/io/progress.hpp), tests supply none.
#include <cstddef>
#include <functional>
#include <memory>
#include <string>

namespace stoneskip {

class ProgressTicker {
 public:
  virtual ~ProgressTicker() = default;  // the work is over (finished or abandoned)
  virtual void tick(std::size_t n = 1) = 0;  // thread-safe
};

using ProgressFactory = std::function<std::unique_ptr<ProgressTicker>(const std::string& label, std::size_t total)>;

// A ticker from the factory, or one that does nothing when there is no factory.
std::unique_ptr<ProgressTicker> start_progress(const ProgressFactory& factory, const std::string& label,
                                               std::size_t total);

}  // namespace stoneskip
