#pragma once
// The reference solution of the stone's equations of motion (model/README.md §1.3–1.6): the same right-hand
// side as the real-time stepper (model/stone/rigid_body.hpp, every water law of
// model/stone/water_laws.hpp), integrated by SUNDIALS CVODE with tight tolerances. The right-hand
// side is only piecewise smooth, so CVODE's root finding locates every vertex crossing the surface
// (and, with RestartStrategy::every_event, every wet face whose normal velocity changes sign and
// the reversal of the air flow over the disk); ReferenceOptions::restart says where the
// integration restarts (CVodeReInit) and where it steps on across the kink. Fills the same
// ThrowResult as the real-time stepper, with located contact times.
//
// Still water only (η = 0; there is no WaterSurface argument): the event functions and the claim
// that the clipped area is smooth between vertex crossings hold for a flat surface.
// Events (solvers/realtime/stone_events.hpp): every vertex crossing z = 0 (contact starts when the
// first vertex goes under, ends when the last comes out, the stone sinks when all are under); in
// the physical convention with every_event also the switch of Eq. 2 on every wet face and the air
// switch of Eq. 6. In the paper convention the force ∝ u² is smooth in u.
// Tolerances: rtol, and atol per component (solvers/reference/absolute_tolerance.hpp).
// BDF: Newton with a dense direct solver and CVODE's difference-quotient Jacobian; Adams:
// fixed-point iteration. The quaternion is renormalised at every restart.
// Statistics are summed over segments (segments = restarts + 1); rhs_evaluations includes those of
// the Jacobian; contact_steps are the steps taken while some vertex was under water.
#include "solvers/realtime/throw_result.hpp"
#include "solvers/reference/reference_options.hpp"

namespace stoneskip {

// Never throws for numerical trouble: a failed solve returns outcome == Outcome::failed with the
// reason in outcome_detail (a NaN in the state or a root function, CVODE's error flag, too many
// steps, a SUNDIALS call that failed), and keeps every contact found before the failure (a contact
// still open then ends at the failure time, and outcome_detail says so). An invalid problem
// (options, a stone without size, environment_problem()) fails at t = 0.
ThrowResult run_reference(const Stone& stone, const Environment& env, const RigidState& initial,
                          const ReferenceOptions& options);

}  // namespace stoneskip
