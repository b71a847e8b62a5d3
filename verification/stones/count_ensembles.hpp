#pragma once
// The bounce counts of the two solvers compared on ensembles (model/README.md §2.4, "Both": a
// chaotic count is decided on ensembles, never run against run). In the paper convention a count
// may change under a 1e-9 relative change of the speed, so the sweeps' "same count at this grid
// value" compares single runs of a chaotic quantity. Here a sample of each sweep's grid values is
// thrown again as an ensemble of perturbed throws per solver (speed × 1 ± ε, ε log-spaced over
// [smallest, largest], verification/study/ensemble_difference.hpp), and the two ensembles' mean
// counts are compared by Welch's interval: a difference is established only where the interval
// excludes 0 (rule ensemble_bounce_agreement, verification/study/verdict_rules.hpp). The sampled
// throws' verdicts are one family, held to family_confidence together (Bonferroni: each of the m
// throws' intervals, and its exact test where neither ensemble has spread, at 1 − (1 −
// family_confidence)/m), so that "different" on any of them is not a chance of many looks.
#include <string>
#include <vector>

#include "verification/stones/bounce_sweep.hpp"
#include "verification/study/ensemble_difference.hpp"
#include "verification/study/record.hpp"

namespace stoneskip {

struct CountEnsembleOptions {
  int members = 16;                   // perturbed throws per solver and sampled grid value (even, ≥ 2)
  double perturbation_smallest = 1e-9;
  double perturbation_largest = 1e-4;
  int throws_per_axis = 3;            // grid values sampled per sweep axis, evenly spaced, both ends (0: none)
  Convention convention = Convention::paper;
  double family_confidence = 0.95;    // the sampled throws' verdicts held together, (0, 1)
  bool valid(std::string* why = nullptr) const;
};

// One sampled throw: the unperturbed runs (the sweep's single-run comparison) and the ensembles.
struct CountEnsembleThrow {
  SweepParameter parameter = SweepParameter::spin_rev_s;
  double value = 0;
  int realtime_single = -1, reference_single = -1;  // −1: the solver failed
  std::vector<double> factors;                      // the speed factors of the members
  std::vector<double> realtime, reference;          // counts per member (−1: failed)
  std::vector<char> realtime_away, reference_away;  // per member: failed by running away (ran_away)
  int realtime_failed = 0, reference_failed = 0;
  int realtime_ran_away = 0, reference_ran_away = 0;  // of the failed members, those that ran away
  MeanDifference difference;                        // realtime − reference, over the members that ran,
                                                    // at the family's per-throw level
};

// Each throw's level in a family of m (Bonferroni): 1 − (1 − family_confidence)/m (m ≥ 1).
double comparison_confidence(const CountEnsembleOptions& options, std::size_t m);

// A throw's difference (realtime − reference) over its members that ran, at `confidence`.
MeanDifference member_difference(const CountEnsembleThrow& t, double confidence);

// The grid values sampled from an ascending grid: `count` indices evenly spaced, both ends included.
std::vector<double> sampled_values(const std::vector<double>& grid, int count);

// Every sampled throw of every axis, both solvers, on the workers. `realtime` and `reference` are
// the sweeps' solver settings; `base` is the sweeps' base throw (put in options.convention).
std::vector<CountEnsembleThrow> run_count_ensembles(const ThrowProblem& base, const SolverChoice& realtime,
                                                   const SolverChoice& reference,
                                                   const std::vector<std::pair<SweepParameter, std::vector<double>>>& axes,
                                                   const CountEnsembleOptions& options, const ParallelOptions& parallel);

// The section's record: a table of the sampled throws, one verdict per throw, and the tally (with
// how many failed members of all ensembles ran away, and how many failed otherwise). Each throw's
// difference is computed here from its members' counts, at the family's per-throw level over
// these throws (`throws.size()` of them), and both levels are stored.
Record count_ensembles_findings(const std::vector<CountEnsembleThrow>& throws, const CountEnsembleOptions& options);

}  // namespace stoneskip
