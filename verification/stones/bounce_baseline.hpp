#pragma once
// Golden baselines of bounce-count curves (cases/baselines/*.toml) and the comparison that
// `stoneskip regress` prints. A baseline file holds the settings that made it ([baseline]: the
// case, swept parameter and grid, convention, water law, solver, tolerances) and the result
// ([result]: the count at each grid value and every bisected threshold); reading and writing the
// file is the command line's (the CLI's case parsing), comparing is here.
//
// What counts as a regression:
//  * a count at a grid value differs, unless a stored threshold lies within compare_tolerance of
//    that value (there the count may legitimately fall either side);
//  * a stored threshold has no recomputed threshold with the same counts on both sides within
//    compare_tolerance of it, or a recomputed threshold has no stored one.
// Bisection brackets a threshold to threshold_tolerance, so two runs of correct code agree to
// within that; compare_tolerance (default 2 × threshold_tolerance) leaves room for round-off
// moving a threshold across a bisection point.
//
// A count is chaotic where a 1e-9 nudge of the speed changes it (the paper convention's curve:
// speed × (1 + 1e-9) gave 12 "regressions"), and a verdict on a chaotic count is decided on
// ensembles, never run against run (model/README.md §2.4). With ensemble_members > 0 every grid
// value also keeps an ensemble of nudged throws (speed × (1 ± ε), ε log-spaced over [1e-9, 1e-6]):
//  * a value is sensitive where its *stored* ensemble has spread (noise that appears only in the new
//    run loosens nothing);
//  * on a robust value the single count, the ensemble (Welch) and the number of failed members are
//    all held;
//  * on a sensitive value the count is a regression only where the two ensembles' mean counts
//    differ by Welch's interval (verification/study/ensemble_difference.hpp; the exact permutation
//    test where neither has spread) held to 95 % over the baseline's sensitive values together
//    (Bonferroni, per baseline file), with at least half the members run on each side, or where a
//    changed single count lies outside every member's range on both sides (no nudge's count); a
//    changed single count within it is tolerated and said, and so are failures moving among the
//    members unless Fisher's exact test of the two failure rates gives p at most the same level;
//  * a threshold gone, moved or new in a cell with a sensitive end is tolerated and said, and in
//    such a cell or one holding more changes (its count past the change is not the grid's at the
//    cell's end) the count just past a change is not held run against run.
#include <optional>
#include <string>
#include <vector>

#include "verification/stones/bounce_sweep.hpp"

namespace stoneskip {

struct BounceBaseline {
  std::string file;              // as read
  std::string name;
  std::string description;
  std::string case_file;         // as written in the baseline (relative to the repository root)
  SweepParameter parameter = SweepParameter::spin_rev_s;
  std::vector<double> values;
  Convention convention = Convention::physical;
  // Optional in the file (default: the case's own): the case is loaded with environment.water_law
  // and environment.pressure_distribution set to them, so the law's published C_w applies unless the
  // case gives water_coefficient.
  std::optional<WaterLaw> water_law;
  std::optional<PressureDistribution> pressure_distribution;
  SolverKind solver = SolverKind::realtime;
  // Solver settings given in the file (else the case's own [solver] / [reference]).
  std::string scheme;            // realtime
  double dt_s = 0, contact_dt_s = 0;
  std::string method;            // reference
  double rtol = 0, atol = 0;
  std::string restart;           // reference: a RestartStrategy name, or empty for the case's
  double t_max_s = 0;            // 0: the case's
  double threshold_tolerance = 0.1;
  double compare_tolerance = 0.2;
  // The stored result.
  bool has_result = false;
  std::string generated;         // code version and date of the run that made it
  std::vector<int> counts;
  std::vector<CountThreshold> thresholds;
  // The ensembles ([baseline] ensemble_members; [result] ensemble_counts, values × members).
  int ensemble_members = 0;      // 0: single runs only
  std::vector<std::vector<int>> ensembles;
};

struct BaselineComparison {
  std::string name;
  bool passed = true;
  std::vector<std::string> regressions;  // one line each
  std::vector<std::string> tolerated;    // differences within the rules (near a threshold)
  int grid_points = 0;
  int thresholds = 0;
  int sensitive_points = 0;  // grid values whose stored ensemble has spread
  // Per sensitive value, how coarse its check is: the shift of the mean count that the ensembles'
  // interval would just establish, t · s √(2/n) (s the stored ensemble's sd, n its members that
  // ran, t at the family's per-value level, ν = 2(n − 1)): smaller shifts pass unseen.
  std::vector<std::string> resolution;
};

BaselineComparison compare_with_baseline(const BounceBaseline& stored, const BounceSweepResult& now);

}  // namespace stoneskip
