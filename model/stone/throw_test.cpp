// A throw's initial state and its angles (model/README.md §1.7–1.8), and the quaternion's rate in
// the equations of motion (§1.3), against closed forms and an independent finite difference. Only
// integrator tests covered them, where a sign error of the attack angle or of the spin would have
// been read as the integrator's.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>

#include "model/stone/mass_properties.hpp"
#include "model/stone/rigid_body.hpp"
#include "model/stone/throw.hpp"

using namespace stoneskip;

namespace {

constexpr double kDeg = std::numbers::pi / 180;
constexpr double kRoundoff = 1e-13;  // a few hundred ulps of unit vectors and angles

Stone prism() {
  const Mesh m = make_prism(0.03, 0.008, 11);
  return make_stone(m, mass_properties_from_density(m, 2500), 0.03, "prism");
}

}  // namespace

BOOST_AUTO_TEST_SUITE(a_throw)

BOOST_AUTO_TEST_CASE(the_release_state_has_the_throw_s_angles_and_spin) {
  // Oracle: §1.7 by hand. Attack α = 20° leading edge up: body x points to (cos α, 0, sin α) and
  // body z to (−sin α, 0, cos α); path β = 5° below the horizontal: v = U (cos β, 0, −sin β); spin
  // Ω = 14 rev/s counter-clockwise seen from above: ω = 2π Ω along body z (the prism's axis is a
  // principal axis, so L = I ω keeps that direction), whose world z is positive.
  const Stone s = prism();
  ThrowParameters p;
  p.speed_m_s = 12;
  p.path_angle_deg = 5;
  p.attack_angle_deg = 20;
  p.spin_rev_s = 14;
  p.height_m = 0.3;
  const RigidState st = initial_state(s, p);
  const Vec3 body_x = st.orientation * Vec3::UnitX(), body_z = st.orientation * Vec3::UnitZ();
  BOOST_TEST((body_x - Vec3(std::cos(20 * kDeg), 0, std::sin(20 * kDeg))).norm() <= kRoundoff);
  BOOST_TEST((body_z - Vec3(-std::sin(20 * kDeg), 0, std::cos(20 * kDeg))).norm() <= kRoundoff);
  BOOST_TEST((st.velocity_m_s - 12 * Vec3(std::cos(5 * kDeg), 0, -std::sin(5 * kDeg))).norm() <= 12 * kRoundoff);
  BOOST_TEST((st.position_m - Vec3(0, 0, 0.3)).norm() == 0.0);
  const Vec3 w = angular_velocity(s, st);
  BOOST_TEST((w - 2 * std::numbers::pi * 14 * body_z).norm() <= 88 * kRoundoff);
  BOOST_TEST(w.z() > 0);
  // The angles read back (§1.8): the attack angle equals α at release, no roll.
  const AttitudeAngles a = attitude_angles(st);
  BOOST_TEST(std::abs(a.path_angle_deg - 5) <= kRoundoff / kDeg);
  BOOST_TEST(std::abs(a.attack_angle_deg - 20) <= kRoundoff / kDeg);
  BOOST_TEST(std::abs(a.roll_angle_deg) <= kRoundoff / kDeg);
}

BOOST_AUTO_TEST_CASE(a_stone_rolled_about_its_path_reads_that_roll) {
  // Oracle: a rotation by φ about the direction of flight (+x) tilts the normal to
  // (0, −sin φ, cos φ); §1.8's roll is atan2(−n·left, n_z) with left = z × forward = +y: φ.
  RigidState st;
  st.velocity_m_s = Vec3(5, 0, -1);
  for (double phi : {-30.0, 7.0, 60.0}) {
    st.orientation = Quat(Eigen::AngleAxisd(phi * kDeg, Vec3::UnitX()));
    const AttitudeAngles a = attitude_angles(st);
    BOOST_TEST(std::abs(a.roll_angle_deg - phi) <= kRoundoff / kDeg);
    BOOST_TEST(std::abs(a.attack_angle_deg) <= kRoundoff / kDeg);
  }
}

BOOST_AUTO_TEST_CASE(the_quaternion_turns_at_the_world_angular_velocity) {
  // Oracle: an independent finite difference. Turning at a constant world ω, the orientation is
  // q(t) = exp(ω t) q0 (an axis-angle rotation by |ω| t about ω̂, applied after q0); its central
  // difference over ±h must equal the right-hand side's dq/dt = ½ (0, ω) ⊗ q0. A body-frame ω, or
  // the product in the other order, differs by O(|ω| |q|) where q0 is not the identity. The
  // difference's own error is |ω|³ h² / 24 ≈ 4e-8 of |dq/dt| at h = 1e-6 s.
  const Stone s = prism();
  Environment env;
  env.air_density_kg_m3 = 0;  // no loads: the quaternion's rate alone
  RigidState st;
  st.position_m = Vec3(0, 0, 1);
  st.orientation = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  set_body_angular_velocity(s, st, Vec3(3, -40, 90));  // a tumbling spin, not along a principal axis in world
  const Vec3 w = angular_velocity(s, st);
  const StateDerivative d = rigid_body_rhs(s, env, st);
  const double h = 1e-6;
  auto q_at = [&](double t) { return Quat(Eigen::AngleAxisd(w.norm() * t, w.normalized())) * st.orientation; };
  const Eigen::Vector4d fd = (Eigen::Vector4d(q_at(h).w(), q_at(h).x(), q_at(h).y(), q_at(h).z()) -
                              Eigen::Vector4d(q_at(-h).w(), q_at(-h).x(), q_at(-h).y(), q_at(-h).z())) /
                             (2 * h);
  BOOST_TEST((d.dquaternion - fd).norm() <= 1e-6 * fd.norm(), "rhs " << d.dquaternion.transpose() << " vs " << fd.transpose());
}

BOOST_AUTO_TEST_SUITE_END()
