// Per-component absolute tolerances (solvers/reference/absolute_tolerance.hpp) against the
// closed forms of a regular N-gon prism (model/README.md §1.2): ℓ = √(R² + h²/4), I_min = I_xx =
// m (R² (1 + 2 cos²(π/N))/12 + h²/12), V = |v₀| + |ω₀| ℓ (or √(g ℓ)).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>

#include "model/stone/throw.hpp"
#include "solvers/reference/absolute_tolerance.hpp"

using namespace stoneskip;

namespace {
// Mass properties are sums of O(N) terms: a few hundred ulps (as in mesh_test).
constexpr double kRelative = 1e-12;
}  // namespace

BOOST_AUTO_TEST_SUITE(absolute_tolerance)

BOOST_AUTO_TEST_CASE(each_component_gets_the_tolerance_that_moves_the_rim_by_atol) {
  // Oracle: the closed forms above, and the header's rules: x: atol; v: atol V/ℓ; q: atol/ℓ;
  // L: atol I_min V/ℓ². Clanet's aluminium disk (R 2.5 cm, h 2.75 mm, N = 32) at 3.5 m/s, 65 rev/s.
  const double R = 0.025, h = 0.00275, rho = 2700;
  const int N = 32;
  const Mesh m = make_prism(R, h, N);
  const Stone stone = make_stone(m, mass_properties_from_density(m, rho), 0, "disk");
  ThrowParameters p;
  p.speed_m_s = 3.5;
  p.path_angle_deg = 20;
  p.attack_angle_deg = 20;
  p.spin_rev_s = 65;
  const RigidState s0 = initial_state(stone, p);
  const double mass = rho * 0.5 * N * R * R * std::sin(2 * std::numbers::pi / N) * h;
  const double c = std::cos(std::numbers::pi / N);
  const double i_min = mass * (R * R * (1 + 2 * c * c) / 12 + h * h / 12);
  const double ell = std::sqrt(R * R + h * h / 4);
  const double V = 3.5 + 2 * std::numbers::pi * 65 * ell;
  const StateScales sc = state_scales(stone, s0, 9.81);
  BOOST_TEST(std::abs(sc.length_m - ell) <= kRelative * ell);
  BOOST_TEST(std::abs(sc.speed_m_s - V) <= kRelative * V);
  BOOST_TEST(std::abs(sc.angular_momentum_kg_m2_s - i_min * V / ell) <= kRelative * i_min * V / ell);
  ReferenceOptions o;
  o.atol = 1e-9;
  const StateVector a = absolute_tolerances(o, sc);
  for (int k = 0; k < 3; ++k) {
    BOOST_TEST(a[kPosition + k] == 1e-9);
    BOOST_TEST(std::abs(a[kVelocity + k] - 1e-9 * V / ell) <= kRelative * 1e-9 * V / ell);
    BOOST_TEST(std::abs(a[kAngularMomentum + k] - 1e-9 * i_min * V / (ell * ell)) <= kRelative * 1e-9 * i_min * V / (ell * ell));
  }
  for (int k = 0; k < 4; ++k) BOOST_TEST(std::abs(a[kQuaternion + k] - 1e-9 / ell) <= kRelative * 1e-9 / ell);
  // Relative to this throw's own angular momentum (1.9e-3 kg m²/s), L's tolerance asks for the
  // accuracy positions get relative to the stone's size (within 3×); a uniform 1e-9 would be 20×
  // looser on L than on x.
  const double relative_L = a[kAngularMomentum] / s0.angular_momentum_kg_m2_s.norm(), relative_x = o.atol / ell;
  BOOST_TEST(relative_L <= 3 * relative_x);
  BOOST_TEST(relative_L >= relative_x / 3);
  BOOST_TEST(o.atol / s0.angular_momentum_kg_m2_s.norm() > 10 * relative_x);
  o.atol_scaling = ToleranceScaling::uniform;
  for (double t : absolute_tolerances(o, sc)) BOOST_TEST(t == 1e-9);
}

BOOST_AUTO_TEST_CASE(a_stone_dropped_from_rest_takes_its_speed_from_gravity) {
  // Oracle: V = √(g ℓ) for a stone at rest (spin-free, still); ℓ per second without gravity.
  const Mesh m = make_prism(0.03, 0.006, 11);
  const Stone stone = make_stone(m, mass_properties_from_density(m, 2500), 0, "prism");
  const RigidState rest;
  const double ell = stone.bounding_radius_m;
  BOOST_TEST(std::abs(state_scales(stone, rest, 9.81).speed_m_s - std::sqrt(9.81 * ell)) <= kRelative);
  BOOST_TEST(state_scales(stone, rest, 0.0).speed_m_s == ell);
}

BOOST_AUTO_TEST_SUITE_END()
