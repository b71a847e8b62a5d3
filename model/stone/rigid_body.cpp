#include "model/stone/rigid_body.hpp"

namespace stoneskip {

StateDerivative rigid_body_rhs(const Stone& stone, const Environment& env, const RigidState& s,
                               const WaterSurface* surface, Loads* loads, std::vector<FacePush>* pushes,
                               const LoadMode* mode) {
  const double m = stone.mass.mass_kg;
  const Vec3 g(0, 0, -m * env.gravity_m_s2);
  const WaterLoads w = water_loads(stone, env, s, surface, pushes, mode);
  const AirLoads a = air_loads(stone, env, s);
  StateDerivative d;
  d.dposition = s.velocity_m_s;
  d.dvelocity = (g + a.force_N + w.force_N) / m;
  if (env.attitude == Attitude::held) {
    // Attitude held (model/stone/environment.hpp): L and q constant, the torques discarded.
    if (loads) *loads = Loads{w, a, g};
    return d;
  }
  d.dangular_momentum = w.torque_N_m;  // τ_air = 0 (model/README.md §1.6)
  const Vec3 omega = angular_velocity(stone, s);
  // dq/dt = ½ (0, ω) ⊗ q (world-frame ω, q body → world).
  const Quat wq(0, omega.x(), omega.y(), omega.z());
  const Quat dq = wq * s.orientation;
  d.dquaternion = 0.5 * Eigen::Vector4d(dq.w(), dq.x(), dq.y(), dq.z());
  if (loads) {
    loads->water = w;
    loads->air = a;
    loads->gravity_N = g;
  }
  return d;
}

void rigid_body_rhs(const Stone& stone, const Environment& env, const double* y, double* dydt,
                    const WaterSurface* surface, std::vector<FacePush>* pushes, const LoadMode* mode) {
  to_vector(rigid_body_rhs(stone, env, from_vector(y), surface, nullptr, pushes, mode), dydt);
}

void to_vector(const StateDerivative& d, double* dydt) {
  for (int i = 0; i < 3; ++i) {
    dydt[kPosition + i] = d.dposition[i];
    dydt[kVelocity + i] = d.dvelocity[i];
    dydt[kAngularMomentum + i] = d.dangular_momentum[i];
  }
  for (int i = 0; i < 4; ++i) dydt[kQuaternion + i] = d.dquaternion[i];
}

double fluid_power_W(const Stone& stone, const Environment& env, const RigidState& s, const WaterSurface* surface) {
  const WaterLoads w = water_loads(stone, env, s, surface);
  const AirLoads a = air_loads(stone, env, s);
  if (env.attitude == Attitude::held) return (w.force_N + a.force_N).dot(s.velocity_m_s);  // torques discarded
  const Vec3 omega = angular_velocity(stone, s);
  return (w.force_N + a.force_N).dot(s.velocity_m_s) + w.torque_N_m.dot(omega);
}

Energy mechanical_energy(const Stone& stone, const Environment& env, const RigidState& s) {
  Energy e;
  e.translational_J = 0.5 * stone.mass.mass_kg * s.velocity_m_s.squaredNorm();
  e.rotational_J = 0.5 * angular_velocity(stone, s).dot(s.angular_momentum_kg_m2_s);
  e.potential_J = stone.mass.mass_kg * env.gravity_m_s2 * s.position_m.z();
  return e;
}

}  // namespace stoneskip
