#pragma once
// Distances between two states of the stone, and fixed-step integration of the real-time scheme
// without any contact logic (for order studies on a chosen interval).
#include "model/stone/rigid_body.hpp"
#include "solvers/realtime/stone_stepper.hpp"

namespace stoneskip {

// One dimensionless number for "how far apart are two states": the largest of
//   |Δx| / R (position in stone radii), |Δv| / |v_ref|, the rotation angle between the two
//   orientations (radians), |ΔL| / |L_ref| (or / (I_zz · 1 rad/s) when L_ref is nearly zero).
// Every part converges at the scheme's order, and none is exactly zero for all schemes (free
// flight is not exactly quadratic: the air force and the spin make it a general ODE).
double state_error(const Stone& stone, const RigidState& s, const RigidState& ref);

// N equal steps of the scheme from s over a time T (no contact logic, no step-size switching).
RigidState integrate_fixed(const Stone& stone, const Environment& env, const RigidState& s, double T_s, int steps,
                           Scheme scheme, long* rhs_evaluations = nullptr);

}  // namespace stoneskip
