// The adaptive stepper's real-time budget (stone_stepper.hpp, "Budget"): at most rhs_per_frame
// right-hand sides per frame, and the error it then makes reported.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "model/stone/throw.hpp"
#include "solvers/realtime/stone_stepper.hpp"

using namespace stoneskip;

namespace {

Stone prism_stone() {
  const Mesh m = make_prism(0.03, 0.008, 11);
  return make_stone(m, mass_properties_from_density(m, 2500), 0.03, "prism");
}

// The convergence study's throw (8 m/s, 40 rev/s, α = 20°), released 2 m up so that the 0.1 s
// solved here is all flight: spin, gravity and the disk's air drag.
RigidState high_throw(const Stone& stone) {
  ThrowParameters p;
  p.speed_m_s = 8;
  p.path_angle_deg = 10;
  p.attack_angle_deg = 20;
  p.spin_rev_s = 40;
  p.height_m = 2;
  return initial_state(stone, p);
}

RealtimeOptions tight(double t_max_s) {
  RealtimeOptions o;  // bs32
  o.rtol = o.atol_m = 1e-12;
  o.t_max_s = t_max_s;
  o.record_trajectory = false;
  return o;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(frame_budget)

BOOST_AUTO_TEST_CASE(a_budget_caps_each_frame_and_reports_the_error_it_makes) {
  // Oracles: (1) the budget itself: 9 frames of 1/90 s at 8 right-hand sides may spend at most 72
  // (plus none: the first right-hand side counts in the first frame); (2) the same throw at
  // rtol = atol_m = 1e-12 without a budget, whose own error (~1e-12 m) is far below the budgeted
  // run's. At 8 per frame the stepper takes about two steps of 5.6 ms a frame, far longer than
  // rtol 1e-10 allows, so steps are forced (accepted over the tolerance, max_error_ratio > 1). The
  // reported estimate Σ‖ŷ − y‖ over the positions bounds the local errors of the second-order
  // member; the accepted third-order solution is more accurate, and over 0.1 s of smooth flight
  // their sum is the error to within the propagation of velocity errors (a factor of a few): the
  // true final position error must lie within [1e-3, 3] × the estimate — an estimate that is not
  // an error bound by orders of magnitude, or that misses it by more than 3×, fails.
  const Stone stone = prism_stone();
  Environment env;
  env.convention = Convention::physical;
  const RigidState s0 = high_throw(stone);
  const double t_max = 0.1;
  const ThrowResult truth = run_realtime(stone, env, s0, tight(t_max));
  RealtimeOptions o = tight(t_max);
  o.rtol = o.atol_m = 1e-10;
  o.rhs_per_frame = 8;
  o.frame_dt_s = 1.0 / 90;
  const ThrowResult r = run_realtime(stone, env, s0, o);
  BOOST_REQUIRE(r.outcome == Outcome::time_limit);
  BOOST_TEST(r.contacts.empty());
  const long frames = static_cast<long>(std::ceil(t_max / o.frame_dt_s - 1e-9));
  BOOST_TEST(r.stats.rhs_evaluations <= frames * o.rhs_per_frame);
  BOOST_TEST(r.stats.budget_forced_steps > 0);
  BOOST_TEST(r.stats.max_error_ratio > 1);
  const double error = (r.final_state.position_m - truth.final_state.position_m).norm();
  const double estimate = r.stats.position_error_estimate_m;
  BOOST_TEST_MESSAGE("budgeted: " << r.stats.steps << " steps, " << r.stats.rhs_evaluations << " rhs, "
                                  << r.stats.budget_forced_steps << " forced, worst ratio " << r.stats.max_error_ratio
                                  << "; final position error " << error << " m against the estimate " << estimate << " m");
  BOOST_TEST(error <= 3 * estimate);
  BOOST_TEST(error >= 1e-3 * estimate);
}

BOOST_AUTO_TEST_CASE(without_a_budget_no_step_is_forced_and_none_exceeds_the_tolerance) {
  // Oracle: the error test itself: every accepted step has error ratio ≤ 1; and a budget large
  // enough never forces a step, so the solution agrees with the free run to within 100× the
  // tolerance (1e-6 m over 0.1 s; its steps differ, since they now end on the frames' boundaries).
  const Stone stone = prism_stone();
  Environment env;
  env.convention = Convention::physical;
  const RigidState s0 = high_throw(stone);
  RealtimeOptions o = tight(0.1);
  o.rtol = o.atol_m = 1e-8;
  const ThrowResult free = run_realtime(stone, env, s0, o);
  BOOST_TEST(free.stats.budget_forced_steps == 0);
  BOOST_TEST(free.stats.max_error_ratio <= 1.0);
  BOOST_TEST(free.stats.max_error_ratio > 0.0);
  o.rhs_per_frame = 1000000;
  const ThrowResult loose = run_realtime(stone, env, s0, o);
  BOOST_TEST(loose.stats.budget_forced_steps == 0);
  BOOST_TEST((loose.final_state.position_m - free.final_state.position_m).norm() <= 1e-6);
}

BOOST_AUTO_TEST_SUITE_END()
