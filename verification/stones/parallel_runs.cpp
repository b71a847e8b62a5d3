#include "verification/stones/parallel_runs.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>


namespace stoneskip {

void parallel_for(std::size_t count, const std::function<void(std::size_t)>& job, const ParallelOptions& options) {
  if (count == 0) return;
  const std::unique_ptr<ProgressTicker> progress = start_progress(options.progress, options.label, count);
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto worker = [&] {
    for (;;) {
      const std::size_t i = next.fetch_add(1);
      if (i >= count) return;
      {
        std::lock_guard<std::mutex> lock(failure_mutex);
        if (failure) return;
      }
      try {
        job(i);
      } catch (...) {
        std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
      }
      progress->tick();
    }
  };
  const int n = std::max(1, std::min<int>(options.workers, static_cast<int>(count)));
  std::vector<std::thread> threads;
  for (int k = 1; k < n; ++k) threads.emplace_back(worker);
  worker();
  for (auto& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace stoneskip

namespace stoneskip {
void run_jobs(const std::vector<std::function<void()>>& jobs, const ParallelOptions& options) {
  parallel_for(jobs.size(), [&](std::size_t i) { jobs[i](); }, options);
}
}  // namespace stoneskip
