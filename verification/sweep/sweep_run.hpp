#pragma once
// A whole sweep on rank 0: check the output and any journal before a throw runs, schedule the
// throws still missing (scheduler.hpp), journal every finished batch, and at the end write the
// result file in throw-index order and remove the journal.
//
//   SweepPlan plan = SweepPlan::prepare(spec, options);  // InputError: bad output, stale journal
//   SweepSummary s = plan.run(evaluate, mpi);            // rank 0; the other ranks run_worker()
//
// A run killed at any moment leaves the journal; `--resume` (options.resume) reads it back, cuts a
// torn tail, and computes only the throws it lacks. The table is then the same bits as an
// uninterrupted run's, every column but cost_*.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "verification/study/progress.hpp"

#include "verification/sweep/journal.hpp"
#include "verification/sweep/sweep_result.hpp"

namespace stoneskip {

struct SweepRunOptions {
  std::filesystem::path out;        // the result file (.h5)
  bool resume = false;
  int master_threads = -1;          // compute threads on rank 0; −1: every core when it is the only
                                    // rank, 1 beside MPI workers; 0 with workers: it only schedules
  std::size_t max_chunk = 32;
  double sync_interval_s = 1.0;     // fdatasync of the journal at most this often
  ProgressFactory progress;         // how the throws are shown (the command line: a bar with the time left); empty: silently
};

struct SweepSummary {
  std::filesystem::path out;
  std::size_t throws = 0, computed = 0, recovered = 0;
  std::size_t failed_solves = 0, not_run = 0;
  std::size_t noted = 0;            // throws with a note (a failure, a contact off the pond)
  bool was_complete = false;        // --resume found a finished result file: nothing to do
  std::vector<std::string> warnings;  // one line each, for stderr (a journal damaged mid-file)
  ScheduleStats schedule;
  std::string brief() const;        // one line
};

class SweepPlan {
 public:
  // Rank 0, before any throw: checks that the output can be written and decides what to compute
  // (everything; or, with resume, what the journal lacks). Creates or opens the journal last, so a
  // refused plan leaves no file behind.
  static SweepPlan prepare(const SweepData& spec, const SweepRunOptions& options);
  std::size_t pending() const { return pending_.size(); }
  const std::filesystem::path& output() const { return options_.out; }
  SweepSummary run(const ThrowEvaluator& evaluate, MpiSession& mpi);

 private:
  SweepPlan() = default;
  SweepData data_;                  // design, provenance; throws filled as rows arrive
  SweepRunOptions options_;
  std::unique_ptr<SweepJournal> journal_;
  std::vector<std::uint64_t> pending_;
  std::vector<bool> have_;
  std::size_t recovered_ = 0;
  bool was_complete_ = false;
  std::vector<std::string> warnings_;
  void take(const RowBatch& b);     // rows into the table by throw index, notes kept
};

// The columns of a sweep's table (the record's) for a design and solvers.
ThrowRecord sweep_record(const SweepDesign& design, SweepSolvers solvers);

}  // namespace stoneskip
