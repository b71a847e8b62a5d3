#pragma once
// The adaptive stepper's real-time budget (solvers/realtime/stone_stepper.hpp, "Budget") measured
// over a set of throws at a ladder of budgets: per budget N (right-hand sides per frame), each
// throw's bounce count, right-hand sides, thread CPU, steps and the steps the budget forced, and
// the frames it spans. Beside reference counts (one per throw, −1 where there is none) a rung says
// how many throws keep the reference's count: the error the budget makes, on the quantity a
// player sees. A rung's worst frame costs at most N right-hand sides: its CPU bound per frame is
// N × (CPU per right-hand side), measured on the same runs.
#include <vector>

#include "verification/stones/throw_problem.hpp"
#include "verification/study/progress.hpp"

namespace stoneskip {

struct FrameBudgetLadderOptions {
  std::vector<long> rhs_per_frame{16, 32, 64, 128, 256};  // ascending
  double frame_dt_s = 1.0 / 90;                            // the paper's > 90 frames/s
  int workers = 2;
  ProgressFactory progress;  // empty: silently
  bool valid(std::string* why = nullptr) const;
};

struct FrameBudgetRung {
  long rhs_per_frame = 0;
  std::vector<int> bounces;       // per throw (−1: the run failed)
  long rhs_evaluations = 0;       // summed over the throws
  long steps = 0, forced_steps = 0;
  long frames = 0;                // Σ ⌈end time / frame⌉
  double cpu_s = 0;               // summed thread CPU
  double max_error_ratio = 0;     // the largest error-test ratio accepted (> 1: the budget forced it)
  double max_energy_gain_J = 0;   // the largest rise of energy over a contact (ThrowResult::max_energy_gain_J)
  long throws_gaining_energy = 0; // throws where it is above zero
  long compared = 0, matched = 0; // throws with a reference count; of those, with the same count
  double match_fraction() const;  // NaN when none is compared
  double forced_fraction() const { return steps > 0 ? double(forced_steps) / steps : 0; }
  double cpu_per_rhs_s() const { return rhs_evaluations > 0 ? cpu_s / rhs_evaluations : 0; }
  double cpu_per_frame_bound_s() const { return double(rhs_per_frame) * cpu_per_rhs_s(); }
  double mean_cpu_per_frame_s() const { return frames > 0 ? cpu_s / frames : 0; }
};

// Runs every throw (its realtime options with the budget set; its scheme if adaptive, else bs32)
// at every rung and counts the matches against reference_bounces (same order as throws; may be empty).
std::vector<FrameBudgetRung> run_frame_budget_ladder(const std::vector<ThrowProblem>& throws,
                                                     const std::vector<int>& reference_bounces,
                                                     const FrameBudgetLadderOptions& o);

// Counts the matches of a rung's bounces against reference counts (a reference of −1: not
// compared; a rung's −1, a failed run: compared, not matched).
void count_budget_matches(FrameBudgetRung& rung, const std::vector<int>& reference_bounces);

// The smallest rung at which, and at every larger one, the match fraction's 95 % Wilson interval
// lies at or above `target` (its lower end; work_precision_grid_stats.hpp); −1 when there is none.
long smallest_budget_meeting(const std::vector<FrameBudgetRung>& rungs, double target);

}  // namespace stoneskip
