// The movie's side view (reports/scene/side_view.hpp) against closed forms: a box stone pitched by θ
// seen along the throw spans a cos θ + c sin θ by a sin θ + c cos θ; its window holds the stone and
// the still level, at true scale.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>
#include <sstream>

#include "model/stone/mass_properties.hpp"
#include "reports/scene/side_view.hpp"

using namespace stoneskip;

namespace {

// Outlines are written with 6 significant digits of centimetres: 1e-4 cm on values of a few cm.
constexpr double kWritten_cm = 1e-4;

// A box a × b × c (a > b > c) on its axes: make_stone keeps it as it is (its principal frame:
// body z the largest moment, about the shortest side; body x the smallest, along the longest).
Stone box_stone(double a, double b, double c) {
  Mesh m;
  for (int k = 0; k < 8; ++k) m.vertices.emplace_back((k & 1 ? 0.5 : -0.5) * a, (k & 2 ? 0.5 : -0.5) * b, (k & 4 ? 0.5 : -0.5) * c);
  // Two outward triangles per face (corner k has bit 0: +x, bit 1: +y, bit 2: +z).
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    m.triangles.push_back({f[0], f[1], f[2]});
    m.triangles.push_back({f[0], f[2], f[3]});
  }
  return make_stone(m, mass_properties_from_density(m, 2500), 0, "box");
}

struct Extent {
  double s0 = 1e300, s1 = -1e300, z0 = 1e300, z1 = -1e300;
  int blocks = 0, points = 0;
};

Extent extent_of(const std::string& text) {
  Extent e;
  std::istringstream in(text);
  std::string line;
  int in_block = 0;
  while (std::getline(in, line)) {
    if (line.empty()) {
      BOOST_TEST(in_block == 4);  // three corners and the first again
      ++e.blocks;
      in_block = 0;
      continue;
    }
    double s = 0, z = 0;
    std::istringstream(line) >> s >> z;
    e.s0 = std::min(e.s0, s);
    e.s1 = std::max(e.s1, s);
    e.z0 = std::min(e.z0, z);
    e.z1 = std::max(e.z1, z);
    ++in_block;
    ++e.points;
  }
  return e;
}

}  // namespace

BOOST_AUTO_TEST_CASE(side_view_direction_is_the_horizontal_velocity) {
  const Vec3 e = side_view_direction(Vec3(3, -4, 7));
  BOOST_TEST(e.x() == 0.6, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(e.y() == -0.8, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(e.z() == 0.0);
  BOOST_TEST((side_view_direction(Vec3(0, 0, -2)) - Vec3::UnitX()).norm() == 0.0);  // a vertical drop: world x
}

BOOST_AUTO_TEST_CASE(a_pitched_box_spans_its_closed_form_outline) {
  const double a = 0.08, b = 0.05, c = 0.01, theta = 20 * std::numbers::pi / 180, zc = 0.013;
  const Stone stone = box_stone(a, b, c);
  BOOST_REQUIRE(stone.body_mesh.vertices.size() == 8);
  RigidState st;
  st.position_m = Vec3(2.0, -1.0, zc);  // the side view is relative to the centre along e, absolute in z
  // Pitched nose up by θ about world y: body x (the long side) rises by a sin θ over its length.
  st.orientation = Quat(Eigen::AngleAxisd(-theta, Vec3::UnitY()));
  std::ostringstream along, across;
  write_side_faces(along, stone, st, Vec3::UnitX());
  write_side_faces(across, stone, st, Vec3::UnitY());
  const Extent e = extent_of(along.str());
  BOOST_TEST(e.blocks == 12);
  BOOST_TEST(e.points == 48);
  const double s_span = a * std::cos(theta) + c * std::sin(theta), z_span = a * std::sin(theta) + c * std::cos(theta);
  BOOST_TEST(std::abs(e.s1 - 50 * s_span) < kWritten_cm);
  BOOST_TEST(std::abs(e.s0 + 50 * s_span) < kWritten_cm);
  BOOST_TEST(std::abs(e.z1 - 100 * (zc + 0.5 * z_span)) < kWritten_cm);
  BOOST_TEST(std::abs(e.z0 - 100 * (zc - 0.5 * z_span)) < kWritten_cm);
  const Extent x = extent_of(across.str());  // seen across: the box's width b
  BOOST_TEST(std::abs(x.s1 - 50 * b) < kWritten_cm);
  BOOST_TEST(std::abs(x.s0 + 50 * b) < kWritten_cm);
}

BOOST_AUTO_TEST_CASE(the_window_holds_the_stone_and_the_still_level_at_true_scale) {
  const double R = 0.03;
  for (const double z : {0.0, 0.02, -0.025, 0.1, -0.11}) {  // within kSideViewReach R: both in view
    const SideWindow w = side_window(z, R);
    BOOST_TEST(w.level_note.empty());
    BOOST_TEST(w.z0_cm <= 100 * (z - R) - 0.3 * 100 * R + 1e-12);
    BOOST_TEST(w.z1_cm >= 100 * (z + R) + 0.3 * 100 * R - 1e-12);
    BOOST_TEST(w.z0_cm < 0);
    BOOST_TEST(w.z1_cm > 0);
    BOOST_TEST(w.z1_cm - w.z0_cm == kSideViewAspect * (w.s1_cm - w.s0_cm), boost::test_tools::tolerance(1e-12));  // the panel's shape
    BOOST_TEST(w.s1_cm - w.s0_cm >= 5 * 100 * R - 1e-12);
    BOOST_TEST(w.s0_cm == -w.s1_cm);
  }
  const SideWindow high = side_window(0.5, R);  // 50 cm up: the stone alone, the level said
  // 4 R about the stone fits in the least width, 5 R (15 cm), whose height is 1.6 × 15 = 24 cm.
  BOOST_TEST(high.z0_cm == 50 - 12, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(high.z1_cm == 50 + 12, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(high.s1_cm == 7.5, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(high.level_note == "level 50 cm below");
  BOOST_TEST(side_window(-0.2, R).level_note == "level 20 cm above");
  const std::vector<double> s = side_samples_cm(high, 5);
  BOOST_TEST(s.front() == high.s0_cm);
  BOOST_TEST(s.back() == high.s1_cm);
  BOOST_TEST(s[2] == 0.0, boost::test_tools::tolerance(1e-12));
}
