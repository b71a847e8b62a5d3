#pragma once
// Options of the CVODE reference solution of the stone's equations of motion.
#include <string>

namespace stoneskip {

// bdf:   CVODE BDF (orders 1–5), Newton iteration with a dense direct linear solver and CVODE's
//        finite-difference Jacobian.
// adams: CVODE Adams–Moulton (orders 1–12), Newton-free fixed-point (functional) iteration.
enum class ReferenceMethod { bdf, adams };
const char* to_string(ReferenceMethod m);
bool parse_reference_method(const std::string& s, ReferenceMethod& out);

// Where the integration restarts (CVodeReInit: order 1, a fresh step-size estimate, the quaternion
// renormalised). Every vertex crossing the surface is always located by root finding and logged
// (contact starts and ends, the sinking); the strategies differ in what else is located and where
// CVODE's multistep history is thrown away (solvers/realtime/stone_events.hpp says which points
// are non-smooth and how):
//   every_event:    also locate each wet face's switch u_i = 0 and the air switch (physical
//                   convention); restart at every located event.
//   every_crossing: restart at every vertex crossing; switches are not located.
//   at_jumps:       restart only where the right-hand side jumps — a face lying in the surface when
//                   it reaches or leaves it (a flat face: its wetted area jumps); none of the water
//                   laws jumps at its switch — and where a contact starts (the step that found the
//                   first vertex under may come from flight, long enough to hold a whole
//                   submersion; in the paper convention a fully submerged stone's opposite faces
//                   cancel, so the error test sees flight at both ends of such a step). Elsewhere
//                   the force is continuous (a slanted face's area grows from zero; every law is
//                   zero at its switch) and CVODE steps across the kink under its error control.
// No strategy locates the savitsky distributions' own switches (model/stone/load_switches.hpp):
// CVODE steps across them, their jumps included, under its error control (solvers/README.md).
// Where one face's loaded-region switch attracts from both sides (a sliding mode: a lens stone's
// planing exit), no step can cross it and the step collapses; the solve then restarts on
// Filippov's sliding field along it and leaves at the located exit (filippov_sliding.hpp; every
// strategy).
//   never:          never restart; CVODE's error control alone handles every kink and jump. Not
//                   safe where the force jumps: a step can carry the stone over a whole feature
//                   whose ends look alike (cvode_stone_test shows a flat plate that falls through
//                   the water unslowed in the paper convention).
enum class RestartStrategy { every_event, every_crossing, at_jumps, never };
const char* to_string(RestartStrategy r);
bool parse_restart_strategy(const std::string& s, RestartStrategy& out);

// How atol applies to the 13 state components (CVodeSVtolerances; solvers/reference/absolute_tolerance.hpp):
//   per_component: atol is the tolerance on positions (m); velocities, the quaternion and the
//                  angular momentum get the tolerance that moves the stone's rim by the same amount,
//                  from the stone's size, mass distribution and the throw's speed and spin.
//   uniform:       atol on every component in SI units (what the reference once did:
//                  far looser on the angular momentum of a slow stone, ~1e-5 kg m²/s, than on
//                  positions).
enum class ToleranceScaling { per_component, uniform };
const char* to_string(ToleranceScaling t);
bool parse_tolerance_scaling(const std::string& s, ToleranceScaling& out);

struct ReferenceOptions {
  ReferenceMethod method = ReferenceMethod::bdf;
  double rtol = 1e-10;
  double atol = 1e-12;          // absolute tolerance on positions (m); see atol_scaling
  ToleranceScaling atol_scaling = ToleranceScaling::per_component;
  double t_max_s = 10.0;
  double output_dt_s = 1e-3;    // trajectory sampling (interpolated: the steps do not depend on it); located events are always sampled
  long max_steps = 2000000;     // over the whole throw; exceeding it fails the solve
  bool record_trajectory = true;
  // The default is the cheapest strategy whose contact times stay within the stated tolerance of
  // an every_event solve (measured in verification/stones/work_precision.hpp; solvers/README.md).
  RestartStrategy restart = RestartStrategy::at_jumps;
  double max_step_s = 0;        // CVODE's largest step; 0: no limit
  // Chattering guard: the solve fails when more than this many events fall within 1 ms.
  int max_events_per_ms = 1000;
  // Step-collapse guard: the solve fails when this many steps advance it by less than 1 ms
  // (checked on consecutive windows of that many steps). A right-hand side that is singular or
  // discontinuous where no event is located (a sliding mode) shrinks the step without bound;
  // without the guard such a solve spins until max_steps.
  long max_steps_per_ms = 20000;
};

}  // namespace stoneskip
