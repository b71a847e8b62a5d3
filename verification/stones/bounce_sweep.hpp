#pragma once
// Bounce count against one throw parameter (spin — the paper's Fig. 8 —, speed, attack angle,
// path angle), with every change of the count located by bisection: between two
// neighbouring grid values whose counts differ, the parameter is halved down to a stated
// tolerance, so a threshold is reported as a value ± tolerance/2, not only as counts on a grid.
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "verification/stones/parallel_runs.hpp"
#include "verification/stones/throw_problem.hpp"

namespace stoneskip {

enum class SweepParameter { spin_rev_s, speed_m_s, attack_angle_deg, path_angle_deg };
const char* to_string(SweepParameter p);          // the [throw] key: "spin_rev_s", ...
const char* unit_of(SweepParameter p);            // "rev/s", "m/s", "deg"
bool parse_sweep_parameter(const std::string& s, SweepParameter& out);
double& parameter_of(ThrowParameters& tp, SweepParameter p);

struct BounceSweepSpec {
  std::string name;                 // [a-z0-9_], e.g. "spin_physical_realtime"
  ThrowProblem base;                // the throw whose parameter is varied
  SweepParameter parameter = SweepParameter::spin_rev_s;
  std::vector<double> values;       // ascending grid
  Convention convention = Convention::physical;
  SolverChoice solver;
  double threshold_tolerance = 0.1; // bisection stops when the bracket is narrower (parameter units),
                                    // or when no double lies strictly between its ends
  int max_thresholds = 12;          // changes beyond this many are listed but not bisected
  // Per grid value, an ensemble of this many throws with the speed × (1 ± ε), ε log-spaced over
  // [ensemble_smallest, ensemble_largest] (verification/study/ensemble_difference.hpp): a count
  // that a 1e-9 nudge changes is compared on ensembles, never run against run (regress). 0: none.
  int ensemble_members = 0;
  double ensemble_smallest = 1e-9, ensemble_largest = 1e-6;
};

struct CountThreshold {
  double lo = 0, hi = 0;            // count_below at lo, count_above at hi, hi − lo ≤ tolerance
  int count_below = 0, count_above = 0;
  bool bisected = false;            // false: only bracketed by the grid
  // The grid's count at the upper end of the cell the change was found in. Bisection follows one
  // change; where count_above differs from it (1 → 2 at 10.9, 0 at the grid's 14), the cell holds
  // at least one more change that was not located.
  int count_at_cell_end = 0;
  // Bisection stopped where a run failed (no count: the change may lie on either side of it), and
  // [lo, hi] is the bracket before that run; bisected stays false (not located to the tolerance).
  double failed_at = std::numeric_limits<double>::quiet_NaN();
  std::string failure{};            // that run's reason (the solver's), empty if none failed
  bool more_in_cell() const { return bisected && count_above != count_at_cell_end; }
  double value() const { return 0.5 * (lo + hi); }
};

struct BounceSweepResult {
  BounceSweepSpec spec;
  std::vector<int> counts;          // per grid value; −1: the solver failed
  std::vector<std::string> failures;  // per grid value: empty, or the reason
  std::vector<CountThreshold> thresholds;
  std::vector<std::vector<int>> ensembles;  // per grid value, the members' counts (−1: failed); empty without
  long runs = 0;                    // throws solved (grid + bisection + ensembles)
  double cpu_s = 0;                 // summed over the runs
};

// The change bracketed by `grid` ([lo, hi], count_below at lo, count_above at hi) narrowed by
// halving until no wider than `tolerance` or no double lies strictly between its ends; count(x) is
// the bounce count at x, < 0 where the run fails. A failed run stops it (failed_at; bisected stays
// false), else bisected is set. count_above is then the count just above the change.
CountThreshold bisect_threshold(CountThreshold grid, double tolerance, const std::function<int(double)>& count);

// Runs every sweep's grid, then every bisection, sharing the workers.
std::vector<BounceSweepResult> run_bounce_sweeps(const std::vector<BounceSweepSpec>& specs,
                                                 const ParallelOptions& options);

}  // namespace stoneskip
