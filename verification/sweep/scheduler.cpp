#include "verification/sweep/scheduler.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "solvers/realtime/clocks.hpp"

namespace stoneskip {

namespace {

constexpr int kAsk = 11, kWork = 12, kResults = 13, kRetire = 14;
constexpr double kWorkerWait_s = 1e-4;  // a worker with nothing to do probes this often

using Clock = std::chrono::steady_clock;

std::vector<unsigned char> encode_ids(const std::vector<std::uint64_t>& ids) {
  std::vector<unsigned char> b(ids.size() * sizeof(std::uint64_t));
  if (!ids.empty()) std::memcpy(b.data(), ids.data(), b.size());
  return b;
}

std::vector<std::uint64_t> decode_ids(const std::vector<unsigned char>& b) {
  std::vector<std::uint64_t> ids(b.size() / sizeof(std::uint64_t));
  if (!ids.empty()) std::memcpy(ids.data(), b.data(), ids.size() * sizeof(std::uint64_t));
  return ids;
}

std::vector<unsigned char> encode_count(std::uint32_t n) {
  std::vector<unsigned char> b(sizeof n);
  std::memcpy(b.data(), &n, sizeof n);
  return b;
}

// The master's list of throws still to hand out, shared by its threads and its MPI thread.
class Dispenser {
 public:
  Dispenser(const std::vector<std::uint64_t>& pending, std::size_t consumers, std::size_t max_chunk)
      : pending_(pending), consumers_(std::max<std::size_t>(1, consumers)), max_chunk_(max_chunk) {}
  std::vector<std::uint64_t> take() {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::size_t n = guided_chunk(pending_.size() - next_, consumers_, max_chunk_);
    std::vector<std::uint64_t> chunk(pending_.begin() + static_cast<std::ptrdiff_t>(next_),
                                     pending_.begin() + static_cast<std::ptrdiff_t>(next_ + n));
    next_ += n;
    if (n) ++chunks_;
    return chunk;
  }
  std::size_t chunks() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return chunks_;
  }
  // Nothing more is handed out: each taker gets an empty chunk from now on.
  void stop() {
    std::lock_guard<std::mutex> lock(mutex_);
    next_ = pending_.size();
  }
  std::size_t next_chunk_size() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return guided_chunk(pending_.size() - next_, consumers_, max_chunk_);
  }

 private:
  const std::vector<std::uint64_t>& pending_;
  std::size_t consumers_, max_chunk_;
  std::size_t next_ = 0, chunks_ = 0;
  mutable std::mutex mutex_;
};

// What the master's compute threads hand to its MPI thread.
struct LocalResults {
  std::mutex mutex;
  std::condition_variable ready;
  RowBatch batch;
  int threads_done = 0;
  std::exception_ptr failure;
};

}  // namespace

std::size_t guided_chunk(std::size_t remaining, std::size_t consumers, std::size_t max_chunk) {
  if (remaining == 0) return 0;
  const std::size_t share = (remaining + 2 * consumers - 1) / (2 * std::max<std::size_t>(1, consumers));
  return std::clamp<std::size_t>(share, 1, std::max<std::size_t>(1, max_chunk));
}

ScheduleStats run_master(const std::vector<std::uint64_t>& pending, std::size_t width, const ThrowEvaluator& evaluate,
                         const BatchSink& sink, const ScheduleOptions& options, MpiSession& mpi) {
  const auto start = Clock::now();
  const CpuTimer cpu;
  ScheduleStats stats;
  stats.ranks = mpi.size();
  const int workers = mpi.size() - 1;
  // No more compute threads than throws to compute (--threads 100000 on a 6-throw sweep starts 6).
  int threads = static_cast<int>(std::min<std::size_t>(
      static_cast<std::size_t>(std::max(workers == 0 ? 1 : 0, options.master_threads)),
      std::max<std::size_t>(pending.size(), workers == 0 ? 1 : 0)));
  stats.master_threads = threads;
  Dispenser dispenser(pending, static_cast<std::size_t>(threads + workers), options.max_chunk);
  LocalResults local;
  local.batch.width = width;

  // 1. The master's own compute threads: rows handed over at the end of each chunk, and within a
  //    long chunk at least every handover_interval_s (what a kill can lose).
  //    A thread the system will not start (no memory for its stack, no process slot) leaves the
  //    work to those it did start; with none at all the sweep stops here, before any throw.
  std::vector<std::thread> pool;
  // Whatever ends this function early (a failed write of the sink, no memory), the threads stop
  // taking throws and are joined first: a joinable thread destroyed is std::terminate.
  struct JoinOnExit {
    Dispenser& dispenser;
    std::vector<std::thread>& pool;
    ~JoinOnExit() {
      dispenser.stop();
      for (auto& t : pool)
        if (t.joinable()) t.join();
    }
  } join_on_exit{dispenser, pool};
  const auto compute = [&](int t) {
    const ThrowSite site{mpi.rank(), t};
    try {
      RowBatch done;
      done.width = width;
      auto last = Clock::now();
      auto hand_over = [&] {
        std::lock_guard<std::mutex> lock(local.mutex);
        local.batch.append(done);
        local.ready.notify_one();
        done.clear();
        last = Clock::now();
      };
      for (;;) {
        const std::vector<std::uint64_t> chunk = dispenser.take();
        if (chunk.empty()) break;
        for (std::uint64_t i : chunk) {
          evaluate(i, site, done);
          if (Clock::now() - last >= std::chrono::duration<double>(options.handover_interval_s)) hand_over();
        }
        hand_over();
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(local.mutex);
      if (!local.failure) local.failure = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(local.mutex);
    ++local.threads_done;
    local.ready.notify_one();
  };
  std::string refused;
  for (int t = 0; t < threads && refused.empty(); ++t) {
    try {
      pool.emplace_back(compute, t);
    } catch (const std::system_error& e) {
      refused = e.what();
    }
  }
  if (!refused.empty()) {
    if (pool.empty() && workers == 0)
      throw std::runtime_error("cannot start a compute thread (" + refused + "): nothing computed; try fewer --threads");
    std::lock_guard<std::mutex> lock(local.mutex);  // the threads started count their ends against this
    threads = static_cast<int>(pool.size());
    stats.master_threads = threads;
  }

  // 2. The MPI thread: answer workers, collect rows, feed the sink.
  auto deliver = [&](const RowBatch& b) {
    if (b.rows() == 0 && b.notes.empty()) return;
    const auto t0 = Clock::now();
    sink(b);
    stats.sink_wall_s += std::chrono::duration<double>(Clock::now() - t0).count();
    stats.throws += b.rows();
  };
  // A quarter of the time the next chunk takes: mean wall per throw per consumer × chunk size.
  auto poll_interval = [&] {
    if (stats.throws == 0) return options.min_poll_s;
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    const double per_throw = elapsed * static_cast<double>(threads + workers) / static_cast<double>(stats.throws);
    const double chunk = static_cast<double>(std::max<std::size_t>(1, dispenser.next_chunk_size()));
    return std::clamp(0.25 * per_throw * chunk, options.min_poll_s, options.max_poll_s);
  };
  std::vector<bool> retired(static_cast<std::size_t>(mpi.size()), false);
  int retired_count = 0;
  for (;;) {
    const CpuTimer round;  // CPU of this round, counted as busy when it handled anything
    bool handled = false;
    MpiSession::Message m;
    while (workers > 0 && mpi.poll(-1, -1, m)) {
      handled = true;
      if (m.tag == kAsk) {
        std::uint32_t n = 0;
        if (m.bytes.size() == sizeof n) std::memcpy(&n, m.bytes.data(), sizeof n);
        for (std::uint32_t k = 0; k < n; ++k) mpi.send(m.source, kWork, encode_ids(dispenser.take()));
      } else if (m.tag == kResults) {
        RowBatch b;
        if (!decode(m.bytes.data(), m.bytes.size(), b) || (b.rows() > 0 && b.width != width))
          throw std::runtime_error("sweep: malformed results from rank " + std::to_string(m.source));
        stats.remote_throws += b.rows();
        deliver(b);
      } else if (m.tag == kRetire) {
        if (!retired[static_cast<std::size_t>(m.source)]) ++retired_count;
        retired[static_cast<std::size_t>(m.source)] = true;
      }
    }
    if (workers > 0) mpi.progress();
    RowBatch mine;
    bool threads_finished = false;
    {
      std::unique_lock<std::mutex> lock(local.mutex);
      auto something = [&] { return local.batch.rows() > 0 || !local.batch.notes.empty(); };
      if (!something()) {
        if (workers > 0)  // sleep until a thread hands over rows or it is time to look for messages
          local.ready.wait_for(lock, std::chrono::duration<double>(poll_interval()), something);
        else
          local.ready.wait(lock, [&] { return something() || local.threads_done == threads; });
      }
      std::swap(mine, local.batch);
      local.batch.width = width;
      threads_finished = local.threads_done == threads;
    }
    if (mine.rows() > 0 || !mine.notes.empty()) {
      const CpuTimer busy;
      deliver(mine);
      stats.master_busy_cpu_s += busy.seconds();
    }
    if (handled) stats.master_busy_cpu_s += round.seconds();
    if (threads_finished && retired_count == workers) break;
  }
  for (auto& t : pool) t.join();
  if (local.failure) std::rethrow_exception(local.failure);
  stats.chunks = dispenser.chunks();
  stats.master_cpu_s = cpu.seconds();
  stats.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
  if (stats.throws != pending.size())
    throw std::runtime_error("sweep: " + std::to_string(stats.throws) + " throws came back of " +
                             std::to_string(pending.size()) + " handed out");
  return stats;
}

void run_worker(std::size_t width, const ThrowEvaluator& evaluate, MpiSession& mpi) {
  const ThrowSite site{mpi.rank(), 0};
  std::deque<std::vector<std::uint64_t>> queue;
  int unanswered = 0;
  bool no_more = false;
  auto take = [&](const MpiSession::Message& m) {
    --unanswered;
    if (m.bytes.empty())
      no_more = true;
    else
      queue.push_back(decode_ids(m.bytes));
  };
  auto drain = [&] {
    MpiSession::Message m;
    while (mpi.poll(0, kWork, m)) take(m);
    mpi.progress();
  };
  mpi.send(0, kAsk, encode_count(1));
  ++unanswered;
  for (;;) {
    drain();
    if (queue.empty()) {
      if (unanswered == 0) break;  // every ask answered, the last with "no more"
      take(mpi.wait(0, kWork, kWorkerWait_s));
      continue;
    }
    const std::vector<std::uint64_t> chunk = std::move(queue.front());
    queue.pop_front();
    if (!no_more) {  // prefetch: the next chunk travels while this one computes
      mpi.send(0, kAsk, encode_count(1));
      ++unanswered;
    }
    RowBatch done;
    done.width = width;
    for (std::uint64_t i : chunk) {
      evaluate(i, site, done);
      drain();  // completes sends in flight, takes in the prefetched chunk
    }
    mpi.send(0, kResults, encode(done));
  }
  mpi.flush();
  mpi.send(0, kRetire, {});
  mpi.flush();
}

}  // namespace stoneskip
