// Where the water's pressure acts (model/stone/pressure_distribution.hpp): the weighted integrals
// against closed forms and a refinement that converges to them, and the centre of pressure of a
// planing plate against Savitsky's fraction of the (Wagner-lengthened) wetted length.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "model/stone/fluid_forces.hpp"
#include "model/stone/mass_properties.hpp"
#include "model/stone/pressure_distribution.hpp"
#include "model/stone/stone.hpp"

using namespace stoneskip;

namespace {

// A few hundred ulps of a unit quantity: sums of a handful of products.
constexpr double kRoundoff = 1e-13;
constexpr double kDeg = std::numbers::pi / 180;

ClippedPolygon triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  ClippedPolygon p;
  p.vertices[0] = a;
  p.vertices[1] = b;
  p.vertices[2] = c;
  p.count = 3;
  return p;
}

// ∫ w dA and ∫ w x dA by the midpoint rule on 4^level congruent sub-triangles: an independent
// computation, second order in the sub-triangle size.
WeightedIntegrals midpoint_refined(const Vec3& a, const Vec3& b, const Vec3& c, const WettedSpan& span, double k,
                                   int level) {
  WeightedIntegrals out;
  const int n = 1 << level;
  const Vec3 e1 = (b - a) / n, e2 = (c - a) / n;
  const double area = 0.5 * e1.cross(e2).norm();
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j) {
      for (int up = 0; up < 2 && (up == 0 || i + j + 1 < n); ++up) {
        const Vec3 x = up == 0 ? Vec3(a + (i + 1.0 / 3) * e1 + (j + 1.0 / 3) * e2)
                               : Vec3(a + (i + 2.0 / 3) * e1 + (j + 2.0 / 3) * e2);
        const double w = (k + 1) * std::pow(std::max(span.xi(x), 0.0), k) * area;
        out.weight_m2 += w;
        out.moment_m3 += w * x;
      }
    }
  return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(pressure_distribution)

BOOST_AUTO_TEST_CASE(savitskys_fraction_gives_the_quadratic_weight) {
  // Oracle: the centroid of (k + 1) ξ^k on [0, 1] is (k + 1)/(k + 2); 3/4 ⇔ k = 2 exactly.
  BOOST_TEST(power_weight_exponent(kSavitskyCentreFraction) == 2.0);
  BOOST_TEST(power_weight_exponent(0.5) == 0.0);  // uniform weight: the centroid at half the length
}

BOOST_AUTO_TEST_CASE(the_weighted_integrals_match_the_closed_form_and_a_refinement_that_converges_to_them) {
  // Oracle 1: for ξ linear on a triangle of area A with vertex values a, b, c,
  //   ∫ 3ξ² dA = 3 A (a² + b² + c² + ab + bc + ca)/6   (exact integration of a quadratic).
  // Oracle 2: the midpoint rule on 4^L sub-triangles, an independent computation whose error falls
  //   as 4^−L (second order in h): the integrals are exact for w x (degree 3: the closed form for
  //   k = 2, the 7-point rule otherwise), so the refinement's error must fall by ≈ 4 per level
  //   towards them. Tolerance: round-off for the closed form. (That the closed form equals the
  //   7-point rule it replaced is fluid_forces_golden_test.cpp's oracle.)
  const Vec3 p0(0.01, -0.02, 0.003), p1(0.05, 0.01, -0.002), p2(-0.01, 0.03, 0.001);
  WettedSpanBuilder b(Vec3(3, 1, -1));
  const ClippedPolygon poly = triangle(p0, p1, p2);
  b.add(poly);
  const WettedSpan span = b.span();
  BOOST_REQUIRE(span.valid());
  const WeightedIntegrals exact = integrate_weight(poly, span, 2.0);
  const double A = 0.5 * (p1 - p0).cross(p2 - p0).norm();
  const double a = span.xi(p0), bb = span.xi(p1), c = span.xi(p2);
  const double closed = 3 * A * (a * a + bb * bb + c * c + a * bb + bb * c + c * a) / 6;
  BOOST_TEST(std::abs(exact.weight_m2 - closed) <= kRoundoff * closed);
  double previous = 0;
  for (int level = 2; level <= 6; ++level) {
    const WeightedIntegrals m = midpoint_refined(p0, p1, p2, span, 2.0, level);
    const double err = (m.moment_m3 - exact.moment_m3).norm() / exact.moment_m3.norm();
    if (level > 2) BOOST_TEST(err < previous / 3.5, "level " << level << ": " << err << " after " << previous);
    previous = err;
  }
  BOOST_TEST(previous < 1e-3);  // O(h²) with h = 1/64 of the triangle: ~(1/64)² of the moment's variation
}

BOOST_AUTO_TEST_CASE(a_planing_plate_is_pushed_at_savitskys_fraction_of_its_wagner_lengthened_wetted_length) {
  // Oracle: a square plate (side a, its edges along x and y before the tilt) planing at attack α, path angle β, trailing edge D deep, no
  // spin: its wet bottom is a rectangle of length l = D / sin α from the trailing edge, and only
  // the bottom is loaded (the trailing rim and the top recede, the side rims slide). The centre of
  // pressure, from the torque about the centre of mass, lies l/2 (uniform), ¾ l (savitsky) and
  // ¾ (π/2) l (savitsky_wagner) ahead of the trailing edge, and the total force is the law's, the
  // same for all three. Tolerance: round-off relative to the plate's size and the force.
  const double R = 0.05, h = 0.004, a = R * std::sqrt(2.0), alpha = 20 * kDeg, beta = 20 * kDeg, D = 0.003;
  const Mesh mesh = make_prism(R, h, 4);
  const Stone s = make_stone(mesh, mass_properties_from_density(mesh, 2500), R, "square plate");
  RigidState st;
  st.orientation = Quat(Eigen::AngleAxisd(-alpha, Vec3::UnitY()) * Eigen::AngleAxisd(std::numbers::pi / 4, Vec3::UnitZ()));
  const Vec3 e2 = Vec3::UnitY(), nz = st.orientation * Vec3::UnitZ();
  st.position_m = Vec3(0, 0, -D + 0.5 * a * std::sin(alpha) + 0.5 * h * std::cos(alpha));
  st.velocity_m_s = 3.5 * Vec3(std::cos(beta), 0, -std::sin(beta));
  const double l = D / std::sin(alpha);
  BOOST_REQUIRE(std::numbers::pi / 2 * l < a);  // the lengthened region stays on the plate
  Environment env;
  set_water_law(env, WaterLaw::planing);
  const struct {
    PressureDistribution d;
    double fraction;
  } cases[] = {{PressureDistribution::uniform, 0.5},
               {PressureDistribution::savitsky, 0.75},
               {PressureDistribution::savitsky_wagner, 0.75 * std::numbers::pi / 2}};
  Vec3 uniform_force = Vec3::Zero();
  for (const auto& c : cases) {
    BOOST_TEST_CONTEXT(to_string(c.d)) {
      env.pressure_distribution = c.d;
      const WaterLoads w = water_loads(s, env, st);
      const double f = w.force_N.norm();
      BOOST_REQUIRE(f > 0);
      BOOST_TEST((w.force_N.normalized() - nz).norm() <= kRoundoff);  // against the bottom's outward normal −n
      if (c.d == PressureDistribution::uniform) uniform_force = w.force_N;
      BOOST_TEST((w.force_N - uniform_force).norm() <= kRoundoff * f);
      // τ = r × F with F = f n: the lever arm along e1 is −τ·e2 / f (e1 × n = −e2).
      const double ahead_of_trailing_edge = -w.torque_N_m.dot(e2) / f + 0.5 * a;
      BOOST_TEST(std::abs(ahead_of_trailing_edge - c.fraction * l) <= 1e-11,
                 ahead_of_trailing_edge << " m vs " << c.fraction * l << " m");
    }
  }
}

BOOST_AUTO_TEST_CASE(below_planing_speed_the_pressure_blends_towards_uniform) {
  // Oracle: the planing plate above, slower. With w_β = (1 − β) + β · 3ξ² over its wet rectangle
  // (no spin: one velocity for the whole plate, so one pressure), the centre of pressure lies
  // (½ + ¼ β) of the (Wagner-lengthened) wetted length ahead of the trailing edge, with
  // β = min(1, |v_h| / √(g b)) and b = 2R the disk's diameter (planing_share); the total force is
  // still the law's. The uniform law's ½ is the limit β → 0: the direction v_h/|v_h|, which flips
  // as v_h passes through zero, then no longer matters. Tolerance: round-off of the plate's size.
  const double R = 0.05, h = 0.004, a = R * std::sqrt(2.0), alpha = 20 * kDeg, path = 20 * kDeg, D = 0.003;
  const Mesh mesh = make_prism(R, h, 4);
  const Stone s = make_stone(mesh, mass_properties_from_density(mesh, 2500), R, "square plate");
  Environment env;
  set_water_law(env, WaterLaw::planing);
  env.pressure_distribution = PressureDistribution::savitsky_wagner;
  const double l = D / std::sin(alpha), lengthened = std::numbers::pi / 2 * l;
  const double planing_speed = std::sqrt(env.gravity_m_s2 * 2 * R);  // C_v = 1
  // Speeds along the path, the last below the micrometre per second under which the span has no
  // direction (WettedSpanBuilder): there the weight is the uniform one, β = 0.
  const Vec3 along(std::cos(path), 0, -std::sin(path));
  const std::vector<Vec3> velocities = {Vec3(2 * planing_speed / std::cos(path) * along), Vec3(0.5 * along),
                                        Vec3(0.05 * along), Vec3(1e-5 * along), Vec3(1e-7 * along)};
  for (const Vec3& v : velocities) {
    BOOST_TEST_CONTEXT("velocity " << v.transpose() << " m/s") {
      RigidState st;
      st.orientation = Quat(Eigen::AngleAxisd(-alpha, Vec3::UnitY()) * Eigen::AngleAxisd(std::numbers::pi / 4, Vec3::UnitZ()));
      st.position_m = Vec3(0, 0, -D + 0.5 * a * std::sin(alpha) + 0.5 * h * std::cos(alpha));
      st.velocity_m_s = v;
      const double vh = std::abs(v.x());
      const double beta = vh > 1e-6 ? std::min(1.0, vh / planing_speed) : 0;
      if (vh > 1e-6) BOOST_TEST(planing_share(st.velocity_m_s, env.gravity_m_s2, 2 * R) == beta, boost::test_tools::tolerance(1e-15));
      const WaterLoads w = water_loads(s, env, st);
      Environment uniform = env;
      uniform.pressure_distribution = PressureDistribution::uniform;
      const double f = w.force_N.norm(), f_law = water_loads(s, uniform, st).force_N.norm();
      BOOST_REQUIRE(f > 0);
      BOOST_TEST(std::abs(f - f_law) <= kRoundoff * f_law);
      const double ahead_of_trailing_edge = -w.torque_N_m.dot(Vec3::UnitY()) / f + 0.5 * a;
      const double expected = (0.5 + 0.25 * beta) * lengthened;
      BOOST_TEST(std::abs(ahead_of_trailing_edge - expected) <= 1e-11, ahead_of_trailing_edge << " m vs " << expected << " m");
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
