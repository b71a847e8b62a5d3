// The pressure head of model/coupling/pressure_head.hpp: conservative rasterisation of the faces'
// pushes (model/README.md §2.4, pressure coupling).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <array>
#include <numeric>

#include "model/coupling/pressure_head.hpp"
#include "model/stone/mass_properties.hpp"
#include "model/stone/portable_uniform.hpp"
#include "model/stone/stone.hpp"

namespace stoneskip {
namespace {

// Round-off of Σ over faces and cells (≈ 100 terms) of overlaps computed from cell-unit
// coordinates of a few cells, relative to Σ_i |F_z,i| (faces may push both ways).
constexpr double kSumRoundoff = 1e-12;

Stone seed_prism() {
  const Mesh m = make_prism(0.03, 0.008, 11);
  return make_stone(m, mass_properties_from_density(m, 2500), 0.03, "seed prism");
}

BOOST_AUTO_TEST_SUITE(pressure_head)

BOOST_AUTO_TEST_CASE(a_square_overlapping_four_cells_gives_each_its_quarter) {
  // Oracle: geometry. A unit square centred on the corner shared by cells (0,0), (1,0), (0,1),
  // (1,1) (cell units) covers a quarter of each; a triangle inside one cell covers its own area.
  const double x[4] = {0, 1, 1, 0}, y[4] = {0, 0, 1, 1};
  for (int i = 0; i <= 1; ++i)
    for (int j = 0; j <= 1; ++j) BOOST_TEST(std::abs(overlap_with_cell(x, y, 4, i, j) - 0.25) <= 1e-15);
  BOOST_TEST(overlap_with_cell(x, y, 4, 2, 0) == 0.0);
  const double tx[3] = {-0.2, 0.3, 0.1}, ty[3] = {-0.1, -0.2, 0.4};  // clockwise or not: |area|
  const double area = 0.5 * std::abs((tx[1] - tx[0]) * (ty[2] - ty[0]) - (tx[2] - tx[0]) * (ty[1] - ty[0]));
  BOOST_TEST(std::abs(overlap_with_cell(tx, ty, 3, 0, 0) - area) <= 1e-15);
}

BOOST_AUTO_TEST_CASE(the_grid_receives_the_stones_vertical_force_wherever_the_stone_lies) {
  // Oracle: the stone's own vertical water force (model/stone/fluid_forces.hpp), per convention
  // and law; Σ h ρ g d² must equal it to round-off for random poses and grid offsets, because
  // the cell overlaps of each face sum to its projected area (conservation), and Σ F_i of the
  // pushes is the force itself.
  const Stone stone = seed_prism();
  PortableUniform rng{7};
  // One draw a statement (a call's arguments are evaluated in an unspecified order): u[0..11].
  auto draws = [&] {
    std::array<double, 12> u;
    for (double& x : u) x = rng(0, 1);
    return u;
  };
  for (int variant = 0; variant < 3; ++variant) {
    Environment env;
    if (variant == 0) set_convention(env, Convention::paper);
    if (variant == 1) set_default_water_model(env);  // planing, savitsky_wagner
    std::vector<FacePush> pushes;
    DraughtPatch patch;
    for (int trial = 0; trial < 40; ++trial) {
      const std::array<double, 12> u = draws();
      RigidState s;
      s.position_m = Vec3(u[0], u[1], 0.002 - 0.004 * u[2]);
      s.velocity_m_s = Vec3(6 + 4 * u[3], u[4] - 0.5, -0.5 - u[5]);
      s.orientation = Quat(Eigen::AngleAxisd(0.3 * u[6], Vec3(u[7] - 0.5, u[8] - 0.5, 0.1).normalized()));
      s.angular_momentum_kg_m2_s = Vec3(0, 0, 1e-4 * u[9]);
      const WaterLoads w = water_loads(stone, env, s, nullptr, &pushes);
      const FieldPlacement at{-0.02 * u[10], -0.02 * u[11]};
      const PressureHeadSummary h = rasterise_pressure_head(pushes, 0.02, at, 1000 * 9.81, patch);
      if (!w.in_contact()) continue;
      double scale = 1e-300;
      for (const FacePush& p : pushes) scale += std::abs(p.force_N.z());
      BOOST_TEST(std::abs(h.force_N - w.force_N.z()) <= kSumRoundoff * scale);
      BOOST_TEST(std::abs(h.rastered_N - w.force_N.z()) <= kSumRoundoff * scale);
      Vec3 sum = Vec3::Zero();
      for (const FacePush& p : pushes) sum += p.force_N;
      BOOST_TEST((sum - w.force_N).norm() <= kSumRoundoff * w.force_N.norm());
    }
  }
}

BOOST_AUTO_TEST_CASE(a_stone_lying_on_the_grid_spreads_over_the_cells_it_covers) {
  // Oracle: uniform pressure p on a flat bottom of area S seen from a cell-aligned grid: every
  // fully covered cell receives p/(ρ g), and the head never exceeds it (conservative, no
  // point-sampling overshoot); the bottom's projection is exactly the area where h > 0 weighted
  // by the covered fraction.
  const Stone stone = seed_prism();
  Environment env;  // Newtonian, uniform: each face's pressure C_w ρ u²
  RigidState s;
  s.position_m = Vec3(0.0031, 0.0017, 0.004 - 1e-4);  // bottom face just under still water
  s.velocity_m_s = Vec3(0, 0, -2.0);
  std::vector<FacePush> pushes;
  water_loads(stone, env, s, nullptr, &pushes);
  DraughtPatch patch;
  const double rho_g = 1000 * 9.81, d = 0.005;
  rasterise_pressure_head(pushes, d, FieldPlacement{}, rho_g, patch);
  const double p = 1000 * 4.0, full = p / rho_g;
  double largest = 0;
  int full_cells = 0;
  for (double h : patch.b_m) {
    largest = std::max(largest, h);
    if (std::abs(h - full) <= 1e-12 * full) ++full_cells;
  }
  BOOST_TEST(largest <= full * (1 + 1e-12));
  BOOST_TEST(full_cells >= 80);  // the ≈ 110 cells of 5 mm inside a 3 cm disk, less its rim
}

BOOST_AUTO_TEST_CASE(a_head_spilt_past_a_wall_is_reflected_onto_the_grid_and_dropped_when_asked) {
  // Oracle: the reflecting wall's ghost rule worked by hand on a 3 × 2 grid. A 5 × 4 box from
  // (−1, −1) with value 1 + a + 10 c at box point (a, c): column −1 lands on column 0, column 3 on
  // column 2 (2·3 − 1 − 3), row −1 on row 0 and row 2 on row 1 (2·2 − 1 − 2); the sum is kept
  // exactly (small integers). Dropping keeps the 3 × 2 inside only.
  auto box = [] {
    DraughtPatch p;
    p.reset(-1, -1, 5, 4);
    for (int c = 0; c < 4; ++c)
      for (int a = 0; a < 5; ++a) p.at(a, c) = 1 + a + 10 * c;
    return p;
  };
  std::vector<double> scratch;
  DraughtPatch folded = box();
  const double total = std::accumulate(folded.b_m.begin(), folded.b_m.end(), 0.0);
  fold_onto_walled_grid(folded, 3, 2, scratch);
  BOOST_TEST((folded.i0 == 0 && folded.j0 == 0 && folded.ni == 3 && folded.nj == 2));
  BOOST_TEST(std::accumulate(folded.b_m.begin(), folded.b_m.end(), 0.0) == total);
  // Grid point (0, 0) receives box points with i ∈ {−1, 0} (a = 0, 1) and j ∈ {−1, 0} (c = 0, 1).
  double expect00 = 0;
  for (int a : {0, 1})
    for (int c : {0, 1}) expect00 += 1 + a + 10 * c;
  BOOST_TEST(folded.at(0, 0) == expect00);
  // Grid point (2, 1) receives i ∈ {2, 3} (a = 3, 4) and j ∈ {1, 2} (c = 2, 3).
  double expect21 = 0;
  for (int a : {3, 4})
    for (int c : {2, 3}) expect21 += 1 + a + 10 * c;
  BOOST_TEST(folded.at(2, 1) == expect21);

  DraughtPatch dropped = box();
  drop_beyond_rim(dropped, 3, 2, scratch);
  BOOST_TEST((dropped.i0 == 0 && dropped.j0 == 0 && dropped.ni == 3 && dropped.nj == 2));
  BOOST_TEST(dropped.at(0, 0) == 1 + 1 + 10 * 1);  // box point (1, 1)
  BOOST_TEST(dropped.at(2, 1) == 1 + 3 + 10 * 2);  // box point (3, 2)
  DraughtPatch outside;
  outside.reset(5, 0, 2, 2);
  outside.at(0, 0) = 1;
  drop_beyond_rim(outside, 3, 2, scratch);
  BOOST_TEST(outside.empty());
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
