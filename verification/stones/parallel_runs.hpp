#pragma once
// Runs independent jobs on a few worker threads (the studies' sweeps use both cores of the
// machine) and ticks a progress line on stderr. Jobs write their own result slot; an exception in
// a job is re-thrown on the calling thread after all workers stop.
#include <cstddef>
#include <functional>
#include <string>

#include "verification/study/progress.hpp"

namespace stoneskip {

struct ParallelOptions {
  int workers = 2;          // 2: both cores of the reference machine
  std::string label;        // progress label
  ProgressFactory progress; // empty: no progress shown
};

void parallel_for(std::size_t count, const std::function<void(std::size_t)>& job, const ParallelOptions& options);

}  // namespace stoneskip

#include <vector>

namespace stoneskip {
// Runs a list of independent jobs (each writes its own result) on the workers.
void run_jobs(const std::vector<std::function<void()>>& jobs, const ParallelOptions& options);
}  // namespace stoneskip
