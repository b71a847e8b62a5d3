#pragma once
// The real-time stepper, quaternion renormalised after every step. Schemes (formal order):
//   semi_implicit_euler (1)  fixed steps; v, L from the forces at the start of the step, then x
//                            with the new v and q rotated by the new ω: the game-engine integrator.
//   midpoint (2), rk4 (4)    fixed steps, explicit Runge–Kutta on the flat state (model/README.md §1.3).
//   bs32 (3)                 adaptive: Bogacki–Shampine 3(2) with FSAL (adaptive_step.hpp), steps
//                            from rtol/atol_m, bounded where a vertex crosses the surface.
//   dp54 (5)                 adaptive as bs32, with Dormand–Prince 5(4) and its own continuous
//                            extension (events to order 5); everything said of bs32 below holds
//                            for it unless it says otherwise.
// Fixed schemes switch to contact_dt_s when the lowest vertex could reach the surface within one
// flight step (clearance < (|v| + |ω| r_bound) dt_s), so a flight step cannot carry it deep; bs32
// uses dt_s as its largest step and ignores contact_dt_s.
//
// Kinks (KinkSteps): the right-hand side is only piecewise smooth (stone_events.hpp (a)–(c): a
// vertex crossing the surface, a wet face's or the air disk's flow switching). A step taken across
// a kink makes a local error of O(h²)–O(h³) there whatever the scheme's order, so no scheme shows
// more than order 2–3 through a contact unless its steps end at the kinks. With `crossings` or
// `all`, a trial step over which a watched switching function changes sign is cut back to end just
// past its first root, located on the trial's cubic Hermite interpolant (dense_output.hpp), and
// taken again; the fixed schemes then resume their step from there.
//
// Sliding (bs32 in still water, sliding_steps.hpp): where the steps stall at a loaded-region switch
// that attracts from both sides (a sliding mode), bs32 steps on Filippov's sliding field
// (filippov_sliding.hpp) and cuts its trials at the sliding's exit, as at a kink.
//
// Budget (bs32 only, rhs_per_frame > 0): the real-time mode. Steps end on the frames' boundaries
// (frame_dt_s) and a frame spends at most rhs_per_frame right-hand sides: when the error test would
// need more, the step is taken at the size the remaining budget allows and accepted whatever its
// error. SolverStats then reports how many steps were forced, the largest error-test ratio accepted
// (1 = the tolerance) and the summed local error estimate of the positions: the error it made.
//
// Contacts (model/README.md §1.8) are located inside the step on the cubic Hermite interpolant of
// the step (dense_output.hpp: O(h⁴), so to the scheme's order up to 4; dp54's quartic extension
// O(h⁵)): a contact starts where the
// first vertex goes under (the first-touch point is that vertex there), ends where the last comes
// out, and the stone sinks where the last goes under; the state there is the interpolant's, and a
// throw that sinks ends at that time and state.
// A live surface (before_step) is piecewise constant in time: it changes at the start of the
// steps where before_step moves it. A contact that the water starts or ends, or a stone that the
// water covers, is logged at that step start — exactly when the modelled surface changed; against
// a surface moving continuously between its own levels that is within one water step (plus the
// stone step in which the change is applied).
#include <functional>
#include <optional>
#include <string>

#include "solvers/realtime/throw_result.hpp"

namespace stoneskip {

enum class Scheme { semi_implicit_euler, midpoint, rk4, bs32, dp54 };
const char* to_string(Scheme s);
bool parse_scheme(const std::string& s, Scheme& out);
int formal_order(Scheme s);
// The order at which the scheme's orientation converges in a steady spin (ω along a principal
// axis, no torque: q(t) = exp(½ ω t) q₀), the quaternion renormalised after every step. A
// Runge–Kutta step multiplies q by its stability polynomial R(z), z = ½ ω h a pure quaternion
// (z² = −x², x = |ω| h / 2), so R(z) = a(x) + b(x) ẑ with ẑ = z/x: a scaled rotation, whose angle is
// atan(b/a) and whose scale the renormalisation removes. For a scheme of order p,
// R(z) = e^z + C z^(p+1) + …: with p + 1 even, z^(p+1) is real, a change of scale, and moves the
// angle only at x^(p+2); with p + 1 odd it moves the angle at x^(p+1). So the angle's global order
// is p + 1 for odd p and p for even p: midpoint 2 (its angle error x³/6 a step), rk4 4 (−x⁵/120),
// bs32 4 (its third-order solution R = the cubic Taylor polynomial: x⁵/30), dp54 6 (R = the
// quintic Taylor polynomial + z⁶/600: x⁷ terms). The semi-implicit Euler step rotates exactly
// through |ω| h: exact in a steady spin (returned: its formal order, the errors then below any
// reference's). Tested on the stepper (stone_stepper_test.cpp); the stones report's flight
// interval expects it (verification/stones/realtime_convergence.cpp).
int steady_spin_order(Scheme s);
bool is_adaptive(Scheme s);  // steps from a tolerance (bs32, dp54), not from dt_s / contact_dt_s

// The adaptive scheme's tolerance (rtol = atol_m) where a case names none: the one the stones
// report's work-precision grid chooses by its stated rule (bounce counts equal to CVODE's on
// every throw of its grid, contact times within its threshold), and on the bench grid bs32's
// counts there equal CVODE's on 313 of 314 throws, 95 % Wilson interval 0.982–0.999 (at 1e-8:
// 307 of 314, 0.955–0.989, below the 98 % line). Measured: solvers/README.md.
constexpr double kDefaultAdaptiveTolerance = 1e-9;

// Which kinks of the right-hand side end a step (see above).
//   none       steps are taken across them (what a game engine does)
//   crossings  the vertex crossings: a step whose ends have different sets of vertices under water
//   all        every switching function of stone_events.hpp: the crossings and, in the physical
//              convention, each wet face's and the air disk's flow switch (a live surface is held
//              during the step, as the right-hand side holds it); under savitsky and
//              savitsky_wagner also the distribution's own (model/stone/load_switches.hpp: the
//              wetted span's ends, the raised waterline, the loaded region, …). A fixed scheme
//              then holds the loaded region over each step (LoadMode, fluid_forces.hpp), so that
//              none of its stages sees the loads jump where the region changes: the step cut back
//              to the change ends on the old branch, the next starts on the new; so does dp54,
//              whose sixth stage (c = 1, weight b₆ = 11/84 in its solution) lies a window past the
//              switch at a cut step's end: unheld, that step errs by 11/84 of its length × the jump,
//              which its estimate all but misses (with steps capped at 1e-4 s on
//              held_load_mode_test.cpp's throw: 1.6e-9 s on the first contact's end unheld, 9e-13 s
//              held). On the same throw at uncapped tolerances the hold changes that error little
//              (6.4e-10 … 3.9e-10 s held against 1.8e-9 … 4.9e-10 s over rtol 1e-7 … 1e-10): a second
//              floor, long cut steps outside dp54's asymptotic range, dominates there
//              (solvers/README.md, "The fifth-order pair"). bs32 does not hold: its solution gives
//              its stage at c = 1 weight 0, and held it kept the same bench counts for 4 % more
//              right-hand sides.
enum class KinkSteps { none, crossings, all };
const char* to_string(KinkSteps k);
bool parse_kink_steps(const std::string& s, KinkSteps& out);
// What a scheme does when a case names nothing: bs32 crossings (at rtol 1e-8 on the bench grid,
// `all` kept CVODE's count on the same 290 of 296 settled throws for 5.6× the CPU, 6 December, and
// was no more accurate in the contact times of single throws: solvers/README.md), dp54 all (its
// error estimate is all but blind to a jump in the loads inside a step: a jump of J in the first
// 80 % of a step moves its solution by up to 0.1 J h and its estimate by 0.0012 J h, so it must not
// step across the distribution's jumps: solvers/README.md, "The fifth-order pair"), the fixed
// schemes none (a fixed step is what a game engine takes).
KinkSteps default_kink_steps(Scheme s);

struct RealtimeOptions {
  Scheme scheme = Scheme::bs32; // the default stepper (what a case that names no scheme runs)
  double dt_s = 1e-3;           // fixed schemes: flight step; bs32: the largest step
  double contact_dt_s = 1e-4;   // fixed schemes: step while in or near the water
  double rtol = kDefaultAdaptiveTolerance;    // bs32: relative tolerance on every state component
  double atol_m = kDefaultAdaptiveTolerance;  // bs32: absolute tolerance on positions (m); the other
                                // components get the one that moves the rim as much (state_scales.hpp)
  std::optional<KinkSteps> kinks;  // none given: the scheme's (default_kink_steps)
  long rhs_per_frame = 0;       // bs32: at most this many right-hand sides per frame (0: no budget)
  double frame_dt_s = 1.0 / 90; // bs32 with a budget: the frame (the paper's > 90 frames/s)
  double t_max_s = 10.0;
  double output_dt_s = 1e-3;    // trajectory sampling (0: every step); contact transitions always
  bool record_trajectory = true;
  // bs32's step-collapse guard, as the reference's (ReferenceOptions::max_steps_per_ms): the run
  // fails when this many steps (at least twice the steps of dt_s, the largest, in 1 ms) advance it
  // by less than 1 ms (checked on consecutive windows). A contact too stiff for an explicit
  // scheme, or a vertex held at the surface (a sliding mode), shrinks the step without bound; bs32
  // takes about 10 steps a millisecond on a skipping throw. 0 or less: no guard.
  long max_steps_per_ms = 20000;
  // bs32: slide along an attracting loaded-region switch where the steps stall (sliding_steps.hpp).
  // false: step across it under the error control alone, as before (an oracle that shares no code
  // with the sliding field, for the reference's tests; it may collapse there).
  bool slide = true;
};

// One step of the scheme (no contact logic), for benchmarks and order studies. start_pushes
// (optional): the faces' pushes at s (FacePush), from the step's first right-hand side;
// stage_met_water (optional): set where a later stage (midpoint, rk4) felt the water's loads.
RigidState realtime_step(const Stone& stone, const Environment& env, const RigidState& s, double dt_s,
                         Scheme scheme, const WaterSurface* surface = nullptr, long* rhs_evaluations = nullptr,
                         std::vector<FacePush>* start_pushes = nullptr, bool* stage_met_water = nullptr);

// before_step (optional) is called with the time at the start of every step: a scene uses it to
// advance a live water surface to that time.
ThrowResult run_realtime(const Stone& stone, const Environment& env, const RigidState& initial,
                         const RealtimeOptions& options, const WaterSurface* surface = nullptr,
                         const std::function<void(double t_s)>& before_step = {});
// The same, with the stone's state at the start of the step handed to the callback as well: a
// two-way scene (solvers/scene/) computes the stone's draught on the water from it.
// step_start_pushes (optional): cleared after each call of before_step, then filled with the faces'
// pushes at the step's start state by the step's first right-hand side (left empty when no step
// follows), so a scene forced by them needs no second evaluation; read it in the next call.
using BeforeStepWithState = std::function<void(double t_s, const RigidState& s)>;
ThrowResult run_realtime(const Stone& stone, const Environment& env, const RigidState& initial,
                         const RealtimeOptions& options, const WaterSurface* surface,
                         const BeforeStepWithState& before_step, std::vector<FacePush>* step_start_pushes = nullptr);

}  // namespace stoneskip
