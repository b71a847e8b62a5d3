// The real-time stepper against closed forms: the ballistic parabola, torque-free tumbling of an
// asymmetric stone (angular momentum and rotational energy), and a flat plate dropped onto still
// water (m dw/dt = m g − C_w ρ_w S w²).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>

#include "model/stone/throw.hpp"
#include "solvers/realtime/stone_stepper.hpp"

using namespace stoneskip;

namespace {

Stone prism_stone(double R = 0.03, double h = 0.008, int n = 11, double rho = 2500) {
  const Mesh m = make_prism(R, h, n);
  return make_stone(m, mass_properties_from_density(m, rho), R, "prism");
}

// An asymmetric stone: the prism squashed to 60 % in y, so I_xx, I_yy, I_zz all differ.
Stone asymmetric_stone() {
  Mesh m = make_prism(0.04, 0.01, 11);
  for (auto& v : m.vertices) v.y() *= 0.6;
  return make_stone(m, mass_properties_from_density(m, 2500), 0.04, "squashed prism");
}

Environment vacuum() {
  Environment e;
  e.air_density_kg_m3 = 0;
  return e;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(realtime_stepper)

BOOST_AUTO_TEST_CASE(free_flight_follows_the_parabola) {
  // Oracle: x = x0 + v0 t, z = z0 + vz0 t − g t²/2 (no air, far above the water).
  // rk4 and midpoint integrate a quadratic exactly: round-off only (1e-9 m over 10 s of
  // 10⁴ steps of ~10 m). Semi-implicit Euler has the closed-form error z_n − z(t) = −g t dt/2
  // (v is updated before x), which the test checks to round-off as well.
  const Stone s = prism_stone();
  const Environment env = vacuum();
  ThrowParameters p{12.0, -30.0, 5.0, 7.0, 1000.0, 0.0};  // thrown upwards at 30°
  const RigidState s0 = initial_state(s, p);
  for (Scheme scheme : {Scheme::semi_implicit_euler, Scheme::midpoint, Scheme::rk4}) {
    RealtimeOptions o;
    o.scheme = scheme;
    o.dt_s = 1e-3;
    o.contact_dt_s = 1e-3;
    o.t_max_s = 10.0;
    o.record_trajectory = false;
    const ThrowResult r = run_realtime(s, env, s0, o);
    const double t = r.end_time_s;
    BOOST_TEST(std::abs(t - 10.0) <= 1e-9);
    const Vec3 exact = s0.position_m + s0.velocity_m_s * t + Vec3(0, 0, -0.5 * env.gravity_m_s2 * t * t);
    const Vec3 scheme_error = scheme == Scheme::semi_implicit_euler ? Vec3(0, 0, -0.5 * env.gravity_m_s2 * t * o.dt_s) : Vec3::Zero();
    BOOST_TEST((r.final_state.position_m - exact - scheme_error).norm() <= 1e-9, to_string(scheme));
    BOOST_TEST(r.contacts.empty());
    BOOST_TEST(r.stats.contact_steps == 0);
  }
}

BOOST_AUTO_TEST_CASE(a_tumbling_asymmetric_stone_keeps_its_angular_momentum_and_energy) {
  // Oracle: torque-free rigid body — L (world) and ½ ω·L are invariants. Spun mostly about the
  // intermediate axis, the stone tumbles (flips) repeatedly over 10 s, exercising the attitude.
  // L is advanced by dL = 0 and is exact in every scheme (round-off). The energy is conserved
  // to the scheme's accuracy: rk4 at 1e-4 s, 1e-9 relative (bound (ω dt)⁴ · ω t ≈ 8e-10; seen
  // 6e-14); semi-implicit Euler (order 1) at 1e-5 s to 5e-3 (first order, ~ ω dt · ω t / 10 ≈
  // 3e-3 — seen 2.2e-3; halving dt halves it).
  const Stone s = asymmetric_stone();
  const Environment env = vacuum();
  RigidState s0;
  s0.position_m = Vec3(0, 0, 1e4);
  set_body_angular_velocity(s, s0, Vec3(0.05, 15.0, 0.1));
  const double e0 = mechanical_energy(s, env, s0).rotational_J;
  struct Case { Scheme scheme; double dt; double tol; };
  for (const Case c : {Case{Scheme::rk4, 1e-4, 1e-9}, Case{Scheme::semi_implicit_euler, 1e-5, 5e-3}}) {
    RealtimeOptions o;
    o.scheme = c.scheme;
    o.dt_s = c.dt;
    o.contact_dt_s = c.dt;
    o.t_max_s = 10.0;
    o.output_dt_s = 0.01;
    Environment no_gravity = env;
    no_gravity.gravity_m_s2 = 0;
    const ThrowResult r = run_realtime(s, no_gravity, s0, o);
    BOOST_TEST((r.final_state.angular_momentum_kg_m2_s - s0.angular_momentum_kg_m2_s).norm() <=
               1e-12 * s0.angular_momentum_kg_m2_s.norm());
    double worst = 0, min_body_y = 1;
    for (const auto& p : r.trajectory) {
      const double e = 0.5 * p.angular_velocity_rad_s.dot(p.state.angular_momentum_kg_m2_s);
      worst = std::max(worst, std::abs(e - e0) / e0);
      const Vec3 body_y = p.state.orientation * Vec3::UnitY();
      min_body_y = std::min(min_body_y, body_y.dot(s0.angular_momentum_kg_m2_s.normalized()));
    }
    BOOST_TEST(worst <= c.tol, to_string(c.scheme) << " worst relative energy drift " << worst);
    BOOST_TEST(min_body_y < -0.9, "the stone must actually flip (intermediate-axis tumbling)");
  }
}

BOOST_AUTO_TEST_CASE(a_flat_plate_dropped_flat_follows_the_closed_form) {
  // Oracle: while only the bottom face is wet, m dw/dt = m g − C ρ S w² (w downward speed).
  // With k = C ρ S / m and w_t = √(g/k): for w0 > w_t, w(t) = w_t coth(a + √(gk) t),
  // a = acoth(w0/w_t), and the depth fallen is (1/k) ln(sinh(a + √(gk) t)/sinh(a)).
  // rk4 with 1e-6 s steps: error ~ (dt/τ)⁴ with τ = 1/√(gk) ≈ 0.05 s: far below 1e-9 relative.
  const double R = 0.05, h = 0.01, rho = 2500;
  const Stone s = prism_stone(R, h, 11, rho);
  Environment env = vacuum();
  env.water_coefficient = 0.7;
  RigidState s0;
  s0.position_m = Vec3(0, 0, h / 2 - 1e-9);  // bottom face just wet
  s0.velocity_m_s = Vec3(0, 0, -2.0);
  const double S = 0.5 * 11 * R * R * std::sin(2 * std::numbers::pi / 11);
  const double m = s.mass.mass_kg, g = env.gravity_m_s2;
  const double k = env.water_coefficient * env.water_density_kg_m3 * S / m;
  const double wt = std::sqrt(g / k), a = std::atanh(wt / 2.0), rate = std::sqrt(g * k);
  RealtimeOptions o;
  o.scheme = Scheme::rk4;
  o.dt_s = 1e-6;
  o.contact_dt_s = 1e-6;
  o.t_max_s = 0.004;  // the top face (0.01 m above the bottom) stays dry: fallen < 0.009 m
  o.record_trajectory = true;
  o.output_dt_s = 1e-3;
  const ThrowResult r = run_realtime(s, env, s0, o);
  BOOST_TEST(r.trajectory.size() >= 4u);
  for (const auto& p : r.trajectory) {
    const double t = p.t_s;
    const double w = wt / std::tanh(a + rate * t);
    const double fallen = std::log(std::sinh(a + rate * t) / std::sinh(a)) / k;
    BOOST_TEST(std::abs(-p.state.velocity_m_s.z() - w) <= 1e-9 * w, "t = " << t);
    BOOST_TEST(std::abs((s0.position_m.z() - p.state.position_m.z()) - fallen) <= 1e-9 * h, "t = " << t);
  }
  BOOST_TEST(s0.position_m.z() - r.final_state.position_m.z() < h - 1e-3);
}

BOOST_AUTO_TEST_CASE(contact_start_is_located_between_steps) {
  // Oracle: a flat plate falling from rest touches the water when its bottom face (h/2 below the
  // centre) reaches z = 0: t = √(2 (z0 − h/2) / g). Linear interpolation of the deepest depth
  // inside a 1e-5 s contact step adds only ~g dt²/(8 v) ≈ 1e-10 s (1e-8 s allowed); the bound is
  // set by the flight part, integrated with semi-implicit Euler in 1e-3 s steps (below).
  const double h = 0.008, z0 = 0.2;
  const Stone s = prism_stone(0.03, h);
  const Environment env = vacuum();
  RigidState s0;
  s0.position_m = Vec3(0, 0, z0);
  RealtimeOptions o;
  o.dt_s = 1e-3;
  o.contact_dt_s = 1e-5;
  o.t_max_s = 0.3;
  o.record_trajectory = false;
  const ThrowResult r = run_realtime(s, env, s0, o);
  BOOST_REQUIRE(!r.contacts.empty());
  const double exact = std::sqrt(2 * (z0 - h / 2) / env.gravity_m_s2);
  // Semi-implicit Euler's own position error at t is g t dt/2 in z for the flight part
  // (1e-3 s steps until the stone is near the water) → time error ≈ (g t dt/2)/(g t) = dt/2.
  BOOST_TEST(std::abs(r.contacts[0].start_s - exact) <= 0.5 * o.dt_s + 1e-8);
  BOOST_TEST(r.stats.contact_steps > 0);
}

BOOST_AUTO_TEST_SUITE_END()
