#include "model/stone/throw.hpp"

#include <cmath>
#include <numbers>

namespace stoneskip {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}

RigidState initial_state(const Stone& stone, const ThrowParameters& p) {
  RigidState s;
  const double beta = p.path_angle_deg * kDeg;
  const double alpha = p.attack_angle_deg * kDeg;
  s.position_m = Vec3(0, 0, p.height_m);
  s.velocity_m_s = p.speed_m_s * Vec3(std::cos(beta), 0, -std::sin(beta));  // §1.7
  // Rotation about world y by −α takes body x to (cos α, 0, sin α) (§1.7).
  s.orientation = Quat(Eigen::AngleAxisd(-alpha, Vec3::UnitY()));
  const Vec3 omega_body(p.wobble_rad_s, 0, 2.0 * std::numbers::pi * p.spin_rev_s);
  set_body_angular_velocity(stone, s, omega_body);
  return s;
}

AttitudeAngles attitude_angles(const RigidState& s) {
  AttitudeAngles a;
  const Vec3& v = s.velocity_m_s;
  const double vh = std::hypot(v.x(), v.y());
  a.path_angle_deg = std::atan2(-v.z(), vh) / kDeg;
  const Vec3 n = s.orientation.normalized() * Vec3::UnitZ();
  const Vec3 forward = vh > 0 ? Vec3(v.x() / vh, v.y() / vh, 0) : Vec3::UnitX();
  const Vec3 left = Vec3::UnitZ().cross(forward);
  a.attack_angle_deg = std::atan2(-n.dot(forward), n.z()) / kDeg;
  a.roll_angle_deg = std::atan2(-n.dot(left), n.z()) / kDeg;
  return a;
}

}  // namespace stoneskip
