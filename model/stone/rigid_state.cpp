#include "model/stone/rigid_state.hpp"

namespace stoneskip {

StateVector to_vector(const RigidState& s) {
  return {s.position_m.x(), s.position_m.y(), s.position_m.z(),
          s.velocity_m_s.x(), s.velocity_m_s.y(), s.velocity_m_s.z(),
          s.orientation.w(), s.orientation.x(), s.orientation.y(), s.orientation.z(),
          s.angular_momentum_kg_m2_s.x(), s.angular_momentum_kg_m2_s.y(), s.angular_momentum_kg_m2_s.z()};
}

RigidState from_vector(const double* y) {
  RigidState s;
  s.position_m = Vec3(y[0], y[1], y[2]);
  s.velocity_m_s = Vec3(y[3], y[4], y[5]);
  s.orientation = Quat(y[6], y[7], y[8], y[9]);
  s.angular_momentum_kg_m2_s = Vec3(y[10], y[11], y[12]);
  return s;
}

Vec3 angular_velocity(const Stone& stone, const RigidState& s) {
  const Mat3 R = s.orientation.normalized().toRotationMatrix();
  return R * (stone.inertia_body_inv * (R.transpose() * s.angular_momentum_kg_m2_s));
}

void set_body_angular_velocity(const Stone& stone, RigidState& s, const Vec3& omega_body_rad_s) {
  const Mat3 R = s.orientation.normalized().toRotationMatrix();
  s.angular_momentum_kg_m2_s = R * (stone.inertia_body_kg_m2 * omega_body_rad_s);
}

}  // namespace stoneskip
