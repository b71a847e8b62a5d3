#pragma once
// The reference solution of the stone's equations of motion (spec §1.3–1.6): the same right-hand
// side as the real-time stepper (model/stone/rigid_body.hpp), integrated by SUNDIALS CVODE with
// tight tolerances. The right-hand side is only piecewise smooth, so CVODE's root finding locates
// every vertex crossing the surface and every submerged triangle whose normal velocity changes
// sign, and the integration restarts there (CVodeReInit); statistics are summed over segments.
// Fills the same ThrowResult as the real-time stepper, with located contact times.
#include "solvers/realtime/throw_result.hpp"
#include "solvers/reference/reference_options.hpp"

namespace stoneskip {

// Never throws for numerical trouble: a failed solve returns outcome == Outcome::failed with the
// reason in outcome_detail (a NaN in the state or a root function, CVODE's error flag, too many
// steps).
ThrowResult run_reference(const Stone& stone, const Environment& env, const RigidState& initial,
                          const ReferenceOptions& options);

}  // namespace stoneskip
