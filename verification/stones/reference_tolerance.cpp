#include "verification/stones/reference_tolerance.hpp"

#include <cmath>
#include <functional>
#include <limits>

#include "verification/stones/contact_comparison.hpp"
#include "verification/stones/parallel_runs.hpp"

namespace stoneskip {

ReferenceToleranceResult run_reference_tolerance(const ThrowProblem& p, const ReferenceToleranceOptions& o) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  ReferenceToleranceResult res;
  res.case_label = p.label;
  res.method = to_string(o.method);
  auto options_for = [&](double rtol) {
    ReferenceOptions r = p.reference;
    r.method = o.method;
    r.rtol = rtol;
    r.atol = o.atol_ratio * rtol;
    r.record_trajectory = false;
    return r;
  };
  std::vector<ThrowResult> runs(o.rtol.size());
  std::vector<std::function<void()>> jobs;
  jobs.push_back([&] { res.truth = solve(p, reference_choice(options_for(o.truth_rtol))); });
  for (std::size_t i = 0; i < o.rtol.size(); ++i)
    jobs.push_back([&, i] { runs[i] = solve(p, reference_choice(options_for(o.rtol[i]))); });
  run_jobs(jobs, ParallelOptions{o.workers, "stones: reference tolerance proportionality", o.progress});

  std::vector<double> h, e_pos, h_t, e_t;
  double at_from = kNaN, at_to = kNaN;
  for (std::size_t i = 0; i < o.rtol.size(); ++i) {
    ReferenceTolerancePoint pt;
    const ThrowResult& r = runs[i];
    pt.rtol = o.rtol[i];
    pt.bounces = r.bounces;
    pt.rhs_evaluations = r.stats.rhs_evaluations;
    pt.steps = r.stats.steps;
    pt.cpu_s = r.stats.cpu_s;
    const ContactComparison c = compare_contacts(r, res.truth);
    if (r.outcome == Outcome::failed) {
      pt.problem = r.outcome_detail;
    } else if (res.truth.outcome == Outcome::failed) {
      pt.problem = "the tight reference failed: " + res.truth.outcome_detail;
    } else if (!c.same_contacts()) {
      pt.problem = "contact list differs from the tight run: " + c.brief();
    } else {
      pt.ok = true;
      pt.bounce_position_error_m = c.max_exit_position_error_m;  // where each contact ends
      pt.contact_time_error_s = std::max(c.max_start_error_s, c.max_end_error_s);
      pt.final_position_error_m =
          r.outcome == res.truth.outcome ? (r.final_state.position_m - res.truth.final_state.position_m).norm() : kNaN;
      h.push_back(pt.rtol);
      e_pos.push_back(pt.bounce_position_error_m);
      h_t.push_back(pt.rtol);
      e_t.push_back(pt.contact_time_error_s);
      if (pt.rtol == o.drop_from_rtol) at_from = pt.bounce_position_error_m;
      if (pt.rtol == o.drop_to_rtol) at_to = pt.bounce_position_error_m;
    }
    if (!pt.ok) pt.bounce_position_error_m = pt.contact_time_error_s = pt.final_position_error_m = kNaN;
    res.points.push_back(pt);
  }
  res.bounce_position_fit = fit_order(h, e_pos);
  res.contact_time_fit = fit_order(h_t, e_t);
  res.drop_from_rtol = o.drop_from_rtol;
  res.drop_to_rtol = o.drop_to_rtol;
  res.error_drop = at_from / at_to;
  return res;
}

}  // namespace stoneskip
