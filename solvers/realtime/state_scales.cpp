#include "solvers/realtime/state_scales.hpp"

#include <algorithm>
#include <cmath>

namespace stoneskip {

StateScales state_scales(const Stone& stone, const RigidState& initial, double gravity_m_s2) {
  StateScales s;
  s.length_m = stone.bounding_radius_m;
  const double spin = angular_velocity(stone, initial).norm();
  s.speed_m_s = std::max(initial.velocity_m_s.norm() + spin * s.length_m, std::sqrt(gravity_m_s2 * s.length_m));
  if (!(s.speed_m_s > 0)) s.speed_m_s = s.length_m / 1.0;  // at rest without gravity: one radius per second
  const double i_min = stone.inertia_body_kg_m2.diagonal().minCoeff();  // principal: the body frame is
  s.angular_momentum_kg_m2_s = i_min * s.speed_m_s / s.length_m;
  return s;
}

StateVector scaled_absolute_tolerances(double atol_m, const StateScales& scales) {
  StateVector a;
  const double per_length = atol_m / scales.length_m;
  for (int k = 0; k < 3; ++k) {
    a[kPosition + k] = atol_m;
    a[kVelocity + k] = per_length * scales.speed_m_s;
    a[kAngularMomentum + k] = per_length * scales.angular_momentum_kg_m2_s;
  }
  for (int k = 0; k < 4; ++k) a[kQuaternion + k] = per_length;
  return a;
}

}  // namespace stoneskip
