// The restart-strategy dimension of the work-precision study (verification/stones/work_precision.hpp):
// the study's summaries recomputed independently from its own points, the tolerance rule, the
// verdict as the cheapest strategy that keeps the contact times, and the law dimension.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "model/stone/mass_properties.hpp"
#include "model/stone/throw.hpp"
#include "verification/stones/work_precision.hpp"

namespace stoneskip {
namespace {

// The 8 m/s throw of the 3 cm stone without spin (sinks in its first contact, ≈ 10 ms long).
ThrowProblem short_throw() {
  ThrowProblem p;
  const Mesh mesh = make_prism(0.03, 0.008, 11);
  p.label = "8 m/s";
  p.stone = make_stone(mesh, mass_properties_from_density(mesh, 2500.0), 0.0, "prism");
  p.parameters.speed_m_s = 8.0;
  p.parameters.path_angle_deg = 10.0;
  p.parameters.attack_angle_deg = 10.0;
  p.parameters.height_m = 0.1;
  p.initial = initial_state(p.stone, p.parameters);
  p.reference.t_max_s = 0.2;
  p.realtime.t_max_s = 0.2;
  return p;
}

BOOST_AUTO_TEST_SUITE(work_precision_restarts)

BOOST_AUTO_TEST_CASE(the_restart_summaries_and_verdict_follow_from_the_points) {
  // Oracle: an independent pass over the study's own points (sums of right-hand sides, worst
  // contact-time error per method, rtol and strategy), the documented tolerance
  // max(restart_time_tolerance_s, factor × every_event's worst), and the verdict's rule (fewest
  // right-hand sides among the strategies that keep the contact times everywhere). The truth
  // restarts at every event; the throws run under two laws, each labelled with its law.
  WorkPrecisionOptions o;
  o.realtime.clear();
  o.dt_s.clear();
  o.methods = {ReferenceMethod::bdf};
  o.restarts = {RestartStrategy::every_event, RestartStrategy::at_jumps};
  o.laws = {WaterLaw::newtonian, WaterLaw::planing};
  o.rtol = {1e-6, 1e-8};
  o.truth_rtol = 1e-11;
  o.repeats = 1;
  o.workers = 1;
  const WorkPrecisionResult r = run_work_precision({short_throw()}, o);
  BOOST_TEST_REQUIRE(r.throws.size() == 2u);
  BOOST_TEST((r.throws[1].law == WaterLaw::planing));
  BOOST_TEST(r.throws[1].label.find("planing") != std::string::npos);
  BOOST_TEST(r.throws[0].truth.solver.find("every_event") != std::string::npos, r.throws[0].truth.solver);
  BOOST_TEST_REQUIRE(r.restarts.size() == 4u);  // 1 method × 2 rtol × 2 strategies
  long rhs_of[2] = {0, 0};
  for (const RestartSummary& s : r.restarts) {
    long rhs = 0;
    int n = 0;
    double worst = 0;
    for (const auto& t : r.throws)
      for (const auto& p : t.points)
        if (!p.realtime && p.restart == s.restart && p.setting == s.rtol) {
          rhs += p.rhs_evaluations;
          ++n;
          if (p.ok) worst = std::max(worst, p.contact_time_error_s);
        }
    BOOST_TEST(s.throws == 2);
    BOOST_TEST(n == 2);
    BOOST_TEST(s.rhs_evaluations == rhs);
    BOOST_TEST(s.worst_contact_time_error_s == worst);
    double every_event_worst = 0;
    for (const RestartSummary& e : r.restarts)
      if (e.restart == RestartStrategy::every_event && e.rtol == s.rtol) every_event_worst = e.worst_contact_time_error_s;
    BOOST_TEST(s.tolerance_s == std::max(o.restart_time_tolerance_s, o.restart_error_factor * every_event_worst));
    BOOST_TEST(s.keeps_contact_times == (s.failed == 0 && s.worst_contact_time_error_s <= s.tolerance_s));
    rhs_of[s.restart == RestartStrategy::at_jumps] += s.rhs_evaluations;
  }
  bool keeps[2] = {true, true};
  for (const RestartSummary& s : r.restarts) keeps[s.restart == RestartStrategy::at_jumps] &= s.keeps_contact_times;
  BOOST_TEST_REQUIRE(r.restart_verdict.found == (keeps[0] || keeps[1]));
  const int expected = keeps[1] && (!keeps[0] || rhs_of[1] < rhs_of[0]) ? 1 : 0;
  BOOST_TEST((r.restart_verdict.restart == (expected ? RestartStrategy::at_jumps : RestartStrategy::every_event)));
  BOOST_TEST(r.restart_verdict.every_event_rhs_evaluations == rhs_of[0]);
  BOOST_TEST_MESSAGE("restart verdict: " << to_string(r.restart_verdict.restart) << "; " << r.restart_verdict.reason);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
