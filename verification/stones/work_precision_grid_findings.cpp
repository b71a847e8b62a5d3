// Findings of the work-precision study over a grid of throws (section "work_precision_grid" of the
// stones report): the grid, each throw's truths and whether it was set aside, one row per family
// and setting (the aggregates of work_precision_grid_stats.hpp), every failure with its reason,
// and the default tolerance the grid supports beside the cases' default (decided here, not in the report).
#include <algorithm>

#include "verification/stones/work_precision_grid.hpp"
#include "verification/study/order_record.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {

Record work_precision_grid_findings(const WorkPrecisionGridResult& r, const WorkPrecisionGridOptions& o) {
  Record rec;
  rec.set("base_label", r.base_label);
  rec.set_table("spins", value_list(o.spins_rev_s, "spin_rev_s"));
  rec.set_table("attack_angles", value_list(o.attack_angles_deg, "attack_angle_deg"));
  rec.set_table("adaptive_rtol", value_list(o.adaptive_rtol, "rtol"));
  rec.set_table("dt_s", value_list(o.dt_s, "dt_s"));
  rec.set_table("cvode_rtol", value_list(o.cvode_rtol, "rtol"));
  rec.set("contact_ratio", o.contact_ratio);
  rec.set("method", std::string(to_string(o.method)));
  rec.set("atol_ratio", o.atol_ratio);
  rec.set("truth_rtol", o.truth_rtol);
  rec.set("truth_check_rtol", o.truth_rtol * o.truth_check_factor);
  rec.set("clock", std::string("CPU time of the solving thread, one run per throw"));

  // The throws and their truths.
  Table throws{{"spin_rev_s", "attack_angle_deg", "truth_bounces", "check_bounces", "set_aside", "truth_rhs_evaluations",
                "truth_cpu_s"},
               {}};
  std::vector<std::string> set_aside;
  for (const GridThrow& t : r.throws) {
    throws.add_row({t.spin_rev_s, t.attack_angle_deg, double(t.truth_bounces), double(t.check_bounces), t.set_aside ? 1.0 : 0.0,
                    double(t.truth_rhs_evaluations), t.truth_cpu_s});
    if (t.set_aside) set_aside.push_back(t.label + ": " + t.set_aside_reason);
  }
  rec.set_table("throws", throws);
  rec.set_strings("set_aside", set_aside);
  rec.set("throw_count", r.throws.size());
  rec.set("kept", int(r.throws.size()) - r.chaotic - r.truth_failed);
  rec.set("chaotic", r.chaotic);
  rec.set("truth_failed", r.truth_failed);

  // One row per family and setting; the family as its position in "families".
  std::vector<std::string> families, failures;
  for (const GridSummary& s : r.summaries)
    if (std::find(families.begin(), families.end(), s.family) == families.end()) families.push_back(s.family);
  Table sum{{"family", "setting", "agreeing", "n", "agreement", "wilson_lo", "wilson_hi", "timed",
             "median_contact_time_error_s", "max_contact_time_error_s", "mean_rhs_evaluations", "mean_cpu_s", "failed",
             "forced_step_fraction", "max_error_ratio"},
            {}};
  for (const GridSummary& s : r.summaries) {
    const double f = double(std::find(families.begin(), families.end(), s.family) - families.begin());
    sum.add_row({f, s.setting, double(s.agreeing), double(s.n), s.agreement.estimate, s.agreement.low, s.agreement.high,
                 double(s.timed), s.median_contact_time_error_s, s.max_contact_time_error_s, s.mean_rhs_evaluations,
                 s.mean_cpu_s, double(s.failed), s.forced_step_fraction, s.max_error_ratio});
    for (const auto& why : s.failures) failures.push_back(s.family + " at " + num(s.setting, 7) + ", " + why);
  }
  rec.set_strings("families", families);
  rec.set_table("summary", sum);
  rec.set_strings("failures", failures);
  // The adaptive family's runs that finished with another bounce count than the truth's.
  std::vector<std::string> missed;
  for (const GridRun& g : r.runs)
    if (g.family == r.adaptive_family && g.ok && !g.same_count)
      missed.push_back("at " + num(g.setting, 2) + ", " + g.throw_label + ": " + std::to_string(g.bounces) +
                       " bounces, the truth " + std::to_string(g.truth_bounces));
  rec.set_strings("adaptive_disagreements", missed);

  // The default the grid supports.
  const GridDefaultChoice& c = r.choice;
  Record& ch = rec.child("default_choice");
  ch.set("family", r.adaptive_family);
  ch.set("agreement_target", o.agreement_target);
  ch.set("agreement_bound", std::string(to_string(o.agreement_bound)));
  ch.set("contact_time_threshold_s", o.contact_time_threshold_s);
  ch.set("found", c.found);
  ch.set("tolerance", c.tolerance);
  ch.set("default_tolerance", c.default_tolerance);
  ch.set("beside_default", std::string(to_string(c.agreement)));
  ch.set("beside_default_phrase", std::string(phrase(c.agreement)));
  ch.set("agreeing", c.at.agreeing);
  ch.set("n", c.at.n);
  ch.set("wilson_lo", c.at.agreement.low);
  ch.set("wilson_hi", c.at.agreement.high);
  ch.set("median_contact_time_error_s", c.at.median_contact_time_error_s);
  ch.set("mean_rhs_evaluations", c.at.mean_rhs_evaluations);
  ch.set("mean_cpu_s", c.at.mean_cpu_s);
  ch.set("throws_to_show_target", c.throws_to_show_target);
  ch.set("reason", c.reason);
  Table per{{"tolerance", "meets"}, {}};
  for (std::size_t i = 0; i < c.tolerances.size(); ++i) per.add_row({c.tolerances[i], c.meets[i] ? 1.0 : 0.0});
  ch.set_table("per_tolerance", per);

  // The real-time budget, when run: its family, frame and tolerance, the smallest budget the rule
  // picks, and per budget the CPU a frame costs at most (N × the mean CPU per right-hand side of
  // that budget's runs) beside the frame itself.
  rec.set("budget_run", !r.budget_family.empty());
  if (!r.budget_family.empty()) {
    const GridBudgetChoice& b = r.budget_choice;
    Record& bc = rec.child("budget_choice");
    bc.set("family", r.budget_family);
    bc.set("frame_dt_s", o.budget_frame_dt_s);
    bc.set("rtol", kDefaultAdaptiveTolerance);
    bc.set("found", b.found);
    bc.set("rhs_per_frame", b.rhs_per_frame);
    bc.set("agreeing", b.at.agreeing);
    bc.set("n", b.at.n);
    bc.set("wilson_lo", b.at.agreement.low);
    bc.set("wilson_hi", b.at.agreement.high);
    bc.set("median_contact_time_error_s", b.at.median_contact_time_error_s);
    bc.set("reason", b.reason);
    Table frames{{"rhs_per_frame", "meets", "cpu_per_rhs_s", "cpu_per_frame_bound_s", "frame_fraction", "forced_step_fraction",
                  "max_error_ratio"},
                 {}};
    for (std::size_t i = 0; i < b.budgets.size(); ++i)
      for (const GridSummary& s : r.summaries)
        if (s.family == r.budget_family && s.setting == b.budgets[i]) {
          const double per_rhs = s.mean_rhs_evaluations > 0 ? s.mean_cpu_s / s.mean_rhs_evaluations : 0;
          frames.add_row({s.setting, b.meets[i] ? 1.0 : 0.0, per_rhs, s.setting * per_rhs,
                          s.setting * per_rhs / o.budget_frame_dt_s, s.forced_step_fraction, s.max_error_ratio});
        }
    bc.set_table("per_budget", frames);
  }
  return rec;
}

}  // namespace stoneskip
