#pragma once
// A fixed team of threads kept alive between calls, for splitting one field step over cores:
// spawning threads per step costs more than a 500 × 500 step. run(f, chunks) calls f(k) once for
// every chunk k in [0, chunks), the chunks claimed one at a time by whichever thread is free, the
// caller included, and returns when all are done. On a machine shared with other work a worker
// may not be scheduled for a whole time slice: the caller then does the chunks it has not
// claimed, and only a chunk a worker has started is waited for. Idle workers spin briefly (a step
// follows the last one within microseconds in a stepping loop), then sleep on a futex
// (std::atomic::wait), so an idle team costs no CPU. One caller at a time.
#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

namespace stoneskip {

class ThreadTeam {
 public:
  explicit ThreadTeam(int threads);  // threads ≥ 1 (1: run() calls f(k) in order on the caller)
  ~ThreadTeam();
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;

  int size() const { return static_cast<int>(workers_.size()) + 1; }
  static constexpr int kMaxChunks = 0xffff;

  template <class F>
  void run(F& f, int chunks) {
    run_erased([](void* ctx, int chunk) { (*static_cast<F*>(ctx))(chunk); }, &f, chunks);
  }

 private:
  using Fn = void (*)(void*, int);
  void run_erased(Fn fn, void* ctx, int chunks);
  void work(std::uint32_t generation, Fn fn, void* ctx);  // claims and runs chunks of one call
  void worker_loop();

  std::vector<std::thread> workers_;
  // [generation: 32 bits][chunks: 16][next chunk: 16]; a claim is a compare-exchange on it, so a
  // worker that wakes late cannot claim a chunk of a call that has ended.
  std::atomic<std::uint64_t> state_{0};
  std::atomic<std::uint32_t> wake_{0};  // the generation workers were woken for
  std::atomic<int> done_{0};
  std::atomic<Fn> fn_{nullptr};
  std::atomic<void*> ctx_{nullptr};
  std::atomic<bool> stop_{false};
  std::uint32_t generation_ = 0;
};

// Splits [0, count) into `parts` contiguous ranges of nearly equal size; returns range `part`.
struct PartRange {
  long begin = 0, end = 0;
};
inline PartRange part_range(long count, int part, int parts) {
  return {count * part / parts, count * (part + 1) / parts};
}

}  // namespace stoneskip
