// Findings of the convergence study (section "convergence" of the stones report): every series
// of errors against step with its order fit and verdict (interval-based, verification/study/
// order_record.hpp), the GCI of scalar series, the reference's own error against its tolerance.
// For each water law of the study the series are found alike (convergence_series_findings).
#include <cmath>
#include <sstream>

#include "verification/stones/stone_studies.hpp"
#include "verification/study/order_record.hpp"
#include "verification/study/verdict_rules.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {

namespace {

void store_series(Record& parent, const ConvergenceSeries& s, OrderJudgement j) {
  Record& r = parent.child(s.quantity + "." + s.scheme);
  r.set("quantity", s.quantity);
  r.set("description", s.description);
  r.set("unit", s.unit);
  r.set("scheme", s.scheme);
  r.set("formal_order", s.formal_order);
  r.set("against_tolerance", s.against_tolerance);
  r.set("reference_error", s.reference_error);
  Table t{{"h_s", "value", "error", "in_fit", "below_floor"}, {}, {"s", s.unit, s.unit, "1", "1"}};
  for (std::size_t i = 0; i < s.h_s.size(); ++i)
    t.add_row({s.h_s[i], s.value[i], s.error[i], s.in_fit[i] ? 1.0 : 0.0, s.below_floor[i] ? 1.0 : 0.0});
  r.set_table("points", t);
  r.set_strings("notes", s.notes);
  j.expected_order = s.formal_order;
  // The rule's reason, plus which points the fit lacks and why (finish_series).
  store_order_fit(r, "fit", s.fit, j).child("verdict").set("reason", judge_order(s.fit, j).reason + s.left_out);
  if (s.has_gci) {
    Record& g = r.child("gci");
    g.set("kind", std::string(to_string(s.gci.kind)));
    g.set("order", s.gci.order);
    g.set("gci_fine", s.gci.gci_fine);
    g.set("gci_fine_absolute", s.gci.gci_fine_absolute);
    g.set("extrapolated", s.gci.extrapolated);
    // Where the apparent order was not reasonable: the formal order and Fs = 3 used (gci.hpp).
    g.set("reverted", s.gci.reverted);
    g.set("order_used", s.gci.order_used);
    g.set("safety_factor", s.gci.safety_factor);
  }
}

}  // namespace

Record convergence_series_findings(const RealtimeConvergenceResult& c, const OrderJudgement& judgement) {
  Record r;
  r.set("case", c.case_label);
  r.set("reference_rtol", c.reference_rtol);
  r.set("check_rtol", c.check_rtol);
  r.set("reference_contacts", c.reference.contacts.size());
  r.set("reference_bounces", c.reference.bounces);
  r.set("reference_outcome", std::string(to_string(c.reference.outcome)));
  r.set("reference_end_time_s", c.reference.end_time_s);
  r.set("flight_interval_end_s", c.flight_interval_end_s);
  r.set("contact_interval_start_s", c.contact_interval_start_s);
  r.set("contact_interval_end_s", c.contact_interval_end_s);
  r.set("free_flight_time_s", c.free_flight_time_s);
  r.set("order_tolerance", judgement.tolerance);
  r.set("minimum_order", judgement.minimum_order);
  r.set_strings("problems", c.problems);
  std::vector<std::string> keys;
  Record& series = r.child("series");
  for (const auto& s : c.series) {
    store_series(series, s, judgement);
    keys.push_back(s.quantity + "." + s.scheme);
  }
  r.set_strings("series_keys", keys);

  // Why an order may not show through a contact: the reference's located events in the first
  // contact and how crowded the scheme-alone steps are with them.
  Record& ev = r.child("events");
  ev.set("contact_start_s", c.events.start_s);
  ev.set("contact_end_s", c.events.end_s);
  ev.set("count", c.events.times_s.size());
  ev.set("min_spacing_s", c.events.min_spacing_s);
  ev.set("median_spacing_s", c.events.median_spacing_s);
  Table crowd{{"h_s", "steps_in_contact", "steps_with_two_or_more_events", "fraction"}, {}};
  for (const auto& k : c.events.scheme_alone)
    crowd.add_row({k.h_s, double(k.steps_in_window), double(k.steps_with_two_or_more), k.fraction()});
  ev.set_table("crowding", crowd);
  return r;
}

Record convergence_findings(const RealtimeConvergenceResult& c, const ReferenceToleranceResult& tol,
                            const OrderJudgement& judgement, double required_drop) {
  Record r = convergence_series_findings(c, judgement);

  // The reference's own error against its tolerance (tolerance proportionality: slope 1).
  Record& t = r.child("reference_tolerance");
  t.set("case", tol.case_label);
  t.set("method", tol.method);
  Table pts{{"rtol", "ok", "bounces", "bounce_position_error_m", "contact_time_error_s", "rhs_evaluations", "cpu_s"}, {}};
  std::vector<std::string> problems;
  for (const auto& p : tol.points) {
    pts.add_row({p.rtol, p.ok ? 1.0 : 0.0, double(p.bounces), p.bounce_position_error_m, p.contact_time_error_s,
                 double(p.rhs_evaluations), p.cpu_s});
    problems.push_back(p.problem);
  }
  t.set_table("points", pts);
  t.set_strings("problems", problems);
  OrderJudgement proportional{1.0, judgement.tolerance, judgement.minimum_order};
  store_order_fit(t, "bounce_position_fit", tol.bounce_position_fit, proportional);
  store_order_fit(t, "contact_time_fit", tol.contact_time_fit, proportional);
  t.set("error_drop", tol.error_drop);
  t.set("drop_from_rtol", tol.drop_from_rtol);
  t.set("drop_to_rtol", tol.drop_to_rtol);
  t.set("required_drop", required_drop);
  const double drop = tol.error_drop;
  const std::string span = "rtol " + num(tol.drop_from_rtol) + " to " + num(tol.drop_to_rtol);
  Record in;
  in.set("ratio", drop);
  in.set("required", required_drop);
  decide_verdict(
      t, "drop", "minimum_ratio", in,
      std::isnan(drop) ? "rtol " + num(tol.drop_from_rtol) + " or " + num(tol.drop_to_rtol) + " was not run or failed"
                       : "the bounce-position error falls " + num(drop) + "× from " + span + " (at least " +
                             num(required_drop) + "× required)");
  return r;
}

}  // namespace stoneskip
