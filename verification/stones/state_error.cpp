#include "verification/stones/state_error.hpp"

#include <algorithm>
#include <cmath>

namespace stoneskip {

double position_error(const Stone& stone, const RigidState& s, const RigidState& ref) {
  return (s.position_m - ref.position_m).norm() / std::max(stone.bounding_radius_m, 1e-6);
}

double orientation_error(const RigidState& s, const RigidState& ref) {
  // Rotation angle between the two orientations, accurate for tiny angles (no acos near 1).
  const Quat d = ref.orientation.normalized().conjugate() * s.orientation.normalized();
  return 2 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

double state_error(const Stone& stone, const RigidState& s, const RigidState& ref) {
  const double e_x = position_error(stone, s, ref);
  const double e_v = (s.velocity_m_s - ref.velocity_m_s).norm() / std::max(ref.velocity_m_s.norm(), 1e-6);
  const double e_q = orientation_error(s, ref);
  const double L_scale = std::max(ref.angular_momentum_kg_m2_s.norm(), stone.inertia_body_kg_m2(2, 2) * 1.0);
  const double e_L = (s.angular_momentum_kg_m2_s - ref.angular_momentum_kg_m2_s).norm() / L_scale;
  return std::max({e_x, e_v, e_q, e_L});
}

RigidState integrate_fixed(const Stone& stone, const Environment& env, const RigidState& s, double T_s, int steps,
                           Scheme scheme, long* rhs_evaluations) {
  RigidState y = s;
  const double h = T_s / steps;
  for (int k = 0; k < steps; ++k) y = realtime_step(stone, env, y, h, scheme, nullptr, rhs_evaluations);
  return y;
}

}  // namespace stoneskip
