// Oracle: the water loads as the straightforward implementation computed them (every face clipped
// for the law's total, clipped again and integrated for the distributed pressure), stored below to
// 17 digits for 200 random states near the water (5 environments × 40 states, the paper's
// 44-triangle prism). The optimised loads must equal them to round-off: kRelative, a few thousand
// ulps of the largest of force, torque × 1/r and area scale, since sums of 44 faces are reordered.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>
#include <algorithm>

#include "model/stone/fluid_forces.hpp"
#include "model/stone/mass_properties.hpp"
#include "model/stone/portable_uniform.hpp"
#include "model/stone/pressure_distribution.hpp"
#include "model/stone/stone.hpp"

using namespace stoneskip;

namespace {

constexpr double kRelative = 1e-12;  // reordered sums of ≤ 44 faces, weights integrated in closed form
constexpr int kStatesPerEnvironment = 40;

Stone prism() {
  const Mesh m = make_prism(0.03, 0.008, 11);
  return make_stone(m, mass_properties_from_density(m, 2500), 0.03, "prism");
}

Environment environment(int k) {
  Environment e;
  switch (k) {
    case 0: break;  // newtonian, uniform
    case 1: set_water_law(e, WaterLaw::planing); break;
    case 2: set_water_law(e, WaterLaw::planing); e.pressure_distribution = PressureDistribution::savitsky; break;
    case 3: set_water_law(e, WaterLaw::planing); e.pressure_distribution = PressureDistribution::savitsky_wagner; break;
    default: e.convention = Convention::paper; break;
  }
  return e;
}

// One draw a statement, last component first: the order in which a call's arguments are evaluated
// is unspecified (GCC, which made the table, evaluates them right to left; clang left to right, and
// a clang build compared other states with the table and failed by O(1)).
Vec3 random_vec(PortableUniform& u, double xy, double z) {
  const double c = u(-z, z), b = u(-xy, xy), a = u(-xy, xy);
  return Vec3(a, b, c);
}
RigidState random_state(PortableUniform& u) {
  RigidState s;
  s.position_m = random_vec(u, 0.1, 0.02);
  const double qz = u(-1, 1), qy = u(-1, 1), qx = u(-1, 1), qw = u(-1, 1);
  s.orientation = Quat(qw, qx, qy, qz).normalized();
  s.velocity_m_s = random_vec(u, 8, 3);
  s.angular_momentum_kg_m2_s = random_vec(u, 2e-3, 1e-2);
  return s;
}

// force (3), torque (3), wetted area, wet triangles, submerged vertices, pushes, Σ push force · (1,1,1).
constexpr int kValues = 11;
void values(const WaterLoads& w, const std::vector<FacePush>& pushes, double* out) {
  for (int i = 0; i < 3; ++i) out[i] = w.force_N[i], out[3 + i] = w.torque_N_m[i];
  out[6] = w.wetted_area_m2;
  out[7] = w.wet_triangles;
  out[8] = w.submerged_vertices;
  out[9] = static_cast<double>(pushes.size());
  double sum = 0;
  for (const FacePush& p : pushes) sum += p.force_N.sum();
  out[10] = sum;
}

#include "model/stone/fluid_forces_golden_values.inc"

// Whether, in still water, the Wagner rise's raised waterline cuts a face off the stone's underside
// (some vertex above the surface and at or under the raised waterline): the loads of such a state
// changed when the rise was confined to the underside.
bool rise_wets_off_underside(const Stone& stone, const RigidState& s) {
  const Mat3 R = s.orientation.normalized().toRotationMatrix();
  const auto& v = stone.body_mesh.vertices;
  std::vector<double> d(v.size());
  double deepest = -1e300;
  for (std::size_t k = 0; k < v.size(); ++k) deepest = std::max(deepest, d[k] = -(s.position_m + R * v[k]).z());
  const double rise = waterline_rise_m(PressureDistribution::savitsky_wagner, deepest);
  const int side = underside_side(R);
  for (std::size_t i = 0; i < stone.body_mesh.triangles.size(); ++i) {
    if (on_underside(stone.face_normals_body[i], side)) continue;
    for (int k : stone.body_mesh.triangles[i])
      if (d[k] < 0 && d[k] + rise >= 0) return true;
  }
  return false;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(fluid_forces_golden)

BOOST_AUTO_TEST_CASE(the_loads_equal_the_straightforward_implementation_s_to_round_off) {
  const Stone stone = prism();
  const bool print = std::getenv("STONESKIP_PRINT_GOLDEN") != nullptr;  // regenerates the table
  int row = 0, compared = 0, below_planing_speed = 0, off_underside = 0;
  for (int e = 0; e < 5; ++e) {
    const Environment env = environment(e);
    PortableUniform u{static_cast<std::uint64_t>(1000 + e)};
    for (int k = 0; k < kStatesPerEnvironment; ++k, ++row) {
      const RigidState s = random_state(u);
      std::vector<FacePush> pushes;
      const WaterLoads w = water_loads(stone, env, s, nullptr, &pushes);
      double v[kValues];
      values(w, pushes, v);
      if (print) {
        std::printf("    {");
        for (int i = 0; i < kValues; ++i) std::printf("%.17g%s", v[i], i + 1 < kValues ? ", " : "},\n");
        continue;
      }
      // Below planing speed (C_v < 1) a distributed pressure is blended with the uniform one since
      // the table was made (pressure_distribution.hpp, planing_share; tested in
      // pressure_distribution_test.cpp): the table holds the unblended loads, so those rows are
      // not compared.
      if (env.pressure_distribution != PressureDistribution::uniform &&
          planing_share(s.velocity_m_s, env.gravity_m_s2, 2 * stone.disk_radius_m) < 1) {
        ++below_planing_speed;
        continue;
      }
      // Since the table was made the Wagner rise wets the underside only (on_underside,
      // pressure_distribution.hpp; tested in fluid_forces_test.cpp): a state where the raised
      // waterline cuts a face off the underside had other loads then, and is not compared.
      if (env.pressure_distribution == PressureDistribution::savitsky_wagner && rise_wets_off_underside(stone, s)) {
        ++off_underside;
        continue;
      }
      const double* g = kGolden[row];
      const double force_scale = std::max(1e-300, std::abs(g[0]) + std::abs(g[1]) + std::abs(g[2]));
      const double torque_scale = std::max(1e-300, std::abs(g[3]) + std::abs(g[4]) + std::abs(g[5]));
      for (int i = 0; i < 3; ++i) {
        BOOST_TEST(std::abs(v[i] - g[i]) <= kRelative * force_scale, "row " << row << " force " << i << ": " << v[i] << " vs " << g[i]);
        BOOST_TEST(std::abs(v[3 + i] - g[3 + i]) <= kRelative * torque_scale,
                   "row " << row << " torque " << i << ": " << v[3 + i] << " vs " << g[3 + i]);
      }
      BOOST_TEST(std::abs(v[6] - g[6]) <= kRelative * std::abs(g[6]), "row " << row);
      for (int i = 7; i <= 9; ++i) BOOST_TEST(v[i] == g[i], "row " << row << " count " << i);
      BOOST_TEST(std::abs(v[10] - g[10]) <= kRelative * (force_scale + std::abs(g[10])), "row " << row);
      if (g[0] != 0 || g[2] != 0) ++compared;
    }
  }
  if (print) return;
  // The table must exercise the contact: most states are wet. Horizontal speeds are uniform on
  // [−8, 8]² m/s, so few fall below the 3 cm prism's √(g · 6 cm) = 0.77 m/s (2 of 80 distributed).
  BOOST_TEST(compared >= 100);
  BOOST_TEST(below_planing_speed <= 4);
  BOOST_TEST_MESSAGE("savitsky_wagner rows not compared (rise off the underside): " << off_underside);
  // Random attitudes put the prism's rim in the raised band in 38 of the 40 Wagner rows: those loads
  // are checked against the rule itself in fluid_forces_test.cpp (each face's polygon, K, Σ F_i).
}

BOOST_AUTO_TEST_SUITE_END()
