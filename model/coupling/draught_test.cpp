#include "model/coupling/draught.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>

#include "model/coupling/test_support.hpp"
#include "model/stone/portable_uniform.hpp"

namespace stoneskip {
namespace {

using test::still_field_options;
using test::submerged_volume;
using test::voxel_mesh;

constexpr double kRoundoff = 1e-12;  // a few thousand ulps of 0.1 m lengths (rotations, interpolation)

Mat3 tilt(double roll_deg, double pitch_deg, double yaw_deg) {
  const double r = M_PI / 180;
  return (Eigen::AngleAxisd(yaw_deg * r, Vec3::UnitZ()) * Eigen::AngleAxisd(pitch_deg * r, Vec3::UnitY()) *
          Eigen::AngleAxisd(roll_deg * r, Vec3::UnitX()))
      .toRotationMatrix();
}

HeightField flat_water(int n, double cell_m, Boundary b, double eta) {
  HeightField f(still_field_options(n, cell_m, b));
  f.set_levels(std::vector<double>(static_cast<std::size_t>(n) * n, eta), std::vector<double>(static_cast<std::size_t>(n) * n, eta));
  return f;
}

double patch_value(const DraughtPatch& p, int i, int j, int n) {
  // b at grid point (i, j) of an n × n field, whatever the patch's folding.
  const int a = ((i - p.i0) % n + n) % n, c = ((j - p.j0) % n + n) % n;
  return a < p.ni && c < p.nj ? p.at(a, c) : 0.0;
}

std::vector<Vec3> world_vertices(const Mesh& m, const Vec3& pos, const Mat3& R) {
  std::vector<Vec3> w;
  for (const auto& v : m.vertices) w.push_back(pos + R * v);
  return w;
}

// The U ("⊐") lying on its side: voxels in (x, z), extruded over 2 voxels in y. Vertical lines
// through the two arms cross the stone twice.
Mesh u_shape(double voxel_m) {
  std::vector<std::array<int, 3>> v;
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 3; ++x) {
      v.push_back({x, y, 0});
      v.push_back({x, y, 2});
    }
    v.push_back({2, y, 1});
  }
  return voxel_mesh(v, Vec3(voxel_m, voxel_m, voxel_m), Vec3(1.5 * voxel_m, voxel_m, 1.5 * voxel_m));
}

BOOST_AUTO_TEST_SUITE(draught_)

BOOST_AUTO_TEST_CASE(tilted_prism_has_the_closed_form_draught_under_its_caps) {
  // Oracle: a vertical line through a tilted flat cylinder enters the bottom cap plane at t_b and
  // leaves the top cap plane at t_t (solved from the planes' equations); where both points lie
  // inside the N-gon caps (checked in the body frame, a margin from the rim), b = clamp(η − t_b,
  // 0, t_t − t_b). Far from the stone b = 0. Tolerance kRoundoff.
  const int n = 200;
  const double d = 1.0 / n, eta = 0.004, R_m = 0.1, h = 0.02;
  const int segments = 64;
  const Mesh prism = make_prism(R_m, h, segments);
  StoneDraught draught(prism);
  HeightField water = flat_water(n, d, Boundary::periodic, eta);
  const Vec3 c(0.503, 0.497, 0.001);
  const Mat3 R = tilt(20, -7, 33);
  DraughtPatch p;
  const DraughtSummary s = draught.compute(c, R, water, FieldPlacement{}, p);
  BOOST_TEST(s.wet);
  const Vec3 nrm = R.col(2);
  int checked = 0;
  double worst = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = i * d, y = j * d;
      const double tb = c.z() + (-0.5 * h - nrm.x() * (x - c.x()) - nrm.y() * (y - c.y())) / nrm.z();
      const double tt = c.z() + (0.5 * h - nrm.x() * (x - c.x()) - nrm.y() * (y - c.y())) / nrm.z();
      const Vec3 qb = R.transpose() * (Vec3(x, y, tb) - c), qt = R.transpose() * (Vec3(x, y, tt) - c);
      const double inner = R_m * std::cos(M_PI / segments) - 2 * d;
      const double b = patch_value(p, i, j, n);
      if (std::hypot(qb.x(), qb.y()) < inner && std::hypot(qt.x(), qt.y()) < inner) {
        worst = std::max(worst, std::abs(b - std::clamp(eta - tb, 0.0, tt - tb)));
        ++checked;
      } else if (std::hypot(x - c.x(), y - c.y()) > R_m + h) {
        worst = std::max(worst, std::abs(b));
      }
    }
  BOOST_TEST(checked > 500);  // not vacuous: the caps' common inner region covers ~900 grid points
  BOOST_TEST(worst <= kRoundoff);
}

BOOST_AUTO_TEST_CASE(draught_volume_equals_the_submerged_volume_of_any_closed_mesh) {
  // Oracle: Σ b d² against the volume below the water by clipped tetrahedra (test_support.hpp), for
  // a prism, the paper's 44-triangle lens and a non-convex U, tilted and half under. Point sampling
  // of b, which is smooth inside the footprint and jumps at its rim, errs by at most the rim's
  // cells: perimeter × d × max b, the perimeter bounded by that of the projection's bounding box
  // (the interior's error is O(d²), far smaller). And averaged over
  // uniformly random grid offsets Σ b d² is an unbiased estimate of ∫ b dA: the mean of 64 offsets
  // must be within 4 standard errors.
  const int n = 160;
  const double d = 1.0 / n, eta = 0.0;
  struct Shape {
    const char* name;
    Mesh mesh;
  };
  const Shape shapes[] = {{"prism", make_prism(0.1, 0.02, 11)}, {"lens", make_lens(0.1, 0.03, 22)}, {"U", u_shape(0.04)}};
  HeightField water = flat_water(n, d, Boundary::periodic, eta);
  PortableUniform rng{7};
  for (const auto& sh : shapes) {
    StoneDraught draught(sh.mesh);
    const Mat3 R = tilt(17, 31, 12);
    const Vec3 c(0.5, 0.5, 0.004);
    const auto world = world_vertices(sh.mesh, c, R);
    const double exact = submerged_volume(world, sh.mesh.triangles, eta);
    double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
    for (const auto& v : world) {
      x0 = std::min(x0, v.x());
      x1 = std::max(x1, v.x());
      y0 = std::min(y0, v.y());
      y1 = std::max(y1, v.y());
    }
    const double perimeter = 2 * ((x1 - x0) + (y1 - y0));
    DraughtPatch p;
    const DraughtSummary s = draught.compute(c, R, water, FieldPlacement{}, p);
    BOOST_TEST(exact > 0);
    BOOST_TEST(std::abs(s.volume_m3 - p.volume_m3(d)) <= 1e-15);
    BOOST_TEST(std::abs(s.volume_m3 - exact) <= perimeter * d * s.max_m, sh.name << ": " << s.volume_m3 << " vs " << exact);
    double sum = 0, sum2 = 0;
    const int offsets = 64;
    for (int k = 0; k < offsets; ++k) {
      const double ax = rng(0, 1);  // one draw a statement: argument order is unspecified
      const FieldPlacement at{-ax * d, -rng(0, 1) * d};
      const double v = draught.compute(c, R, water, at, p).volume_m3;
      sum += v;
      sum2 += v * v;
    }
    const double mean = sum / offsets, se = std::sqrt(std::max(sum2 / offsets - mean * mean, 0.0) / (offsets - 1));
    BOOST_TEST(std::abs(mean - exact) <= 4 * se + 1e-15, sh.name << ": mean " << mean << " exact " << exact << " se " << se);
  }
}

BOOST_AUTO_TEST_CASE(non_convex_u_counts_both_of_its_intervals) {
  // Oracle: the upright U of 4 cm voxels spans z ∈ [−6, −2] cm (lower arm), [−2, 2] (back), [2, 6]
  // (upper arm); with the water at z = 3 cm a line through the arms' columns is inside for
  // 4 cm of the lower arm and 1 cm of the upper: b = 5 cm; through the back column 9 cm.
  const int n = 64;
  const double d = 1.0 / n;
  HeightField water = flat_water(n, d, Boundary::reflecting, 0.03);
  StoneDraught draught(u_shape(0.04));
  DraughtPatch p;
  const Vec3 c(0.5 + 0.3 * d, 0.5 + 0.3 * d, 0.0);  // grid points off the voxel faces
  draught.compute(c, Mat3::Identity(), water, FieldPlacement{}, p);
  int arms = 0, back = 0;
  double worst = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = i * d - c.x(), y = j * d - c.y(), b = patch_value(p, i, j, n);
      double expect = 0;
      if (std::abs(y) < 0.04 && x > -0.06 && x < 0.06) {
        expect = x < 0.02 ? 0.05 : 0.09;
        (x < 0.02 ? arms : back)++;
      }
      worst = std::max(worst, std::abs(b - expect));
    }
  // x = (k − 0.3) d: inside (−6, 2) cm for 5 values of k, inside (2, 6) cm for 3; y: 5 values.
  BOOST_TEST(arms == 5 * 5);
  BOOST_TEST(back == 3 * 5);
  BOOST_TEST(worst <= kRoundoff);
}

BOOST_AUTO_TEST_CASE(points_on_shared_edges_are_counted_once) {
  // Oracle: an axis-aligned 16 × 8-cell box with every face on grid lines (d = 1/64, exact binary
  // coordinates): its faces' diagonals and rims pass exactly through grid points. With the box
  // under water each point of the half-open footprint [i0, i0 + 16) × [j0, j0 + 8) (top-left rule)
  // gets b = h, and no other point gets anything: Σ b = 16 · 8 · h exactly.
  const int n = 64;
  const double d = 1.0 / 64, h = 0.0625;
  HeightField water = flat_water(n, d, Boundary::periodic, 0.5);
  const Mesh box = voxel_mesh({{0, 0, 0}}, Vec3(16 * d, 8 * d, h), Vec3(8 * d, 4 * d, 0.5 * h));
  StoneDraught draught(box);
  DraughtPatch p;
  for (double yaw : {0.0, 90.0, 180.0}) {
    const Mat3 R = yaw == 0 ? Mat3::Identity() : Mat3(Eigen::AngleAxisd(yaw * M_PI / 180, Vec3::UnitZ()));
    Mat3 Rx = R;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) Rx(a, b) = std::round(Rx(a, b));  // exact quarter turns
    const DraughtSummary s = draught.compute(Vec3(0.5, 0.5, 0.0), Rx, water, FieldPlacement{}, p);
    BOOST_TEST(s.points == 16 * 8, "yaw " << yaw << ": " << s.points);
    BOOST_TEST(s.volume_m3 == 16 * 8 * h * d * d);
    BOOST_TEST(s.max_m == h);
  }
}

BOOST_AUTO_TEST_CASE(draught_follows_the_surface_and_wraps_on_a_periodic_field) {
  // Oracle: (1) under a sloping surface z = 0.01 + 0.05 x a flat-bottomed box (bottom at −1 cm,
  // top above the water) has b = z_ij + 0.01 at each point of its footprint. (2) The same tilted
  // prism placed across the periodic seam gives the same values, shifted, as one in the middle.
  const int n = 64;
  const double d = 1.0 / n;
  HeightField slope(still_field_options(n, d, Boundary::reflecting));
  std::vector<double> z(n * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) z[j * n + i] = 0.01 + 0.05 * i * d;
  slope.set_levels(z, z);
  const Mesh box = voxel_mesh({{0, 0, 0}}, Vec3(0.2, 0.2, 0.1), Vec3(0.1, 0.1, 0.01));
  StoneDraught draught(box);
  DraughtPatch p;
  draught.compute(Vec3(0.5 + 0.2 * d, 0.5 + 0.2 * d, 0), Mat3::Identity(), slope, FieldPlacement{}, p);
  double worst = 0;
  int points = 0;
  for (int c = 0; c < p.nj; ++c)
    for (int a = 0; a < p.ni; ++a) {
      const int i = p.i0 + a;
      if (p.at(a, c) > 0) ++points;
      if (p.at(a, c) > 0) worst = std::max(worst, std::abs(p.at(a, c) - (0.01 + 0.05 * i * d + 0.01)));
    }
  BOOST_TEST(points == 13 * 13);  // 0.2 m / (1/64) = 12.8 cells
  BOOST_TEST(worst <= kRoundoff);

  HeightField water = flat_water(n, d, Boundary::periodic, 0.002);
  StoneDraught prism(make_prism(0.1, 0.02, 11));
  const Mat3 R = tilt(10, 5, 40);
  DraughtPatch mid, seam;
  const DraughtSummary s1 = prism.compute(Vec3(0.5, 0.5, 0), R, water, FieldPlacement{}, mid);
  const DraughtSummary s2 = prism.compute(Vec3(0.5 + 32 * d, 0.5 - 30 * d, 0), R, water, FieldPlacement{}, seam);
  BOOST_TEST(s1.points == s2.points);
  BOOST_TEST(std::abs(s1.volume_m3 - s2.volume_m3) <= 1e-15);
  double diff = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) diff = std::max(diff, std::abs(patch_value(mid, i, j, n) - patch_value(seam, i + 32, j - 30, n)));
  BOOST_TEST(diff <= kRoundoff);
}

BOOST_AUTO_TEST_CASE(a_stone_in_flight_or_beyond_the_rim_has_no_draught) {
  // Oracle: the definition — nothing of the stone below the water, or no grid point under it.
  const int n = 32;
  const double d = 1.0 / n;
  HeightField water = flat_water(n, d, Boundary::reflecting, 0.0);
  StoneDraught prism(make_prism(0.1, 0.02, 11));
  DraughtPatch p;
  BOOST_TEST(!prism.compute(Vec3(0.5, 0.5, 0.0101), Mat3::Identity(), water, FieldPlacement{}, p).wet);
  BOOST_TEST(p.empty());
  BOOST_TEST(!prism.compute(Vec3(1.5, 0.5, -0.005), Mat3::Identity(), water, FieldPlacement{}, p).wet);
  BOOST_TEST(p.empty());
  // Half beyond the rim: only the points on the grid, each with the full column below η = 0.
  const DraughtSummary s = prism.compute(Vec3(1.0, 0.5, 0.0), Mat3::Identity(), water, FieldPlacement{}, p);
  BOOST_TEST(s.wet);
  BOOST_TEST(p.i0 + p.ni <= n);
  BOOST_TEST(std::abs(s.max_m - 0.01) <= kRoundoff);
}

BOOST_AUTO_TEST_CASE(coupled_limit_is_the_free_limit_over_root_two) {
  // Oracle: model/README.md §2.4, the Courant number under the footprint is √2 σ: 5-point 1/2, γ = 1/3 √6/4.
  BOOST_TEST(std::abs(coupled_courant_limit(named_stencil("five_point")) - 0.5) <= 1e-15);
  BOOST_TEST(std::abs(coupled_courant_limit(named_stencil("nine_point_isotropic")) - std::sqrt(6.0) / 4) <= 1e-15);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
