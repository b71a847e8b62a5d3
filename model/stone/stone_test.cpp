// make_stone's principal frame (model/stone/stone.hpp, principal_frame in mass_properties.hpp):
// meshes built on their axes are left exactly as they were; an irregular stone written in other
// orientations (rotated, translated, y-up) gives the same body mesh, inertia, air disk and loads.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>

#include "model/stone/fluid_forces.hpp"

using namespace stoneskip;

namespace {

// Positions are O(3 cm) and pass through an eigen-decomposition and two rotations: 1e-13 m is a few
// hundred ulps of them. Moments O(1e-5 kg m²) relative likewise.
constexpr double kPosition_m = 1e-13;
constexpr double kRelative = 1e-11;

// An irregular flat stone: a 9-gon prism whose rim radii, rim heights and top apex all differ, so
// its three moments differ and no symmetry fixes the sign of any axis; and it is tilted in its own
// file (its principal axes are not the file's axes).
Mesh irregular_stone() {
  const int n = 9;
  Mesh m;
  const double radius[n] = {0.030, 0.026, 0.031, 0.022, 0.027, 0.033, 0.025, 0.029, 0.024};
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n + 0.05 * std::sin(3.0 * k);
    const double r = radius[k];
    m.vertices.emplace_back(r * std::cos(a), r * std::sin(a), -0.004 + 0.0005 * std::cos(2.0 * k));
    m.vertices.emplace_back(0.9 * r * std::cos(a), 0.9 * r * std::sin(a), 0.003 + 0.0004 * std::sin(k));
  }
  m.vertices.emplace_back(0.002, -0.001, -0.0045);  // bottom centre
  m.vertices.emplace_back(-0.003, 0.002, 0.0045);   // top centre, off axis
  const int bottom = 2 * n, top = 2 * n + 1;
  for (int k = 0; k < n; ++k) {
    const int j = (k + 1) % n;
    m.triangles.push_back({bottom, 2 * j, 2 * k});          // bottom fan, outward −z
    m.triangles.push_back({top, 2 * k + 1, 2 * j + 1});     // top fan, outward +z
    m.triangles.push_back({2 * k, 2 * j, 2 * j + 1});       // rim
    m.triangles.push_back({2 * k, 2 * j + 1, 2 * k + 1});
  }
  const Mat3 tilt = Eigen::AngleAxisd(0.15, Vec3(1, 1, 0).normalized()).toRotationMatrix();
  for (auto& v : m.vertices) v = tilt * v;
  return m;
}

Mesh transformed(const Mesh& m, const Mat3& R, const Vec3& shift) {
  Mesh out = m;
  for (auto& v : out.vertices) v = R * v + shift;
  return out;
}

Stone stone_of(const Mesh& m) { return make_stone(m, mass_properties_from_density(m, 2500), 0, "irregular"); }

}  // namespace

BOOST_AUTO_TEST_SUITE(stone_frame)

BOOST_AUTO_TEST_CASE(a_prism_built_on_its_axes_is_left_exactly_as_it_was) {
  // Oracle: make_prism builds the body frame of model/README.md §1.1 (I diagonal, I_zz largest); the frame
  // must then be the identity and the body mesh the mesh minus its centre of mass, bit for bit, so
  // every result computed before principal frames existed is unchanged.
  for (int n : {3, 11, 32}) {
    const Mesh m = make_prism(0.03, 0.008, n);
    const MassProperties mp = mass_properties_from_density(m, 2500);
    const Stone s = make_stone(m, mp, 0, "prism");
    BOOST_TEST((s.body_axes_in_mesh == Mat3::Identity()), "N=" << n);
    for (std::size_t k = 0; k < m.vertices.size(); ++k)
      BOOST_TEST((s.body_mesh.vertices[k] == m.vertices[k] - mp.center_of_mass_m), "N=" << n << " vertex " << k);
    BOOST_TEST((s.inertia_body_kg_m2 == mp.inertia_kg_m2));
  }
}

BOOST_AUTO_TEST_CASE(the_body_frame_is_principal_with_z_the_largest_moment_and_right_handed) {
  // Oracle: definition of the frame — Pᵀ I P diagonal with I_xx ≤ I_yy ≤ I_zz, P a proper rotation,
  // body z pointing to the file's up (+z), and the mesh still closed and outward in the body frame.
  const Mesh m = irregular_stone();
  const Stone s = stone_of(m);
  const Mat3& P = s.body_axes_in_mesh;
  const Mat3& I = s.inertia_body_kg_m2;
  const double scale = I.trace();
  BOOST_TEST(std::abs(I(0, 1)) + std::abs(I(0, 2)) + std::abs(I(1, 2)) <= kRelative * scale);
  BOOST_TEST(I(0, 0) < I(1, 1));
  BOOST_TEST(I(1, 1) < I(2, 2));
  BOOST_TEST(std::abs(P.determinant() - 1) <= kRelative);
  BOOST_TEST((P.transpose() * P - Mat3::Identity()).cwiseAbs().maxCoeff() <= kRelative);
  BOOST_TEST(P(2, 2) > 0.9);  // the file's up, tilted by 0.15 rad
  BOOST_TEST(check_mesh(s.body_mesh).ok);
  BOOST_TEST(check_mesh(s.body_mesh).signed_volume_m3 > 0);
}

BOOST_AUTO_TEST_CASE(the_same_stone_written_in_other_orientations_is_the_same_stone) {
  // Oracle: the stone written as is, rotated by 35° about (1, 2, 3) and moved, and written y-up
  // (its up along the file's +y, as Blender exports OBJ), then rotated 50° about that up: the body
  // meshes, moments, air disks must agree vertex by vertex, and so must the water loads of one state.
  const Mesh m = irregular_stone();
  const Mat3 oblique = Eigen::AngleAxisd(35 * std::numbers::pi / 180, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Mat3 y_up = Eigen::AngleAxisd(50 * std::numbers::pi / 180, Vec3::UnitY()).toRotationMatrix() *
                    Eigen::AngleAxisd(-std::numbers::pi / 2, Vec3::UnitX()).toRotationMatrix();
  BOOST_TEST_REQUIRE((y_up * Vec3::UnitZ() - Vec3::UnitY()).norm() <= 1e-15);  // z → +y
  const Stone a = stone_of(m);
  RigidState st;
  st.position_m = Vec3(0.1, 0, 0.001);
  st.velocity_m_s = Vec3(3.3, 0.2, -1.2);
  st.orientation = Quat(Eigen::AngleAxisd(-0.35, Vec3::UnitY()));
  set_body_angular_velocity(a, st, Vec3(1, -2, 400));
  const WaterLoads wa = water_loads(a, Environment{}, st);
  BOOST_TEST_REQUIRE(wa.wet_triangles > 0);
  for (const auto& [name, R, shift] : {std::tuple{"oblique", oblique, Vec3(1, -2, 0.5)}, std::tuple{"y-up", y_up, Vec3(0, 0, 0)}}) {
    BOOST_TEST_CONTEXT(name) {
      const Stone b = stone_of(transformed(m, R, shift));
      BOOST_TEST_REQUIRE(b.body_mesh.vertices.size() == a.body_mesh.vertices.size());
      double worst = 0;
      for (std::size_t k = 0; k < a.body_mesh.vertices.size(); ++k)
        worst = std::max(worst, (a.body_mesh.vertices[k] - b.body_mesh.vertices[k]).norm());
      BOOST_TEST(worst <= kPosition_m);
      BOOST_TEST((a.inertia_body_kg_m2 - b.inertia_body_kg_m2).cwiseAbs().maxCoeff() <= kRelative * a.inertia_body_kg_m2.trace());
      BOOST_TEST(std::abs(a.disk_radius_m - b.disk_radius_m) <= kPosition_m);
      // The frame maps the file's frame onto the body frame: P_b = R P_a.
      BOOST_TEST((b.body_axes_in_mesh - R * a.body_axes_in_mesh).cwiseAbs().maxCoeff() <= kRelative);
      const WaterLoads wb = water_loads(b, Environment{}, st);
      BOOST_TEST(wb.wet_triangles == wa.wet_triangles);
      BOOST_TEST((wa.force_N - wb.force_N).norm() <= kRelative * wa.force_N.norm());
      BOOST_TEST((wa.torque_N_m - wb.torque_N_m).norm() <= kRelative * wa.torque_N_m.norm());
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
