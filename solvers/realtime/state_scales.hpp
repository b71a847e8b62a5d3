#pragma once
// Three scales of a stone and its throw, from which both the CVODE reference and the adaptive
// real-time stepper set per-component absolute tolerances that move the stone's rim alike
// (solvers/reference/absolute_tolerance.hpp gives the reasoning):
//   ℓ  = the stone's bounding radius (m);
//   V  = |v₀| + |ω₀| ℓ, at least √(g ℓ) (m/s): the fastest a point of the stone moves at release;
//   L₀ = I_min V / ℓ (kg m²/s): the angular momentum that turns the rim at V about the principal
//        axis of least inertia.
#include "model/stone/rigid_state.hpp"

namespace stoneskip {

struct StateScales {
  double length_m = 1;
  double speed_m_s = 1;
  double angular_momentum_kg_m2_s = 1;
};

StateScales state_scales(const Stone& stone, const RigidState& initial, double gravity_m_s2);

// Per-component absolute tolerances from a tolerance on positions (m): velocity atol·V/ℓ,
// quaternion atol/ℓ, angular momentum atol·L₀/ℓ.
StateVector scaled_absolute_tolerances(double atol_m, const StateScales& scales);

}  // namespace stoneskip
