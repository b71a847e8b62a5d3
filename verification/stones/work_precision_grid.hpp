#pragma once
// Work against precision over a grid of throws, and the adaptive stepper's default tolerance chosen
// by it. A base throw (physical convention) is thrown at each spin × attack angle of the grid. Per
// throw a tight CVODE truth and a second truth at a tighter tolerance: a throw whose two truths
// disagree on the bounce count is chaotic at the truth's own accuracy and is set aside (counted,
// listed), as is one whose truth fails. The families — the adaptive bs32 over its tolerances, fixed
// schemes over flight steps, CVODE over rtol — run on every other throw; per family and setting
// the study aggregates (work_precision_grid_stats.hpp) the fraction of throws whose bounce count
// equals the truth's with its Wilson interval, the median and largest contact-time error over the
// throws whose contact lists match, and the mean right-hand sides and thread CPU per throw. Failed
// runs are counted with their reasons. The default rule (GridDefaultRule) picks a bs32 tolerance,
// stated beside kDefaultAdaptiveTolerance. The real-time budget (optional): bs32 at the cases'
// default tolerance with at most N right-hand sides per frame (solvers/realtime/stone_stepper.hpp,
// "Budget"), one family whose setting is N, with the steps the budget forced and the largest
// error-test ratio it accepted; the same rule then picks the smallest budget that keeps the counts.
#include <string>
#include <vector>

#include "verification/stones/throw_problem.hpp"
#include "verification/stones/work_precision_grid_stats.hpp"
#include "verification/study/progress.hpp"
#include "verification/study/record.hpp"

namespace stoneskip {

struct WorkPrecisionGridOptions {
  std::vector<double> spins_rev_s{0, 20, 40, 60};
  std::vector<double> attack_angles_deg{10, 20, 30};
  std::vector<double> adaptive_rtol{1e-5, 1e-6, 1e-7, 1e-8, 1e-9};  // bs32: rtol = atol_m
  std::vector<Scheme> fixed_schemes{Scheme::rk4, Scheme::semi_implicit_euler};
  std::vector<double> dt_s{4e-3, 1e-3, 2.5e-4};  // fixed schemes' flight steps
  double contact_ratio = 0.1;                     // contact step = ratio · dt_s
  ReferenceMethod method = ReferenceMethod::bdf;
  std::vector<double> cvode_rtol{1e-4, 1e-6, 1e-8};
  double atol_ratio = 1e-2;         // CVODE: atol = atol_ratio · rtol (truths included)
  double truth_rtol = 1e-11;
  double truth_check_factor = 0.1;  // the second truth at truth_rtol × this
  double agreement_target = 0.98;
  AgreementBound agreement_bound = AgreementBound::point_estimate;
  double contact_time_threshold_s = 1e-4;
  std::vector<long> budget_rhs_per_frame;        // the budget family's budgets (empty: not run)
  double budget_frame_dt_s = 1.0 / 90;           // its frame (the paper's > 90 frames/s)
  int workers = 2;
  ProgressFactory progress;  // empty: silently
  bool valid(std::string* why = nullptr) const;
};

struct GridThrow {
  double spin_rev_s = 0, attack_angle_deg = 0;
  std::string label;
  int truth_bounces = 0, check_bounces = 0;
  long truth_rhs_evaluations = 0;
  double truth_cpu_s = 0;
  bool set_aside = false;
  std::string set_aside_reason;  // "chaotic: …" or "truth failed: …"
};

struct WorkPrecisionGridResult {
  std::string base_label;
  std::vector<GridThrow> throws;   // spin-major
  int chaotic = 0;                 // set aside: the two truths' bounce counts differ
  int truth_failed = 0;            // set aside: a truth failed
  std::vector<GridRun> runs;
  std::vector<GridSummary> summaries;  // per family and setting
  std::string adaptive_family;
  GridDefaultChoice choice;
  std::string budget_family;       // empty when no budget was run
  GridBudgetChoice budget_choice;
};

// The family names the study gives (the summaries' `family`).
std::string adaptive_family_name(Scheme s);                    // "bs32 (adaptive)"
std::string fixed_family_name(Scheme s, double contact_ratio);  // "rk4 (contact dt/10)"
std::string cvode_family_name(ReferenceMethod m);              // "CVODE bdf"
std::string budget_family_name(Scheme s, double frame_dt_s);    // "bs32 (budget per 11.1 ms frame)"

WorkPrecisionGridResult run_work_precision_grid(const ThrowProblem& base, const WorkPrecisionGridOptions& o);

// The findings (the stones report's section "work_precision_grid"): the grid and its throws, the
// table "summary" (family as a position in the list "families"), the failures, and the choice.
Record work_precision_grid_findings(const WorkPrecisionGridResult& r, const WorkPrecisionGridOptions& o);

}  // namespace stoneskip
