#pragma once
// The arithmetic of the work-precision study over a grid of throws (work_precision_grid.hpp): the
// Wilson score interval of a proportion, the aggregation of the runs of each solver family and
// setting over the throws, and the rule that picks the adaptive stepper's default tolerance from
// those aggregates. Pure functions of their inputs, so each is tested on hand-built numbers.
#include <string>
#include <vector>

namespace stoneskip {

// z of a two-sided 95 % interval of the normal distribution (Φ⁻¹(0.975)).
constexpr double kWilsonZ95 = 1.959963984540054;

// A proportion k/n with its Wilson score interval (Wilson 1927; Newcombe 1998, method 3, without
// continuity correction): (k + z²/2 ± z √(k(n−k)/n + z²/4)) / (n + z²). n = 0: estimate NaN, [0, 1].
struct ProportionInterval {
  double estimate = 0;
  double low = 0;
  double high = 1;
};
ProportionInterval wilson_interval(int successes, int n, double z = kWilsonZ95);

// The fewest throws that, all agreeing, put the Wilson lower bound at or above `target` (0 < target
// < 1): n/(n + z²) ≥ target, i.e. n ≥ target z² / (1 − target).
int throws_to_show(double target, double z = kWilsonZ95);

// One run: a solver family at one setting on one throw of the grid (one not set aside).
struct GridRun {
  std::string family;          // "bs32 (adaptive)", "rk4 (contact dt/10)", "CVODE bdf"
  double setting = 0;          // tolerance (bs32, CVODE) or flight step dt_s (fixed schemes)
  std::string throw_label;
  bool ok = false;             // false: the solve failed (`problem` says why)
  std::string problem;
  int bounces = 0, truth_bounces = 0;
  bool same_count = false;     // its bounce count equals the truth's
  bool same_contacts = false;  // its contact list matches the truth's: contact_time_error_s is set
  double contact_time_error_s = 0;  // largest start or end error over the contacts
  long rhs_evaluations = 0;
  double cpu_s = 0;            // thread CPU
  // The adaptive stepper's own account (zero for the other families): accepted steps, the steps a
  // frame budget forced over the tolerance, and the largest error-test ratio it accepted.
  long steps = 0, forced_steps = 0;
  double max_error_ratio = 0;
};

// A family at one setting, over the throws.
struct GridSummary {
  std::string family;
  double setting = 0;
  int n = 0;                   // throws run
  int agreeing = 0;            // with the truth's bounce count (a failed run does not agree)
  ProportionInterval agreement;
  int timed = 0;               // throws whose contact list matches the truth's
  double median_contact_time_error_s = 0;  // over the timed throws (NaN when none)
  double max_contact_time_error_s = 0;
  double mean_rhs_evaluations = 0;  // per throw, failures included
  double mean_cpu_s = 0;
  double forced_step_fraction = 0;  // Σ forced steps / Σ steps over the throws (0 when no steps)
  double max_error_ratio = 0;       // the largest over the throws
  int failed = 0;
  std::vector<std::string> failures;  // "throw: reason", every failure
};

// One summary per family and setting, in the order they first appear in `runs`.
std::vector<GridSummary> summarise_grid_runs(const std::vector<GridRun>& runs);

// Which estimate of the count agreement a tolerance must bring to the target.
enum class AgreementBound { point_estimate, wilson_lower };
const char* to_string(AgreementBound b);  // "point_estimate", "wilson_lower"
bool parse_agreement_bound(const std::string& s, AgreementBound& out);

struct GridDefaultRule {
  std::string family;                  // the adaptive family's name in the summaries
  double agreement_target = 0.98;
  AgreementBound bound = AgreementBound::point_estimate;
  double contact_time_threshold_s = 1e-4;  // the median contact-time error must be below this
};

// How the grid's choice stands beside the cases' default tolerance.
enum class DefaultAgreement { same, default_tighter, default_looser, no_choice };
const char* to_string(DefaultAgreement a);  // "same", "default_tighter", "default_looser", "no_choice"
const char* phrase(DefaultAgreement a);     // in words: "the grid agrees with the default", …

// The loosest tolerance of rule.family that meets the rule — agreement (by rule.bound) at or above
// the target and median contact-time error below the threshold — at which every tighter
// tolerance meets it too (so a lucky loose tolerance is not picked over a failing tighter one).
struct GridDefaultChoice {
  bool found = false;
  double tolerance = 0;
  GridSummary at;                      // the summary at the choice
  std::vector<double> tolerances;      // tightest first
  std::vector<bool> meets;             // per tolerance
  double default_tolerance = 0;
  DefaultAgreement agreement = DefaultAgreement::no_choice;
  int throws_to_show_target = 0;       // throws_to_show(target): all agreeing, the lower bound reaches it
  std::string reason;                  // computed, in words
};
GridDefaultChoice choose_grid_default(const std::vector<GridSummary>& summaries, const GridDefaultRule& rule,
                                      double default_tolerance);

// The real-time budget (bs32 with at most N right-hand sides per frame: the summaries of
// rule.family, setting N): the smallest budget at which, and at every larger one, the rule above is
// met (agreement by rule.bound at or above the target, median contact-time error below the
// threshold) — the same rule as the default tolerance's, with larger budgets in place of tighter
// tolerances.
struct GridBudgetChoice {
  bool found = false;
  double rhs_per_frame = 0;
  GridSummary at;                     // the summary at the choice
  std::vector<double> budgets;        // largest first
  std::vector<bool> meets;            // per budget
  std::string reason;                 // computed, in words
};
GridBudgetChoice choose_grid_budget(const std::vector<GridSummary>& summaries, const GridDefaultRule& rule);

}  // namespace stoneskip
