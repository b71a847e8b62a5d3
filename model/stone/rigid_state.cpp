#include "model/stone/rigid_state.hpp"

namespace stoneskip {

StateVector to_vector(const RigidState& s) {
  StateVector y{};
  for (int k = 0; k < 3; ++k) {
    y[kPosition + k] = s.position_m[k];
    y[kVelocity + k] = s.velocity_m_s[k];
    y[kAngularMomentum + k] = s.angular_momentum_kg_m2_s[k];
  }
  y[kQuaternion + 0] = s.orientation.w();
  y[kQuaternion + 1] = s.orientation.x();
  y[kQuaternion + 2] = s.orientation.y();
  y[kQuaternion + 3] = s.orientation.z();
  return y;
}

RigidState from_vector(const double* y) {
  RigidState s;
  s.position_m = Vec3(y[kPosition], y[kPosition + 1], y[kPosition + 2]);
  s.velocity_m_s = Vec3(y[kVelocity], y[kVelocity + 1], y[kVelocity + 2]);
  s.orientation = Quat(y[kQuaternion], y[kQuaternion + 1], y[kQuaternion + 2], y[kQuaternion + 3]);
  s.angular_momentum_kg_m2_s = Vec3(y[kAngularMomentum], y[kAngularMomentum + 1], y[kAngularMomentum + 2]);
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
