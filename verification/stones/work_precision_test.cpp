// The work-precision study's headline error, against an independent computation from the two
// contact lists: the bounce positions for a throw that bounces, the sinking point for one that
// never does — never the larger of the two mixed under the name "bounce position".
#include "verification/stones/work_precision.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>

#include "verification/stones/convergence_throw.hpp"

namespace stoneskip {
namespace {

BOOST_AUTO_TEST_SUITE(work_precision)

BOOST_AUTO_TEST_CASE(the_headline_error_is_the_bounce_position_or_else_the_sinking_point) {
  // Oracle: the distance between the run's and the truth's exit positions of the matching
  // contacts, computed here from the contact lists the study returns (its truth) and from a run of
  // the same setting. Throw 1 (the convergence throw) bounces once, then sinks: its headline is
  // the bounce's error, and the sinking point's error (about 50× larger at this step) is reported apart.
  // Throw 2 (the same without spin, α = 10°) sinks in its first contact: its headline is the
  // sinking point. rk4 at a 4 ms flight step, no CVODE families, one repeat: about 1 s.
  constexpr double kSame = 0;  // the same numbers, computed twice the same way
  ThrowProblem bounce = convergence_throw();
  ThrowProblem sink = bounce;
  sink.parameters.spin_rev_s = 0;
  sink.parameters.attack_angle_deg = 10;
  sink = with_parameters(sink, sink.parameters);
  WorkPrecisionOptions o;
  o.realtime = {{Scheme::rk4, 0.1}};
  o.dt_s = {4e-3};
  o.methods = {};
  o.repeats = 1;
  const WorkPrecisionResult res = run_work_precision({bounce, sink}, o);
  BOOST_REQUIRE(res.throws.size() == 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const WorkPrecisionThrow& t = res.throws[k];
    BOOST_REQUIRE(t.points.size() == 1u);
    const WorkPoint& p = t.points[0];
    BOOST_REQUIRE_MESSAGE(p.ok, p.problem);
    RealtimeOptions ro = (k ? sink : bounce).realtime;
    ro.scheme = Scheme::rk4;
    ro.dt_s = 4e-3;
    ro.contact_dt_s = 4e-4;
    ro.record_trajectory = false;
    const ThrowResult r = solve(k ? sink : bounce, realtime_choice(ro));
    BOOST_REQUIRE(r.contacts.size() == t.truth.contacts.size());
    // The run here keeps the throw's kinks (none given, so a fixed scheme's: none) and reproduces
    // the study's errors below exactly: the stored name is what ran.
    BOOST_TEST(!ro.kinks.has_value());
    BOOST_TEST(t.fixed_kinks == "none");
    const double sink_error = (r.contacts.back().exit_position_m - t.truth.contacts.back().exit_position_m).norm();
    BOOST_TEST(std::abs(p.sink_position_error_m - sink_error) <= kSame);
    if (k == 0) {
      BOOST_TEST((t.headline == HeadlineError::bounce_position));
      const double bounce_error = (r.contacts[0].exit_position_m - t.truth.contacts[0].exit_position_m).norm();
      BOOST_TEST(std::abs(p.headline_error_m - bounce_error) <= kSame);
      BOOST_TEST(p.bounce_position_error_m == p.headline_error_m);
      BOOST_TEST_MESSAGE("bounce throw: bounce error " << bounce_error << " m, sinking error " << sink_error << " m");
    } else {
      BOOST_TEST((t.headline == HeadlineError::sink_position));
      BOOST_TEST(std::abs(p.headline_error_m - sink_error) <= kSame);
      BOOST_TEST(std::isnan(p.bounce_position_error_m));
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
