#pragma once
// The stone's equations of motion (model/README.md §1.3):
//   m dv/dt = F_gravity + F_air + Σ F_i      dx/dt = v
//   dL/dt   = τ_air + Σ τ_i                  dq/dt = ½ (0, ω) ⊗ q,  ω = R I_body⁻¹ Rᵀ L
// as a function of a state, shared by every integrator. With env.attitude == held, dL/dt = 0 and
// dq/dt = 0 (the torques are discarded; model/stone/environment.hpp).
#include "model/stone/fluid_forces.hpp"

namespace stoneskip {

struct StateDerivative {
  Vec3 dposition = Vec3::Zero();
  Vec3 dvelocity = Vec3::Zero();
  Eigen::Vector4d dquaternion = Eigen::Vector4d::Zero();  // (w, x, y, z)
  Vec3 dangular_momentum = Vec3::Zero();
};

struct Loads {
  WaterLoads water;
  AirLoads air;
  Vec3 gravity_N = Vec3::Zero();
};

// Right-hand side. `loads` (optional) receives the forces it used; `pushes` (optional) each wetted
// face's push (water_loads), for a scene that forces its water with them; `mode` (optional) the
// distributed pressure's loaded region held over a step (LoadMode in fluid_forces.hpp).
StateDerivative rigid_body_rhs(const Stone& stone, const Environment& env, const RigidState& s,
                               const WaterSurface* surface = nullptr, Loads* loads = nullptr,
                               std::vector<FacePush>* pushes = nullptr, const LoadMode* mode = nullptr);
// A derivative as a flat array (kStateSize doubles, the state's layout).
void to_vector(const StateDerivative& d, double* dydt);
// The same on flat arrays (kStateSize doubles each), for generic integrators and CVODE.
void rigid_body_rhs(const Stone& stone, const Environment& env, const double* y, double* dydt,
                    const WaterSurface* surface = nullptr, std::vector<FacePush>* pushes = nullptr,
                    const LoadMode* mode = nullptr);

// Rate at which water and air do work on the stone: P = F·v + τ·ω with the total fluid force and
// torque as applied (model/README.md §1.6). Never positive in the physical convention.
double fluid_power_W(const Stone& stone, const Environment& env, const RigidState& s,
                     const WaterSurface* surface = nullptr);

struct Energy {
  double translational_J = 0;
  double rotational_J = 0;
  double potential_J = 0;  // m g z
  double total_J() const { return translational_J + rotational_J + potential_J; }
};
Energy mechanical_energy(const Stone& stone, const Environment& env, const RigidState& s);

}  // namespace stoneskip
