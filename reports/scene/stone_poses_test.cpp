// The stone between steps (reports/scene/stone_poses.hpp) against a closed-form motion: constant
// velocity and a constant turning rate about a fixed axis, which linear position and slerp give
// exactly; and the ends held.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "reports/scene/stone_poses.hpp"

using namespace stoneskip;

namespace {

// Round-off of a few operations on O(1) values (positions in metres, unit quaternions).
constexpr double kRoundOff = 1e-13;

const Vec3 kStart(0.5, -0.2, 0.1), kVelocity(8.0, 0.3, -1.5), kAxis = Vec3(0.2, -0.4, 1.0).normalized();
constexpr double kRate_rad_s = 2 * 3.14159265358979 * 10;  // 10 rev/s

StonePose exact(double t) {
  return {t, kStart + t * kVelocity, Quat(Eigen::AngleAxisd(kRate_rad_s * t, kAxis))};
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_uniform_motion_is_interpolated_exactly_between_uneven_steps) {
  std::vector<StonePose> poses;
  for (const double t : {0.0, 0.004, 0.0041, 0.009, 0.02}) poses.push_back(exact(t));  // uneven steps, < ½ turn each
  for (const double t : {0.001, 0.00405, 0.0066, 0.015, 0.004}) {
    const StonePose p = pose_at(poses, t), e = exact(t);
    BOOST_TEST((p.position_m - e.position_m).norm() < kRoundOff);
    BOOST_TEST(p.orientation.angularDistance(e.orientation) < 1e-12);  // acos near 1 loses half the digits
    BOOST_TEST(p.t_s == t);
  }
}

BOOST_AUTO_TEST_CASE(a_quaternion_stored_with_the_other_sign_takes_the_short_arc) {
  std::vector<StonePose> poses = {exact(0.0), exact(0.01)};
  poses[1].orientation.coeffs() *= -1;  // the same orientation
  const StonePose p = pose_at(poses, 0.005);
  BOOST_TEST(p.orientation.angularDistance(exact(0.005).orientation) < 1e-12);
}

BOOST_AUTO_TEST_CASE(before_the_first_and_after_the_last_the_ends_are_held) {
  const std::vector<StonePose> poses = {exact(0.1), exact(0.2)};
  BOOST_TEST((pose_at(poses, 0.05).position_m - exact(0.1).position_m).norm() == 0.0);
  BOOST_TEST((pose_at(poses, 0.3).position_m - exact(0.2).position_m).norm() == 0.0);
  BOOST_TEST((pose_at({}, 0.3).position_m).norm() == 0.0);
}
