#pragma once
// Per-component absolute tolerances of the CVODE reference (CVodeSVtolerances).
// One scalar atol on all 13 components of [x, v, q, L] asks for very different accuracies: 1e-12
// is 1e-12 of a 1 m position but 1e-7 of the 1e-5 kg m²/s angular momentum of a slow stone. Here
// ReferenceOptions::atol is the tolerance on positions (m), and every other component gets the
// tolerance whose effect on the stone is the same displacement of its rim, from three scales of
// the stone and the throw:
//   ℓ  = the stone's bounding radius (m): how far the geometry of the contact reaches;
//   V  = |v₀| + |ω₀| ℓ, at least √(g ℓ) (m/s): the fastest a point of the stone moves at release
//        (√(g ℓ): the speed of a stone dropped from rest, falling one radius; ℓ per second for a
//        stone at rest without gravity);
//   L₀ = I_min V / ℓ (kg m²/s): the angular momentum that turns the rim at V about the principal
//        axis of least inertia (the most sensitive one).
// Tolerances: position atol; velocity atol·V/ℓ (over the time ℓ/V in which a contact develops, a
// velocity error moves the stone by atol); quaternion atol/ℓ (an attitude error that moves the rim
// by atol); angular momentum atol·L₀/ℓ (the angular-velocity error atol·V/ℓ² of the least-inertia
// axis moves the rim at atol·V/ℓ, like the velocity tolerance).
#include "solvers/realtime/state_scales.hpp"
#include "solvers/reference/reference_options.hpp"

namespace stoneskip {

// The 13 absolute tolerances (per_component as above; uniform: atol everywhere).
StateVector absolute_tolerances(const ReferenceOptions& o, const StateScales& scales);

}  // namespace stoneskip
