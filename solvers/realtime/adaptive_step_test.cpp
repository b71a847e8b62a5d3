// The adaptive stepper's embedded pairs (adaptive_step.hpp) and their dense output
// (dense_output.hpp) against an independent computation: rk4 in steps a thousand times shorter, on
// an asymmetric stone's flight, tumbling (gravity, no air), whose attitude no scheme here
// integrates exactly.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

#include "model/stone/throw.hpp"
#include "solvers/realtime/adaptive_step.hpp"
#include "solvers/realtime/dense_output.hpp"
#include "solvers/realtime/stone_stepper.hpp"

using namespace stoneskip;

namespace {

// An asymmetric stone (the prism squashed to 60 % in y: I_xx, I_yy, I_zz all differ), so that its
// body angular velocity moves (Euler's equations) and no scheme integrates its attitude exactly.
// (A symmetric stone spun about its axis turns at a constant ω: each pair's solution is then a
// truncated exponential whose leading error is along q, which the renormalisation removes, and
// both pairs show one order more than their own.)
Stone squashed_stone() {
  Mesh m = make_prism(0.04, 0.01, 11);
  for (auto& v : m.vertices) v.y() *= 0.6;
  return make_stone(m, mass_properties_from_density(m, 2500), 0.04, "squashed prism");
}

// Thrown at 8 m/s, 2 m above the water (all flight: gravity and the disk's air drag), spinning at
// 60 rad/s about mostly its intermediate axis, where it tumbles.
RigidState high_throw(const Stone& stone) {
  RigidState s;
  s.position_m = Vec3(0, 0, 2);
  s.velocity_m_s = Vec3(8, 0, 1);
  set_body_angular_velocity(stone, s, Vec3(0.5, 60.0, 1.0));
  return s;
}

// n steps of a scheme's step (realtime_step: no contact logic; the pairs at a fixed size).
RigidState stepped(const Stone& stone, const Environment& env, RigidState s, double t_s, int n, Scheme scheme) {
  for (int i = 0; i < n; ++i) s = realtime_step(stone, env, s, t_s / n, scheme);
  return s;
}

// The state's distance from another: the position (m) and the rim's displacement by the rotation
// between the two attitudes (bounding radius × angle), whichever is larger.
double distance(const Stone& stone, const RigidState& a, const RigidState& b) {
  const double angle = a.orientation.angularDistance(b.orientation);
  return std::max((a.position_m - b.position_m).norm(), stone.bounding_radius_m * angle);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(adaptive_pairs)

BOOST_AUTO_TEST_CASE(each_pair_s_solution_converges_at_its_order) {
  // Oracle: rk4 in 2e5 steps over 0.1 s (ω dt = 3e-5 rad: its error ~ (ω dt)⁴ of the rim, far
  // below round-off). Each pair's solution at fixed steps must converge at its order p, bs32 3 and
  // dp54 5. The series is fixed before looking: from 16 steps (ω h = 0.38) doubling, each point
  // kept while its error is above kFloor_m (100 × the round-off floor, ~1e-13 m, where the errors
  // stop falling), at least three points. The observed orders approach p from above as h falls
  // (pre-asymptotic), so each must be at least p − kOrderSlack and the finest within kOrderSlack
  // of p. A wrong coefficient of dp54's drops it to order 4 or below.
  constexpr double kOrderSlack = 0.3;
  constexpr double kFloor_m = 1e-11;
  const Stone stone = squashed_stone();
  Environment env;
  env.air_density_kg_m3 = 0;  // u|u| of the disk's air model has a kink at u = 0 (edge-on), which a tumble crosses
  const RigidState s0 = high_throw(stone);
  const double t = 0.1;
  const RigidState truth = stepped(stone, env, s0, t, 200000, Scheme::rk4);
  struct Case {
    Scheme scheme;
    double order;
  };
  for (const Case c : {Case{Scheme::bs32, 3}, Case{Scheme::dp54, 5}}) {
    std::vector<double> errors;
    for (int n = 16; n <= 4096; n *= 2) {
      const double e = distance(stone, stepped(stone, env, s0, t, n, c.scheme), truth);
      if (e < kFloor_m) break;
      errors.push_back(e);
    }
    BOOST_REQUIRE_MESSAGE(errors.size() >= 3, to_string(c.scheme) << ": " << errors.size() << " points above the floor");
    for (std::size_t i = 0; i + 1 < errors.size(); ++i) {
      const double p = std::log2(errors[i] / errors[i + 1]);
      const bool finest = i + 2 == errors.size();
      BOOST_TEST((p >= c.order - kOrderSlack && (!finest || p <= c.order + kOrderSlack)),
                 to_string(c.scheme) << ": errors " << errors[i] << ", " << errors[i + 1] << " m, order " << p);
    }
  }
}

BOOST_AUTO_TEST_CASE(in_a_steady_spin_the_attitude_converges_at_the_scheme_s_steady_spin_order) {
  // Oracle: the closed form of a steady spin, q(t) = exp(½ ω t) q₀ (ω along the body's largest
  // principal axis, no torque: the disk's air model exerts none, model/README.md §1.5), and the
  // orders steady_spin_order derives (stone_stepper.hpp): midpoint 2, rk4 4, bs32 4, dp54 6. The
  // series is fixed before looking, as above: from 16 steps doubling, each point kept while its
  // angle error is above kFloor_rad, at least three points; every pairwise order at least
  // order − kOrderSlack, the finest within kOrderSlack of it. For bs32 and dp54 the finest order
  // must also lie 0.5 or more above the formal one, so that the check can tell p from p + 1 (a
  // step without the renormalisation, or one that renormalised inside the stages, shows p).
  constexpr double kOrderSlack = 0.3;
  constexpr double kFloor_rad = 1e-11;
  const Stone stone = squashed_stone();
  Environment env;
  env.air_density_kg_m3 = 0;
  RigidState s0 = high_throw(stone);
  s0.orientation = Quat(Eigen::AngleAxisd(0.4, Vec3(1, 1, 0).normalized()));
  const Vec3 omega_body(0, 0, 60.0);
  set_body_angular_velocity(stone, s0, omega_body);
  const Vec3 omega_world = s0.orientation * omega_body;
  const double t = 0.1;
  const Quat truth = Quat(Eigen::AngleAxisd(omega_world.norm() * t, omega_world.normalized())) * s0.orientation;
  for (const Scheme scheme : {Scheme::midpoint, Scheme::rk4, Scheme::bs32, Scheme::dp54}) {
    const double order = steady_spin_order(scheme);
    std::vector<double> errors;
    for (int n = 16; n <= 4096; n *= 2) {
      const double e = stepped(stone, env, s0, t, n, scheme).orientation.angularDistance(truth);
      if (e < kFloor_rad) break;
      errors.push_back(e);
    }
    BOOST_REQUIRE_MESSAGE(errors.size() >= 3, to_string(scheme) << ": " << errors.size() << " points above the floor");
    for (std::size_t i = 0; i + 1 < errors.size(); ++i) {
      const double p = std::log2(errors[i] / errors[i + 1]);
      const bool finest = i + 2 == errors.size();
      BOOST_TEST((p >= order - kOrderSlack && (!finest || p <= order + kOrderSlack)),
                 to_string(scheme) << ": errors " << errors[i] << ", " << errors[i + 1] << " rad, order " << p << ", expected " << order);
      if (finest && formal_order(scheme) % 2 == 1) BOOST_TEST(p >= formal_order(scheme) + 0.5, to_string(scheme) << ": order " << p);
    }
  }
}

BOOST_AUTO_TEST_CASE(dp54_s_dense_output_is_a_fifth_order_local_interpolant) {
  // Oracle: rk4 in 4000 steps to θ h inside one dp54 step of size h. Dormand–Prince's continuous
  // extension (the cubic Hermite plus θ²(1 − θ)² q) errs by O(h⁵) inside the step (halving h
  // divides it by 32), the cubic Hermite alone by O(h⁴) (16). At θ = 0.3 (not the midpoint, where
  // errors of odd symmetry vanish) the extension's order between halvings must be within
  // kOrderSlack of 5, and its error below the cubic's at every h: a quartic term with a wrong
  // coefficient is no better than the cubic and converges at its order, 4.
  constexpr double kOrderSlack = 0.4;
  constexpr double theta = 0.3;
  const Stone stone = squashed_stone();
  Environment env;
  env.air_density_kg_m3 = 0;  // u|u| of the disk's air model has a kink at u = 0 (edge-on), which a tumble crosses
  const RigidState s0 = high_throw(stone);
  const StateVector y0 = to_vector(s0);
  StateVector k1;
  rigid_body_rhs(stone, env, y0.data(), k1.data(), nullptr);
  StateVector atol;
  atol.fill(1.0);
  std::vector<double> quartic, cubic;
  for (double h : {4e-3, 2e-3, 1e-3, 5e-4}) {
    const AdaptiveTrial trial = dp54_step(stone, env, y0, k1, h, nullptr, atol, 0.0);
    BOOST_REQUIRE(trial.has_quartic);
    HermiteStep dense{y0, trial.y1, k1, trial.k4, h, trial.quartic, true};
    const RigidState truth = stepped(stone, env, s0, theta * h, 4000, Scheme::rk4);
    quartic.push_back(distance(stone, dense.state_at(theta), truth));
    dense.has_quartic = false;
    cubic.push_back(distance(stone, dense.state_at(theta), truth));
    BOOST_TEST(quartic.back() < cubic.back(), "h " << h << ": quartic " << quartic.back() << " m, cubic " << cubic.back());
  }
  for (std::size_t i = 0; i + 1 < quartic.size(); ++i) {
    const double p = std::log2(quartic[i] / quartic[i + 1]);
    BOOST_TEST(std::abs(p - 5) <= kOrderSlack, "errors " << quartic[i] << ", " << quartic[i + 1] << " m, order " << p);
  }
}

BOOST_AUTO_TEST_CASE(dp54_s_error_estimate_is_blind_to_a_jump_inside_its_step_and_bs32_s_is_not) {
  // Oracle: the tableaux' arithmetic. A field whose x advances at 1 (a clock) and whose v_x jumps
  // from 0 to 1 where x passes f = 0.25 of a unit step: the exact change of v_x is 1 − f = 0.75,
  // the pair's solution adds b_i over the stages past the jump (c_i > f), its error estimate e_i
  // over the same stages. dp54: stages 3–7, Σ b = 1 − 35/384 (error 0.25 − 35/384 = 0.159) and
  // Σ e = −e₁ = −71/57600 (0.0012): the estimate sees 1/129 of the error, which is why dp54 cuts
  // its steps at the loads' jumps (default kinks "all"). bs32: stages 2–4, Σ b = 7/9 (error 1/36),
  // Σ e = 1/12 + 1/9 − 1/8 = 5/72: its estimate bounds the error here.
  constexpr double kRoundoff = 1e-14;
  const Stone stone = squashed_stone();
  const Environment env;
  const double f = 0.25;
  const FieldFunction field = [f](const double* y, double* d) {
    for (int i = 0; i < kStateSize; ++i) d[i] = 0;
    d[kPosition] = 1;
    d[kVelocity] = y[kPosition] > f ? 1 : 0;
  };
  const StateVector y0 = to_vector(RigidState{});
  StateVector k1, atol;
  field(y0.data(), k1.data());
  atol.fill(1.0);
  // Only v_x has an error estimate (x is integrated exactly): |e_v| = RMS × √(state size).
  const auto estimate = [](const AdaptiveTrial& t) { return t.error_norm * std::sqrt(double(kStateSize)); };
  const AdaptiveTrial dp = dp54_step(stone, env, y0, k1, 1.0, nullptr, atol, 0.0, &field);
  const double dp_error = dp.y1[kVelocity] - (1 - f);
  BOOST_TEST(dp_error == 0.25 - 35.0 / 384, boost::test_tools::tolerance(kRoundoff));
  BOOST_TEST(estimate(dp) == 71.0 / 57600, boost::test_tools::tolerance(kRoundoff));
  BOOST_TEST(std::abs(dp_error) > 100 * estimate(dp));
  const AdaptiveTrial bs = bs32_step(stone, env, y0, k1, 1.0, nullptr, atol, 0.0, &field);
  const double bs_error = bs.y1[kVelocity] - (1 - f);
  BOOST_TEST(bs_error == 1.0 / 36, boost::test_tools::tolerance(kRoundoff));
  BOOST_TEST(estimate(bs) == 5.0 / 72, boost::test_tools::tolerance(kRoundoff));
  BOOST_TEST(estimate(bs) >= std::abs(bs_error));
  // And the default kinks follow: dp54 cuts at every switch, bs32 at the crossings.
  BOOST_TEST((default_kink_steps(Scheme::dp54) == KinkSteps::all));
  BOOST_TEST((default_kink_steps(Scheme::bs32) == KinkSteps::crossings));
}

BOOST_AUTO_TEST_CASE(the_pairs_step_sizes_follow_their_orders) {
  // Oracle: the step-size rule h · clamp(0.9 err^(−1/(q+1)), 0.2, 5) (Hairer, Nørsett & Wanner
  // §II.4, Eq. 4.13) with q the embedded order: 2 for bs32, 4 for dp54. Closed form at three
  // error norms (one each side of the clamps, one inside).
  BOOST_TEST(bs32_next_step(1.0, 8.0) == 0.9 / 2.0, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(dp54_next_step(1.0, 32.0) == 0.9 / 2.0, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(dp54_next_step(1.0, 1e-12) == 5.0);
  BOOST_TEST(dp54_next_step(1.0, 1e6) == 0.2);
  BOOST_TEST(dp54_next_step(1.0, 0.0) == 5.0);
}

BOOST_AUTO_TEST_SUITE_END()
