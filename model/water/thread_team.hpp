#pragma once
// A fixed team of threads kept alive between calls, for splitting one field step over cores:
// spawning threads per step costs more than a 500 × 500 step. run(f) calls f(part) for every part
// in [0, size()), part 0 on the calling thread, and returns when all parts are done. Idle workers
// spin briefly (a step follows the last one within microseconds in a stepping loop), then sleep
// on a futex (std::atomic::wait), so a team left idle costs no CPU. One caller at a time.
#include <atomic>
#include <thread>
#include <vector>

namespace stoneskip {

class ThreadTeam {
 public:
  explicit ThreadTeam(int threads);  // threads ≥ 1 (1: run() calls f(0) directly)
  ~ThreadTeam();
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;

  int size() const { return static_cast<int>(workers_.size()) + 1; }

  template <class F>
  void run(F& f) {
    run_erased([](void* ctx, int part) { (*static_cast<F*>(ctx))(part); }, &f);
  }

 private:
  void run_erased(void (*fn)(void*, int), void* ctx);
  void work(int part);

  std::vector<std::thread> workers_;
  void (*fn_)(void*, int) = nullptr;
  void* ctx_ = nullptr;
  std::atomic<unsigned> generation_{0};
  std::atomic<int> pending_{0};
  std::atomic<bool> stop_{false};
};

// Splits [0, count) into `parts` contiguous ranges of nearly equal size; returns range `part`.
struct PartRange {
  long begin = 0, end = 0;
};
inline PartRange part_range(long count, int part, int parts) {
  return {count * part / parts, count * (part + 1) / parts};
}

}  // namespace stoneskip
