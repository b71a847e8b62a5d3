#pragma once
// Dynamic scheduling of a sweep's throws over threads and MPI ranks (master/worker).
//
// Rank 0 (the master) holds the list of throws still to compute and hands them out in chunks:
// to its own compute threads (master_threads of them, in-process) and, on request, to the other
// ranks (the workers). Chunks are guided (Polychronopoulos & Kuck 1987): ceil(remaining /
// (2 · consumers)) throws, at most max_chunk, so chunks shrink towards the end and a 100× spread
// in the cost of a throw leaves little idle time at the tail.
//
// Protocol (tags in scheduler.cpp):
//   worker → master  ASK(n)      "send me n more chunks"; a worker asks for its first chunk at
//                                 start and for one more each time it starts a chunk, so the
//                                 next chunk is already there when it finishes (prefetch: the
//                                 master's reply latency is hidden behind a chunk's compute time)
//   master → worker  WORK(ids)   one reply per chunk asked: the throw indices; empty = no more
//   worker → master  RESULTS     the finished chunk's rows and notes (row_batch.hpp encoding)
//   worker → master  RETIRE      after its last RESULTS, once every ask has been answered
// The master's MPI thread never computes: it looks for messages, collects its threads' rows, and
// passes every batch to the sink (journal, progress) as it arrives, sleeping in between. It sleeps
// a quarter of the time the chunk being handed out now takes to compute (the mean throw time so
// far × the chunk size), within [min_poll_s, max_poll_s]: a worker's prefetched request is then
// answered long before it needs the chunk, and a sweep of 5 ms throws costs the master tens of
// wake-ups a second, not thousands. It returns when every worker has retired and its threads are
// done. Which rank or thread computed
// a throw, and in which order, never changes the throw's row (only its cost_ columns).
#include <cstdint>
#include <functional>
#include <vector>

#include "verification/sweep/mpi_session.hpp"
#include "verification/sweep/row_batch.hpp"

namespace stoneskip {

struct ThrowSite {
  int rank = 0;
  int thread = 0;
};

// Computes one throw and appends its row (and notes) to `out`. Called from several threads at
// once; must depend on the index only.
using ThrowEvaluator = std::function<void(std::uint64_t index, const ThrowSite& site, RowBatch& out)>;
// Receives each batch of finished throws on rank 0's MPI thread, in arrival order.
using BatchSink = std::function<void(const RowBatch&)>;

struct ScheduleOptions {
  int master_threads = 1;          // compute threads on rank 0; at least 1 when it is alone
  std::size_t max_chunk = 32;      // largest chunk handed out
  double min_poll_s = 5e-4;        // bounds of the master's sleep between looks for messages
  double max_poll_s = 2e-2;
  double handover_interval_s = 0.2;  // a master thread hands its rows over at least this often
};

struct ScheduleStats {
  int ranks = 1;
  int master_threads = 0;
  std::size_t throws = 0;          // computed in this run
  std::size_t chunks = 0;          // handed out (to threads and workers)
  std::size_t remote_throws = 0;   // of which computed by other ranks
  double wall_s = 0;
  double master_cpu_s = 0;         // CPU of rank 0's scheduling thread: MPI, sink, bookkeeping,
                                   // and polling for messages while idle
  double master_busy_cpu_s = 0;    // of which handling messages and rows (the cost per task)
  double sink_wall_s = 0;          // of which in the sink (journal, progress)
};

std::size_t guided_chunk(std::size_t remaining, std::size_t consumers, std::size_t max_chunk);

// Rank 0 (also the only process when there is no MPI job).
ScheduleStats run_master(const std::vector<std::uint64_t>& pending, std::size_t width, const ThrowEvaluator& evaluate,
                         const BatchSink& sink, const ScheduleOptions& options, MpiSession& mpi);
// Every other rank: computes what the master sends until told there is no more.
void run_worker(std::size_t width, const ThrowEvaluator& evaluate, MpiSession& mpi);

}  // namespace stoneskip
