// The real-time stepper against closed forms: the ballistic parabola, torque-free tumbling of an
// asymmetric stone (angular momentum and rotational energy), a flat plate dropped onto still
// water (m dw/dt = m g − C_w ρ_w S w²) and the time it sinks, the first-touch point of a stone in
// free flight, and contacts started and ended by a moving water surface.
#include <boost/test/unit_test.hpp>

#include <chrono>
#include <cmath>
#include <limits>
#include <vector>
#include <numbers>
#include <ostream>
#include <thread>

#include "model/stone/throw.hpp"
#include "model/stone/water_surface.hpp"
#include "solvers/realtime/stone_stepper.hpp"

namespace stoneskip {
// Lets Boost.Test print the enum in a failure message.
inline std::ostream& operator<<(std::ostream& o, Outcome x) { return o << to_string(x); }
inline std::ostream& operator<<(std::ostream& o, ContactLog::Status x) { return o << to_string(x); }
}  // namespace stoneskip

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

// A flat water surface whose level a test moves between steps (a stand-in for a live field).
class FlatLevel : public WaterSurface {
 public:
  double level_m = 0;
  double height_m(double, double) const override { return level_m; }
};

// The plate of the dropped-plate tests: R = 5 cm, h = 1 cm, C_w = 0.7, no air, released with its
// bottom face just wet at 2 m/s downwards. While only the bottom face pushes (the rim faces are
// vertical: u = v·n = 0 exactly), m dw/dt = m g − C ρ S w², so with k = C ρ S / m,
// w_t = √(g/k), a = atanh(w_t/w0), rate = √(g k): w(t) = w_t coth(a + rate t) and the depth
// fallen is (1/k) ln(sinh(a + rate t)/sinh(a)).
struct DroppedPlate {
  double R = 0.05, h = 0.01, rho = 2500, w0 = 2.0;
  Stone stone = prism_stone(R, h, 11, rho);
  Environment env = [] {
    Environment e = vacuum();
    e.water_coefficient = 0.7;
    return e;
  }();
  RigidState initial() const {
    RigidState s0;
    s0.position_m = Vec3(0, 0, h / 2 - 1e-9);  // bottom face just wet
    s0.velocity_m_s = Vec3(0, 0, -w0);
    return s0;
  }
  double k() const {
    const double S = 0.5 * 11 * R * R * std::sin(2 * std::numbers::pi / 11);
    return env.water_coefficient * env.water_density_kg_m3 * S / stone.mass.mass_kg;
  }
  double wt() const { return std::sqrt(env.gravity_m_s2 / k()); }
  double a() const { return std::atanh(wt() / w0); }
  double rate() const { return std::sqrt(env.gravity_m_s2 * k()); }
  double speed(double t) const { return wt() / std::tanh(a() + rate() * t); }
  // The time at which the plate has fallen `fallen` metres.
  double time_to_fall(double fallen) const {
    return (std::asinh(std::sinh(a()) * std::exp(k() * fallen)) - a()) / rate();
  }
};

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

BOOST_AUTO_TEST_CASE(the_trajectory_is_sampled_at_each_output_time_however_short_output_dt_is) {
  // Oracle: rk4 in free flight with 1 ms steps, 0.5 s. With output_dt_s = 0.01 the samples are the
  // steps at k·0.01 s, k = 0 … 50 (to round-off of the summed steps); with an output_dt_s far below
  // the step (1e-14 s, and 1e-300 s) every step's end is an output time: the samples are those of
  // output_dt_s = 0 (every step), 501 of them. The stepper used to step the next output time up
  // by output_dt_s, which at 1e-14 s took 1e11 additions a step and at 1e-300 s never moved it
  // (a hang, found by feeding the CLI such a value).
  const Stone s = prism_stone();
  const RigidState s0 = initial_state(s, ThrowParameters{12.0, -30.0, 5.0, 7.0, 1000.0, 0.0});
  auto times = [&](double output_dt_s) {
    RealtimeOptions o;
    o.scheme = Scheme::rk4;
    o.dt_s = o.contact_dt_s = 1e-3;
    o.t_max_s = 0.5;
    o.output_dt_s = output_dt_s;
    std::vector<double> t;
    for (const TrajectorySample& x : run_realtime(s, vacuum(), s0, o).trajectory) t.push_back(x.t_s);
    return t;
  };
  const std::vector<double> every = times(0), coarse = times(0.01);
  BOOST_TEST_REQUIRE(every.size() == 501u);
  BOOST_TEST_REQUIRE(coarse.size() == 51u);
  for (std::size_t k = 0; k < coarse.size(); ++k) BOOST_TEST(std::abs(coarse[k] - 0.01 * k) <= 1e-12);
  for (double tiny : {1e-14, 1e-300}) {
    const std::vector<double> t = times(tiny);
    BOOST_TEST_REQUIRE(t.size() == every.size(), "output_dt_s = " << tiny);
    for (std::size_t k = 0; k < t.size(); ++k) BOOST_TEST(t[k] == every[k]);
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

BOOST_AUTO_TEST_CASE(a_nan_water_surface_fails_the_throw_saying_so) {
  // Oracle: the bad-input rule, no silent default: a surface that gives NaN heights (a broken field)
  // makes NaN loads (fluid_forces.cpp), and every scheme fails the throw with its reason, promptly.
  // The loads had skipped a NaN depth: the stone flew on as if over no water, to t_max_s.
  struct NanSurface : WaterSurface {
    double height_m(double, double) const override { return std::numeric_limits<double>::quiet_NaN(); }
  } nan_surface;
  const Stone s = prism_stone();
  const RigidState s0 = initial_state(s, {8, 10, 10, 5, 0.1, 0});
  for (Scheme scheme : {Scheme::bs32, Scheme::semi_implicit_euler, Scheme::rk4}) {
    RealtimeOptions o;
    o.scheme = scheme;
    o.t_max_s = 5;
    o.record_trajectory = false;
    const auto t0 = std::chrono::steady_clock::now();
    const ThrowResult r = run_realtime(s, Environment{}, s0, o, &nan_surface);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    BOOST_TEST_CONTEXT(to_string(scheme)) {
      BOOST_TEST(r.outcome == Outcome::failed, r.outcome_detail);
      BOOST_TEST(!r.outcome_detail.empty());
      BOOST_TEST(seconds < 5.0);  // no hang: the state or the step fails at once
    }
  }
}

BOOST_AUTO_TEST_CASE(contact_start_is_located_between_steps) {
  // Oracle: a flat plate falling from rest touches the water when its bottom face (h/2 below the
  // centre) reaches z = 0: t = √(2 (z0 − h/2) / g). Locating the touch inside a 1e-5 s contact step
  // adds at most what linear interpolation would, ~g dt²/(8 v) ≈ 1e-10 s (1e-8 s allowed); the bound is
  // set by the flight part, integrated with semi-implicit Euler in 1e-3 s steps (below).
  const double h = 0.008, z0 = 0.2;
  const Stone s = prism_stone(0.03, h);
  const Environment env = vacuum();
  RigidState s0;
  s0.position_m = Vec3(0, 0, z0);
  RealtimeOptions o;
  o.scheme = Scheme::semi_implicit_euler;  // a fixed-step study (the default is bs32)
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

BOOST_AUTO_TEST_CASE(a_fixed_step_into_the_water_enters_at_the_flight_s_speed_and_energy) {
  // Oracle: in vacuum the flight is ballistic: v(t) = v0 + g t, and the energy at the entry is the
  // release energy. A stone thrown at 30 m/s, 10° down, from 10 cm enters the water inside a
  // single game-frame step (1/90 s, semi-implicit Euler, the fixed scheme a game would use); the
  // step's end lies deep under water. The entry was located on a cubic Hermite whose end slope
  // held the water's loads at that depth, and reported 42.5 m/s and 50.6 J from a 24 J release
  // (a flight "gaining" 26 J). Now: semi-implicit Euler's velocity is exact for constant g and
  // the interpolant's velocity with it (1e-9 m/s: round-off of the root's time); its position is
  // off by g h²/2 a step, so the energy by ≤ m g · g h² (2 steps), 3e-5 of it here (1e-4 allowed).
  const Stone s = prism_stone();
  const Environment env = vacuum();
  const ThrowParameters p{30.0, 10.0, 20.0, 10.0, 0.1, 0.0};
  const RigidState s0 = initial_state(s, p);
  RealtimeOptions o;
  o.scheme = Scheme::semi_implicit_euler;
  o.dt_s = o.contact_dt_s = 1.0 / 90;
  o.t_max_s = 0.1;
  o.record_trajectory = false;
  const ThrowResult r = run_realtime(s, env, s0, o);
  BOOST_REQUIRE(!r.contacts.empty());
  const ContactRecord& c = r.contacts[0];
  const double e0 = mechanical_energy(s, env, s0).total_J();
  const Vec3 v = s0.velocity_m_s + Vec3(0, 0, -env.gravity_m_s2) * c.start_s;
  BOOST_TEST(std::abs(c.entry_speed_m_s - v.norm()) <= 1e-9);
  BOOST_TEST(std::abs(c.entry_energy_J - e0) <= 1e-4 * e0);
}

BOOST_AUTO_TEST_CASE(a_step_whose_stages_met_the_water_between_dry_ends_is_counted) {
  // Oracle: the same grazing throw (8 m/s, 1° down, from 2 cm) with fine rk4 steps makes contacts;
  // one 0.1 s rk4 step from the release has its third stage ~1 cm under water (z0 + dt/2 (v0 +
  // g dt/2)) while both its ends are dry, so no contact is logged although the water's loads changed
  // the throw: the step must be counted, not silent. The fine run has no such step.
  const Stone s = prism_stone();
  const Environment env = vacuum();
  const RigidState s0 = initial_state(s, ThrowParameters{8.0, 1.0, 10.0, 10.0, 0.02, 0.0});
  RealtimeOptions o;
  o.scheme = Scheme::rk4;
  o.record_trajectory = false;
  o.t_max_s = 0.1;
  o.dt_s = 1e-3;
  o.contact_dt_s = 1e-5;
  const ThrowResult fine = run_realtime(s, env, s0, o);
  BOOST_TEST(!fine.contacts.empty());
  BOOST_TEST(fine.stats.steps_through_water == 0);
  o.dt_s = o.contact_dt_s = 0.1;
  const ThrowResult coarse = run_realtime(s, env, s0, o);
  BOOST_TEST(coarse.stats.steps == 1);
  BOOST_TEST(coarse.contacts.empty());
  BOOST_TEST(coarse.stats.steps_through_water == 1);
  BOOST_TEST(coarse.stats.first_step_through_water_s == 0.0);
}

BOOST_AUTO_TEST_CASE(a_dropped_plate_sinks_at_the_closed_form_time_and_place) {
  // Oracle: the dropped plate's closed form (DroppedPlate): it sinks when its top face reaches the
  // surface, i.e. after falling h − 1e-9 m, at t_s = time_to_fall(h − 1e-9), with its centre at
  // z = −h/2 (the top face, h/2 above the centre, at z = 0). The stepper locates the crossing of
  // the last vertex inside the step on the step's cubic Hermite interpolant, which errs less than
  // linear interpolation of its depth would: for a depth z(t) with |z''| = |k w² − g| and |z'| = w
  // at the crossing, at most |z''| dt²/(8 w). rk4's own error ((dt·rate)⁴ ≈ 1e-11 relative at
  // 1e-4 s) is far below it, so the sinking time must be within that bound (× 2 for the step's
  // cubic term) at every contact step. The located centre is at −h/2 to round-off.
  const DroppedPlate p;
  const double t_exact = p.time_to_fall(p.h - 1e-9);
  const double w = p.speed(t_exact), accel = std::abs(p.k() * w * w - p.env.gravity_m_s2);
  constexpr double kCubicMargin = 2;       // the bound is for a quadratic depth over the step
  constexpr double kRoundoff_s = 1e-15;    // a few ulps of a 6 ms time
  constexpr double kRoundoff_m = 1e-15;    // a few ulps of a 5 mm height
  for (double dt : {1e-4, 5e-5, 2.5e-5}) {
    RealtimeOptions o;
    o.scheme = Scheme::rk4;
    o.dt_s = dt;
    o.contact_dt_s = dt;
    o.t_max_s = 0.05;
    o.output_dt_s = 0;
    const ThrowResult r = run_realtime(p.stone, p.env, p.initial(), o);
    BOOST_REQUIRE(r.outcome == Outcome::sank);
    BOOST_REQUIRE(r.contacts.size() == 1u);
    const ContactRecord& c = r.contacts.back();
    const double bound = kCubicMargin * accel * dt * dt / (8 * w) + kRoundoff_s;
    BOOST_TEST(std::abs(r.end_time_s - t_exact) <= bound, "dt " << dt << ": sank at " << r.end_time_s << " s, exact "
                                                           << t_exact << " s, error " << r.end_time_s - t_exact
                                                           << " s, bound " << bound << " s");
    // The outcome, the end of the last contact, the final state and the last sample agree.
    BOOST_TEST(c.end_s == r.end_time_s);
    BOOST_TEST(!c.bounced);
    BOOST_TEST((c.exit_position_m - r.final_state.position_m).norm() == 0.0);
    BOOST_TEST(r.trajectory.back().t_s == r.end_time_s);
    BOOST_TEST(std::abs(r.final_state.position_m.z() + p.h / 2) <= kRoundoff_m,
               "dt " << dt << ": centre at " << r.final_state.position_m.z() << " m when it sank");
  }
}

namespace {

// The exact first touch of a stone in free flight without air: the centre follows the parabola
// x0 + v0 t − g t²/2 ẑ, and a symmetric stone (I_xx = I_yy) spun about its symmetry axis turns
// at constant ω about that fixed axis, R(t) = AngleAxis(|ω| t, n) R0. Each vertex's height is then
// a closed form in t; its first zero is bracketed on a 1e-6 s grid and bisected to round-off.
struct ExactTouch {
  double t_s = 0;
  Vec3 point_m = Vec3::Zero();
  double vertex_speed_m_s = 0, vertex_vertical_speed_m_s = 0;
};

ExactTouch exact_first_touch(const Stone& stone, const RigidState& s0, const Vec3& omega, double g) {
  const double w = omega.norm();
  const Vec3 axis = w > 0 ? Vec3(omega / w) : Vec3::UnitZ();
  auto vertex = [&](int j, double t) {
    const Quat q = Quat(Eigen::AngleAxisd(w * t, axis)) * s0.orientation;
    return Vec3(s0.position_m + s0.velocity_m_s * t + Vec3(0, 0, -0.5 * g * t * t) + q * stone.body_mesh.vertices[j]);
  };
  ExactTouch best;
  best.t_s = 1e300;
  for (int j = 0; j < static_cast<int>(stone.body_mesh.vertices.size()); ++j) {
    double lo = 0, hi = -1;
    for (double t = 1e-6; t < 1.0; t += 1e-6)
      if (vertex(j, t).z() <= 0) {
        lo = t - 1e-6;
        hi = t;
        break;
      }
    if (hi < 0 || lo >= best.t_s) continue;
    for (int it = 0; it < 200 && hi - lo > 1e-16; ++it) {
      const double mid = 0.5 * (lo + hi);
      (vertex(j, mid).z() > 0 ? lo : hi) = mid;
    }
    if (hi < best.t_s) {
      best.t_s = hi;
      best.point_m = vertex(j, hi);
      const double e = 1e-7;
      const Vec3 v = (vertex(j, hi + e) - vertex(j, hi - e)) / (2 * e);
      best.vertex_speed_m_s = v.norm();
      best.vertex_vertical_speed_m_s = std::abs(v.z());
    }
  }
  return best;
}

// The throw of the first-touch tests: 8 m/s at 0.17 rad down, the stone tilted and spun at
// 40 rev/s about its symmetry axis, 0.1 m up; with its exact first touch.
struct SpunThrow {
  RigidState s0;
  ExactTouch exact;
};

SpunThrow spun_tilted_throw(const Stone& stone, double g) {
  SpunThrow t;
  t.s0.position_m = Vec3(0, 0, 0.1);
  t.s0.velocity_m_s = Vec3(8 * std::cos(0.17), 0, -8 * std::sin(0.17));
  t.s0.orientation = Quat(Eigen::AngleAxisd(-0.26, Vec3::UnitY())) * Quat(Eigen::AngleAxisd(0.12, Vec3::UnitZ()));
  const double spin = 2 * std::numbers::pi * 40;
  set_body_angular_velocity(stone, t.s0, Vec3(0, 0, spin));
  t.exact = exact_first_touch(stone, t.s0, t.s0.orientation * Vec3(0, 0, spin), g);
  return t;
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_first_touch_is_the_vertex_that_crosses_first_at_the_located_time) {
  // Oracle: exact_first_touch (closed-form flight: parabola, rotation at constant ω about the
  // symmetry axis), for a stone without spin (yawed 7° so that one vertex is the lowest) and one
  // spun at 40 rev/s. rk4 in 1e-4 s flight steps integrates the parabola exactly and the rotation
  // to ~1e-9 rad; the touch is located inside a 1e-5 s contact step on the step's Hermite
  // interpolant, which errs less than linear interpolation of the vertex depths, whose error in
  // time is at most a dt²/(8 |ż|), a = g + ω² R the largest vertex
  // acceleration, ż the vertex's vertical speed at the touch; the point then errs by the vertex
  // speed times that, plus a dt²/8 (× 2 for the step's cubic term). The deepest vertex at the end
  // of the first wet step (what a solver that does not interpolate reports) is off by up to
  // |v| dt ≈ 8e-5 m.
  const Stone stone = prism_stone();
  const Environment env = vacuum();
  constexpr double kCubicMargin = 2;
  constexpr double kIntegration_m = 1e-9;  // rk4's attitude error (~1e-9 rad) times R, generously
  for (double spin_rev_s : {0.0, 40.0}) {
    RigidState s0;
    s0.position_m = Vec3(0, 0, 0.1);
    s0.velocity_m_s = Vec3(8 * std::cos(0.17), 0, -8 * std::sin(0.17));
    s0.orientation = Quat(Eigen::AngleAxisd(-0.26, Vec3::UnitY())) * Quat(Eigen::AngleAxisd(0.12, Vec3::UnitZ()));
    const Vec3 omega = s0.orientation * Vec3(0, 0, 2 * std::numbers::pi * spin_rev_s);
    set_body_angular_velocity(stone, s0, Vec3(0, 0, 2 * std::numbers::pi * spin_rev_s));
    const ExactTouch exact = exact_first_touch(stone, s0, omega, env.gravity_m_s2);
    RealtimeOptions o;
    o.scheme = Scheme::rk4;
    o.dt_s = 1e-4;
    o.contact_dt_s = 1e-5;
    o.t_max_s = exact.t_s + 2e-3;
    o.record_trajectory = false;
    const ThrowResult r = run_realtime(stone, env, s0, o);
    BOOST_REQUIRE(!r.contacts.empty());
    const double dt = o.contact_dt_s;
    const double a = env.gravity_m_s2 + omega.squaredNorm() * stone.bounding_radius_m;
    const double bound_t = kCubicMargin * a * dt * dt / (8 * exact.vertex_vertical_speed_m_s);
    const double bound_x = exact.vertex_speed_m_s * bound_t + kCubicMargin * a * dt * dt / 8 + kIntegration_m;
    BOOST_TEST(std::abs(r.contacts[0].start_s - exact.t_s) <= bound_t,
               spin_rev_s << " rev/s: start " << r.contacts[0].start_s << " s, exact " << exact.t_s << " s");
    const double miss = (r.contacts[0].first_touch_m - exact.point_m).norm();
    BOOST_TEST(miss <= bound_x, spin_rev_s << " rev/s: first touch " << miss << " m from the exact point, bound "
                                           << bound_x << " m");
  }
}

BOOST_AUTO_TEST_CASE(the_first_touch_time_converges_at_the_scheme_s_order) {
  // Oracle: exact_first_touch (closed-form flight) for the stone spun at 40 rev/s about its tilted
  // symmetry axis. The touch is located on the step's cubic Hermite interpolant (O(dt⁴)), so rk4 in
  // uniform steps dt must show its own order 4 in the touch time (the rotation is the only part it
  // does not integrate exactly); linear interpolation of the depths would show 2. The observed
  // order between successive halvings, log2(e(dt)/e(dt/2)), must be within kOrderSlack of 4. The
  // steps are dt = t_touch / (N + ½), so that the touch lies mid-step at every N: the
  // interpolant's error constant depends on where in its step the event falls.
  constexpr double kOrderSlack = 0.5;
  const Stone stone = prism_stone();
  const Environment env = vacuum();
  const auto [s0, exact] = spun_tilted_throw(stone, env.gravity_m_s2);
  std::vector<double> errors, steps;
  for (int n : {32, 64, 128, 256}) {
    const double dt = exact.t_s / (n + 0.5);
    steps.push_back(dt);
    RealtimeOptions o;
    o.scheme = Scheme::rk4;
    o.dt_s = o.contact_dt_s = dt;
    o.t_max_s = exact.t_s + 2e-3;
    o.record_trajectory = false;
    const ThrowResult r = run_realtime(stone, env, s0, o);
    BOOST_REQUIRE(!r.contacts.empty());
    errors.push_back(std::abs(r.contacts[0].start_s - exact.t_s));
  }
  for (std::size_t i = 0; i + 1 < errors.size(); ++i) {
    const double order = std::log2(errors[i] / errors[i + 1]);
    BOOST_TEST(std::abs(order - 4) <= kOrderSlack, "dt " << steps[i] << " → " << steps[i + 1] << ": errors "
                                                        << errors[i] << ", " << errors[i + 1] << " s, order " << order);
  }
}

BOOST_AUTO_TEST_CASE(the_adaptive_stepper_locates_the_first_touch_to_its_tolerance) {
  // Oracle: exact_first_touch as above. Each pair (bs32, dp54) with rtol = atol_m = tol keeps the
  // position error per unit time near tol, so the touch time errs by about tol × t / (the vertex's
  // vertical speed, ~1.4 m/s here): at most 10 tol (a margin of ~100 over that estimate) at every
  // tolerance, and every step of the flight is far longer than the fixed schemes' 10 µs contact
  // step. dp54, of order 5, must take fewer steps than bs32 at 1e-8 (at 1e-4 and 1e-6 both take
  // the 78 steps that the flight's dip limit allows, whatever the tolerance).
  constexpr double kTimePerTolerance_s = 10;  // seconds of touch-time error per unit tolerance
  const Stone stone = prism_stone();
  const Environment env = vacuum();
  const auto [s0, exact] = spun_tilted_throw(stone, env.gravity_m_s2);
  for (double tol : {1e-4, 1e-6, 1e-8}) {
    long steps[2] = {0, 0};
    for (Scheme scheme : {Scheme::bs32, Scheme::dp54}) {
      RealtimeOptions o;
      o.scheme = scheme;
      o.rtol = o.atol_m = tol;
      o.t_max_s = exact.t_s + 1e-4;
      o.record_trajectory = false;
      const ThrowResult r = run_realtime(stone, env, s0, o);
      BOOST_REQUIRE(!r.contacts.empty());
      const double e = std::abs(r.contacts[0].start_s - exact.t_s);
      BOOST_TEST(e <= kTimePerTolerance_s * tol,
                 to_string(scheme) << " tol " << tol << ": touch error " << e << " s in " << r.stats.steps << " steps");
      BOOST_TEST(exact.t_s / r.stats.steps > 1e-5, to_string(scheme) << " tol " << tol << ": " << r.stats.steps << " steps");
      steps[scheme == Scheme::dp54] = r.stats.steps;
    }
    if (tol <= 1e-8) BOOST_TEST(steps[1] < steps[0], "tol " << tol << ": dp54 " << steps[1] << " steps, bs32 " << steps[0]);
  }
}

BOOST_AUTO_TEST_CASE(contacts_that_the_water_starts_and_ends_are_logged_when_the_water_moves) {
  // Oracle: a stone at rest with no gravity (nothing moves it: u = 0 on every face) under a flat
  // surface that a before_step callback raises and lowers, as a scene moves its height field
  // between stone steps. The surface is piecewise constant in time: it changes at the first step
  // that starts at or after each of its jump times, so the contacts must start and end exactly
  // there: the level rises over the bottom face at 50.55 ms (first step start 51 ms: flight steps
  // of 1 ms), falls back at 80.55 ms (first step start 80.6 ms: contact steps of 0.1 ms from 51 ms),
  // and rises over the whole stone at 100.55 ms (100.6 ms: flight steps again from 80.6 ms), where
  // it sinks. Times are sums of steps: 1e-12 s of round-off allowed.
  constexpr double kRoundoff_s = 1e-12;
  const double h = 0.008;
  const Stone s = prism_stone(0.03, h);
  Environment env = vacuum();
  env.gravity_m_s2 = 0;
  RigidState s0;
  s0.position_m = Vec3(0, 0, 0.01);  // bottom face at 6 mm, top at 14 mm
  FlatLevel water;
  auto move_water = [&](double t) { water.level_m = t < 0.05055 ? 0.0 : t < 0.08055 ? 0.008 : t < 0.10055 ? 0.0 : 0.02; };
  RealtimeOptions o;
  o.scheme = Scheme::semi_implicit_euler;  // a fixed-step study (the default is bs32)
  o.dt_s = 1e-3;
  o.contact_dt_s = 1e-4;
  o.t_max_s = 0.2;
  o.output_dt_s = 0;
  const ThrowResult r = run_realtime(s, env, s0, o, &water, move_water);
  BOOST_TEST_INFO("outcome " << to_string(r.outcome) << " at " << r.end_time_s << " s, " << r.contacts.size() << " contacts");
  BOOST_REQUIRE(r.contacts.size() == 2u);
  BOOST_TEST(std::abs(r.contacts[0].start_s - 0.051) <= kRoundoff_s);
  BOOST_TEST(std::abs(r.contacts[0].end_s - 0.0806) <= kRoundoff_s);
  BOOST_TEST(r.contacts[0].bounced);  // the water left the stone: free flight follows
  BOOST_TEST(std::abs(r.contacts[1].start_s - 0.1006) <= kRoundoff_s);
  BOOST_TEST(r.outcome == Outcome::sank);
  BOOST_TEST(r.contacts[1].end_s == r.end_time_s);
  BOOST_TEST(std::abs(r.end_time_s - 0.1006) <= kRoundoff_s);
  // Every sample that is wet lies inside a logged contact.
  for (const auto& p : r.trajectory) {
    if (p.wetted_area_m2 <= 0) continue;
    bool inside = false;
    for (const auto& c : r.contacts) inside = inside || (p.t_s >= c.start_s && p.t_s <= c.end_s);
    BOOST_TEST(inside, "wet sample at t = " << p.t_s << " s outside every contact");
  }
}

BOOST_AUTO_TEST_CASE(the_contact_log_refuses_a_start_while_open_and_an_end_while_closed) {
  // Oracle: model/README.md §1.8 — contacts are disjoint intervals, each started once and ended once. A
  // second start while a contact is open, or an end with none open, is refused and leaves the
  // list as it was.
  ContactLog log;
  RigidState s;
  s.velocity_m_s = Vec3(1, 0, -1);
  BOOST_TEST(log.end(0.5, s, 1.0, true) == ContactLog::Status::refused_end_while_closed);
  BOOST_TEST(log.contacts().empty());
  BOOST_TEST(log.start(1.0, s, Vec3(1, 2, 3), 1.0) == ContactLog::Status::ok);
  BOOST_TEST(log.start(2.0, s, Vec3(4, 5, 6), 1.0) == ContactLog::Status::refused_start_while_open);
  BOOST_TEST(log.contacts().size() == 1u);
  BOOST_TEST(log.contacts()[0].start_s == 1.0);
  BOOST_TEST(log.contacts()[0].first_touch_m == Vec3(1, 2, 3));
  BOOST_TEST(log.end(3.0, s, 1.0, true) == ContactLog::Status::ok);
  BOOST_TEST(log.end(4.0, s, 1.0, false) == ContactLog::Status::refused_end_while_closed);
  BOOST_TEST(log.contacts().size() == 1u);
  BOOST_TEST(log.contacts()[0].end_s == 3.0);
  BOOST_TEST(log.contacts()[0].bounced);
}

BOOST_AUTO_TEST_CASE(the_shortest_flight_is_the_least_gap_between_consecutive_contacts) {
  // Oracle: the definition, on hand-built contact lists. Gaps 0.0005 s and 0.05 s: the shortest
  // is 0.0005 s to round-off of the subtraction (1e-15 s); one contact or none has no flight (+∞).
  std::vector<ContactRecord> c(3);
  c[0].start_s = 0.1;
  c[0].end_s = 0.2;
  c[1].start_s = 0.2005;
  c[1].end_s = 0.3;
  c[2].start_s = 0.35;
  c[2].end_s = 0.4;
  BOOST_TEST(std::abs(shortest_flight_s(c) - 0.0005) < 1e-15);
  c[1].start_s = 0.25;  // now 0.05 and 0.05
  BOOST_TEST(std::abs(shortest_flight_s(c) - 0.05) < 1e-15);
  c.resize(1);
  BOOST_TEST(std::isinf(shortest_flight_s(c)));
  BOOST_TEST(std::isinf(shortest_flight_s({})));
}

BOOST_AUTO_TEST_CASE(cpu_time_is_the_thread_s_own_and_wall_time_includes_waiting) {
  // Oracle: a thread that sleeps uses no CPU. A before_step callback sleeps 50 ms once inside a
  // 10-step flight (microseconds of work): the wall time includes the 50 ms, the CPU time must
  // not (allowed 20 ms: the work itself plus scheduling noise on a loaded machine, still well
  // below the sleep).
  const Stone s = prism_stone();
  RigidState s0;
  s0.position_m = Vec3(0, 0, 10);
  RealtimeOptions o;
  o.scheme = Scheme::semi_implicit_euler;  // a fixed-step study (the default is bs32)
  o.dt_s = 1e-3;
  o.t_max_s = 0.01;
  bool slept = false;
  auto sleep_once = [&](double) {
    if (!slept) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    slept = true;
  };
  const ThrowResult r = run_realtime(s, vacuum(), s0, o, nullptr, sleep_once);
  BOOST_TEST(r.stats.wall_s >= 0.05);
  BOOST_TEST(r.stats.cpu_s <= 0.02, "cpu_s " << r.stats.cpu_s << " s for 10 flight steps and a 50 ms sleep");
}

BOOST_AUTO_TEST_CASE(a_state_that_runs_away_fails_and_a_collapsing_step_gives_up) {
  // Oracle: the physical convention's passivity (model/README.md §1.6: every face's power is −C ρ
  // u³ S ≤ 0, the air's too), so the energy never exceeds the release energy. A budget of 4
  // right-hand sides per 0.5 s frame forces a 0.5 s step through the first contact, which gives
  // the stone ~1e9 J: the run must fail saying so, not end as a throw that sank.
  const Stone stone = prism_stone();
  Environment env;
  set_default_water_model(env);
  ThrowParameters p;
  p.speed_m_s = 8;
  p.path_angle_deg = 10;
  p.attack_angle_deg = 10;
  p.spin_rev_s = 10;
  p.height_m = 0.05;
  RealtimeOptions o;
  o.record_trajectory = false;
  o.t_max_s = 2;
  o.rhs_per_frame = 4;
  o.frame_dt_s = 0.5;
  const ThrowResult forced = run_realtime(stone, env, initial_state(stone, p), o);
  BOOST_TEST(forced.outcome == Outcome::failed);
  BOOST_TEST(forced.outcome_detail.find("ran away") != std::string::npos, forced.outcome_detail);
  // A plate 2 m across of density 1 kg/m³ (mass 25 g) meets forces that a 30 g stone of 6 cm
  // meets: the contact is far too stiff for an explicit scheme at 1e-9, whose steps collapse to
  // nanoseconds. The run must give up at the guard (20 000 steps in less than 1 ms), within a
  // bounded work, instead of spinning for minutes.
  const Stone plate = prism_stone(1.0, 0.008, 11, 1.0);
  o.rhs_per_frame = 0;
  const ThrowResult stiff = run_realtime(plate, env, initial_state(plate, p), o);
  BOOST_TEST(stiff.outcome == Outcome::failed);
  BOOST_TEST(stiff.outcome_detail.find("collapsed") != std::string::npos, stiff.outcome_detail);
  BOOST_TEST(stiff.stats.steps <= 2 * o.max_steps_per_ms + 100000);  // the guard's windows, and what led to them
}

BOOST_AUTO_TEST_SUITE_END()
