#pragma once
// Distances between two states of the stone, and fixed-step integration of the real-time scheme
// without any contact logic (for order studies on a chosen interval).
#include "model/stone/rigid_body.hpp"
#include "solvers/realtime/stone_stepper.hpp"

namespace stoneskip {

// One dimensionless number for "how far apart are two states": the largest of
//   |Δx| / R (position in stone radii), |Δv| / |v_ref|, the rotation angle between the two
//   orientations (radians), |ΔL| / |L_ref| (or / (I_zz · 1 rad/s) when L_ref is nearly zero).
// None is exactly zero for all schemes (free flight is not exactly quadratic: the air force and
// the spin make it a general ODE). Each part converges at least at the scheme's order; one can
// converge faster: on a steady spin (ω constant, as in torque-free flight about the symmetry axis)
// a three-stage third-order scheme (bs32's fixed-step member) advances the quaternion by
// 1 + iφ − φ²/2 − iφ³/6 (φ = ω h / 2), whose phase error is φ⁵/30 per step once the quaternion is
// renormalised (arctan of the ratio against tan φ = φ + φ³/3 + 2φ⁵/15), so its orientation
// converges at order 4 while its position converges at 3.
double state_error(const Stone& stone, const RigidState& s, const RigidState& ref);
// The parts alone: |Δx| / R, and the rotation angle between the two orientations (radians).
double position_error(const Stone& stone, const RigidState& s, const RigidState& ref);
double orientation_error(const RigidState& s, const RigidState& ref);

// N equal steps of the scheme from s over a time T (no contact logic, no step-size switching).
RigidState integrate_fixed(const Stone& stone, const Environment& env, const RigidState& s, double T_s, int steps,
                           Scheme scheme, long* rhs_evaluations = nullptr);

}  // namespace stoneskip
