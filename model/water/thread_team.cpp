#include "model/water/thread_team.hpp"

#include <stdexcept>

namespace stoneskip {
namespace {

// About 20 µs of polling before a worker or the caller sleeps: long enough to catch the next step
// of a stepping loop, short enough not to hold a core a scene needs for the stone.
constexpr int kSpinIterations = 4000;

inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

constexpr std::uint64_t pack(std::uint32_t generation, std::uint32_t chunks, std::uint32_t next) {
  return (static_cast<std::uint64_t>(generation) << 32) | (static_cast<std::uint64_t>(chunks) << 16) | next;
}

}  // namespace

ThreadTeam::ThreadTeam(int threads) {
  if (threads < 1) throw std::invalid_argument("ThreadTeam: threads must be >= 1");
  workers_.reserve(static_cast<std::size_t>(threads) - 1);
  for (int t = 1; t < threads; ++t) workers_.emplace_back([this] { worker_loop(); });
}

ThreadTeam::~ThreadTeam() {
  stop_.store(true, std::memory_order_release);
  wake_.fetch_add(1, std::memory_order_acq_rel);
  wake_.notify_all();
  for (auto& t : workers_) t.join();
}

void ThreadTeam::work(std::uint32_t generation, Fn fn, void* ctx) {
  std::uint64_t s = state_.load(std::memory_order_acquire);
  for (;;) {
    const std::uint32_t gen = static_cast<std::uint32_t>(s >> 32), chunks = (s >> 16) & 0xffff, next = s & 0xffff;
    if (gen != generation || next >= chunks) return;
    if (!state_.compare_exchange_weak(s, pack(gen, chunks, next + 1), std::memory_order_acq_rel, std::memory_order_acquire))
      continue;
    fn(ctx, static_cast<int>(next));
    if (done_.fetch_add(1, std::memory_order_acq_rel) + 1 == static_cast<int>(chunks)) done_.notify_one();
  }
}

void ThreadTeam::run_erased(Fn fn, void* ctx, int chunks) {
  if (chunks <= 0) return;
  if (workers_.empty()) {
    for (int k = 0; k < chunks; ++k) fn(ctx, k);
    return;
  }
  if (chunks > kMaxChunks) throw std::invalid_argument("ThreadTeam: too many chunks");
  // The previous call has ended (all its chunks done), so no worker can still claim from it.
  fn_.store(fn, std::memory_order_relaxed);
  ctx_.store(ctx, std::memory_order_relaxed);
  done_.store(0, std::memory_order_relaxed);
  const std::uint32_t gen = ++generation_;
  state_.store(pack(gen, static_cast<std::uint32_t>(chunks), 0), std::memory_order_release);
  wake_.store(gen, std::memory_order_release);
  wake_.notify_all();
  work(gen, fn, ctx);
  for (int spin = 0; spin < kSpinIterations; ++spin) {
    if (done_.load(std::memory_order_acquire) == chunks) return;
    cpu_relax();
  }
  for (int d = done_.load(std::memory_order_acquire); d != chunks; d = done_.load(std::memory_order_acquire))
    done_.wait(d, std::memory_order_acquire);
}

void ThreadTeam::worker_loop() {
  std::uint32_t seen = 0;
  for (;;) {
    std::uint32_t g = wake_.load(std::memory_order_acquire);
    for (int spin = 0; g == seen && spin < kSpinIterations; ++spin) {
      cpu_relax();
      g = wake_.load(std::memory_order_acquire);
    }
    while (g == seen) {
      wake_.wait(seen, std::memory_order_acquire);
      g = wake_.load(std::memory_order_acquire);
    }
    seen = g;
    if (stop_.load(std::memory_order_acquire)) return;
    // fn and ctx may already belong to a later call; then its generation differs from g and no
    // chunk is claimed with them (work() checks the generation in the same exchange as the claim).
    work(g, fn_.load(std::memory_order_acquire), ctx_.load(std::memory_order_acquire));
  }
}

}  // namespace stoneskip
