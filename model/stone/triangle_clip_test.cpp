// Clipping a triangle against the water surface (model/README.md §1.4 step 2): exact areas and centroids.
#include <boost/test/unit_test.hpp>


#include "model/stone/portable_uniform.hpp"
#include "model/stone/triangle_clip.hpp"

using namespace stoneskip;

namespace {
constexpr double kRoundoff = 1e-13;  // unit-size triangles: a few ulps per operation
}

BOOST_AUTO_TEST_SUITE(triangle_clip)

BOOST_AUTO_TEST_CASE(a_triangle_cut_halfway_up_keeps_a_quarter_of_its_area) {
  // Oracle: similar triangles. Apex (0,0,−1), top edge z = 1 from x = −1 to 1 (area 2). The water
  // line z = 0 halves the height, so the submerged part is the similar triangle with apex
  // (0,0,−1) and base (±½, 0, 0): area ½, centroid z = (−1 + 0 + 0)/3.
  const Vec3 a(0, 0, -1), b(1, 0, 1), c(-1, 0, 1);
  const ClippedArea s = clip_submerged(a, b, c, -a.z(), -b.z(), -c.z());
  BOOST_TEST(std::abs(s.area_m2 - 0.5) <= kRoundoff);
  BOOST_TEST(std::abs(s.centroid_m.z() + 1.0 / 3.0) <= kRoundoff);
  BOOST_TEST(std::abs(s.centroid_m.x()) <= kRoundoff);
}

BOOST_AUTO_TEST_CASE(known_depths_give_the_trapezoid) {
  // Oracle: the whole triangle minus its dry tip. The right triangle (0,0,−1), (2,0,−1), (0,0,1)
  // cut at z = 0 leaves the trapezoid between z = −1 (width 2) and z = 0 (width 1): area 1.5.
  const Vec3 p0(0, 0, -1), p1(2, 0, -1), p2(0, 0, 1);
  const ClippedArea s = clip_submerged(p0, p1, p2, 1, 1, -1);
  BOOST_TEST(std::abs(s.area_m2 - 1.5) <= kRoundoff);
  // Whole: area 2, centroid z = −1/3. Dry tip: (0,0,0),(1,0,0),(0,0,1): area ½, centroid z = 1/3.
  const double zc = (2 * (-1.0 / 3.0) - 0.5 * (1.0 / 3.0)) / 1.5;
  BOOST_TEST(std::abs(s.centroid_m.z() - zc) <= kRoundoff);
}

BOOST_AUTO_TEST_CASE(wet_and_dry_parts_add_up_to_the_whole_triangle) {
  // Oracle: complementarity. Clipping with d and with −d splits the triangle: areas and first
  // moments of the two parts add up to the whole triangle's, for any depths.
  PortableUniform rng{7};
  auto point = [&] {  // one draw a statement: argument order is unspecified
    const double x = rng(-1, 1);
    const double y = rng(-1, 1);
    const double z = rng(-1, 1);
    return Vec3(x, y, z);
  };
  for (int k = 0; k < 2000; ++k) {
    const Vec3 a = point(), b = point(), c = point();
    const Vec3 depth = point();
    const double da = depth.x(), db = depth.y(), dc = depth.z();
    const ClippedArea wet = clip_submerged(a, b, c, da, db, dc);
    const ClippedArea dry = clip_submerged(a, b, c, -da, -db, -dc);
    const double whole = 0.5 * (b - a).cross(c - a).norm();
    BOOST_TEST(std::abs(wet.area_m2 + dry.area_m2 - whole) <= 1e-12);
    const Vec3 moment = wet.area_m2 * wet.centroid_m + dry.area_m2 * dry.centroid_m;
    BOOST_TEST((moment - whole * (a + b + c) / 3.0).norm() <= 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(fully_dry_and_fully_wet_triangles) {
  // Oracle: trivial cases, area 0 and the whole triangle.
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  BOOST_TEST(clip_submerged(a, b, c, -1, -2, -3).area_m2 == 0.0);
  BOOST_TEST(std::abs(clip_submerged(a, b, c, 1, 2, 3).area_m2 - 0.5) <= kRoundoff);
}

BOOST_AUTO_TEST_SUITE_END()
