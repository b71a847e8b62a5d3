#pragma once
// The seed's system, whole (Lee & Baek 2013 §3–4; model/README.md §2.4): a stone stepped by the
// real-time stepper (solvers/realtime/stone_stepper.hpp) on a live height field
// (model/water/height_field.hpp), run frame by frame for a set duration whether or not the stone
// has sunk, with what each part cost.
//
// Coupling (model/README.md §2.4):
//   none     no field at all: the stone on still water (η = 0). The cheapest scene, and the
//            throw is the still-water throw bit for bit.
//   one_way  the stone is clipped against the field's surface (bilinear between grid points,
//            model/water/height_field_surface.hpp); the field runs free.
//   two_way  and the stone forces the field, z_tt = c²∇²(z + h) − μ z_t (the forced leapfrog,
//            HeightField::step(DraughtPatch)), with the head h chosen by SceneOptions::forcing:
//   pressure      h = p_s/(ρ_w g), what the stone's faces press on the water with
//                 (model/coupling/pressure_head.hpp: each face's push of the water law, rasterised
//                 conservatively), so the water receives the stone's vertical impulse, opposite.
//                 Evaluated at the start of every stone step and held over it (the semi-implicit
//                 stepper's own quadrature of the stone's impulse): the faces' pushes are the ones
//                 the stepper's own right-hand side computed there (run_realtime's
//                 step_start_pushes), rasterised at the step's end; the binomial smoothing, linear,
//                 is applied once to each water step's sum. Step k's head over [t_k, t_k+1]
//                 goes to the water steps whose hats cover it, with the leapfrog's hat weights
//                 h̄ⁿ = (1/Δt) ∫ hatₙ(t) h(t) dt, hatₙ = max(0, 1 − |t − t_n|/Δt)
//                 (the exact weights of a second difference: z(t+Δt) − 2z(t) + z(t−Δt) =
//                 ∫ hat z_tt), so the forced step stays second order in Δt under a footprint that
//                 jumps between grid cells. The field's level n is the surface the stone sees during
//                 [t_n, t_n+1) (held, or extrapolated from levels n − 1 and n: SceneOptions::
//                 level_in_time): step n needs h up to t_n+1.
//   displacement  h = b, the stone's draught (model/coupling/draught.hpp; the first model, kept
//                 for comparison: model/README.md §2.4). The field's level n is the surface the
//                 stone sees during [t_n − Δt/2, t_n + Δt/2); when the stone's clock passes
//                 t_n + Δt/2 the field steps, forced by the window's draught
//                 (solvers/scene/draught_window.hpp: K samples per step, K = 1 the spec's point
//                 sample at t_n), each sample taken at the start of the first stone step at or
//                 after its time.
// Both record the water's vertical impulse on the stone (its momentum change less gravity's and the
// air's, step by step) and the vertical impulse the water received, Σ Δt Σ h̄ ρ_w g d² over the
// water's steps, and (with
// energy_budget) the waves' energy budget of solvers/scene/wave_energy.hpp.
// Stability (model/README.md §2.4): under a floating stone b follows z with unit gain, so the two-way step
// is stable only for σ = cΔt/d ≤ coupled_courant_limit(stencil) = the free limit / √2. A scene
// above it is refused (SceneOptions::valid), not run: the growth there is geometric from the
// first steps (model/coupling/two_way_test.cpp: ×1.55 per step 3 % above the limit).
// After the stone's throw ends (it sank, or reached its own t_max) the stone leaves the scene: its
// draught is no longer applied, and the water runs on to the scene's end.
//
// Frames: frame k (k = 1 … N, N = ⌊duration · rate⌋) ends at t = k/rate; at its end the
// recorder (optional) sees the field's current level and the stone at the first step start at or
// after that time (within one stone step: 1 ms in flight, one contact step near the water).
// Cost: each frame's thread CPU time and wall time (a thread-CPU reading costs microseconds on a
// virtual machine, so it is read once per frame), and the frame's wall time split into parts with
// the steady clock (tens of ns a reading): draught (sampling b and adding it to the window), water
// (field steps), recording (the recorder), stone (the rest: the stepper, its clipping against the
// field, the loop's own bookkeeping). With field threads > 1 the thread CPU time leaves out the
// field's workers: read the wall times.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "model/coupling/draught.hpp"
#include "model/water/height_field.hpp"
#include "model/water/height_field_surface.hpp"
#include "solvers/realtime/stone_stepper.hpp"

namespace stoneskip {

enum class Coupling { none, one_way, two_way };
const char* to_string(Coupling c);
bool parse_coupling(const std::string& s, Coupling& out);

// What forces the water under two-way coupling (model/README.md §2.4).
enum class Forcing { pressure, displacement };
const char* to_string(Forcing f);
bool parse_forcing(const std::string& s, Forcing& out);

// Binomial passes over the pressure head (model/coupling/pressure_head.hpp, smooth_conservatively):
// the seed's 3 cm stone on 2 cm cells forces mostly at the grid scale. Measured (3 s scenes): the
// final waves' energy at |k| d > π/2 is 40 / 9.9 / 2.9 / 0.8 % with 0 / 1 / 2 / 3 passes on
// seed_8ms, 88 / – / 8.4 / 2.5 % on seed_8ms_paper; three keep both under 5 %.
constexpr int kPressureSmoothingPasses = 3;

// A head of fixed width in metres (SceneOptions::head_width_m, model/README.md §2.4, "A head of
// fixed width"): m passes of the binomial filter spread a point by a variance of m/2 cells² per
// axis (each [1 2 1]/4 has variance ½), so a standard deviation w takes m = 2 (w/d)² passes,
// rounded to the nearest, and never fewer than kPressureSmoothingPasses (which keep the forcing
// off the grid's scale). w = 0: kPressureSmoothingPasses on every grid, a width of √1.5 cells.
// Returns 0 where the passes would exceed kMaxPressureSmoothingPasses (w/d > 8): each pass costs
// the patch's box, which grows by a point a side per pass (at 128 passes a 3 cm stone on 2.5 mm
// cells smooths a 150² box 128 times a water step).
constexpr int kMaxHeadWidthCells = 8;
constexpr int kMaxPressureSmoothingPasses = 2 * kMaxHeadWidthCells * kMaxHeadWidthCells;  // 128
int pressure_smoothing_passes(double head_width_m, double cell_m);

// How the field takes the steps that nothing forces (no head or draught waiting, no per-step
// damping loss measured): above all the ring phase after the throw. In flight the stone reads the
// surface at each of its steps (1 ms in the seed, inside one water step), so free steps come
// together only once it has left. All three give the same field bit for bit
// (HeightField::advance is n calls of step()); they differ in speed and in how cost is booked.
//   one_at_a_time      each step as a forced one (the reference the others are tested against).
//   to_the_next_frame  HeightField::advance over the free steps up to the frame's end (or the
//                      stone's next step): a temporal-blocked wavefront where the field is large.
//                      With one water step per frame (the seed) that is one step: nothing to block.
//   to_the_next_look   without a recorder nobody looks at the field before the scene's end, so
//                      the free steps after the throw run in one advance; the frames they span
//                      share its thread CPU and wall time by their water steps (the split is an
//                      even share, not a measurement of each frame). With a recorder: as
//                      to_the_next_frame.
enum class FreeWater { one_at_a_time, to_the_next_frame, to_the_next_look };
const char* to_string(FreeWater f);
const char* to_string(LevelInTime l);
bool parse_level_in_time(const std::string& s, LevelInTime& out);
bool parse_free_water(const std::string& s, FreeWater& out);

// How far a scene runs: to its duration whatever the stone does (watching it), or only as long as
// the stone's throw (`stoneskip run` on a case with [water]).
enum class SceneEnd { at_duration, with_the_throw };

struct SceneWater {
  HeightFieldOptions field;
  std::vector<double> initial_m;  // z(0) at rest, nx·ny row-major (empty: still water)
  FieldPlacement placement;       // where grid point (0, 0) lies in the throw's frame
};

struct SceneOptions {
  Stone stone;
  Environment environment;
  RigidState initial;
  RealtimeOptions stone_steps;     // its t_max_s is cut to the scene's end (SceneEnd::at_duration)
  Coupling coupling = Coupling::two_way;
  std::optional<SceneWater> water; // required unless coupling is none (then ignored)
  Forcing forcing = Forcing::pressure;  // two_way
  int draught_samples = 8;         // K per water step (two_way, displacement)
  // two_way, pressure: the head's standard deviation in metres (pressure_smoothing_passes); 0: a
  // fixed number of cells (the scene as the paper's real-time model would run it).
  double head_width_m = 0;
  // The level the stone reads between water steps (model/water/height_field_surface.hpp): the last
  // one held, or the line through the last two extrapolated to the stone step's start.
  LevelInTime level_in_time = LevelInTime::held;
  // Measure the waves' energy budget (solvers/scene/wave_energy.hpp): two transforms of the grid per
  // water step, so off where speed is measured.
  bool energy_budget = false;
  // Steps that nothing forces; with energy_budget on a damped field every step stays one at a
  // time (Dₙ is a quadratic form of each step's levels: no sum over several steps gives it).
  FreeWater free_water = FreeWater::to_the_next_frame;
  double frame_rate_hz = 90;       // one frame = 1/rate of simulated time
  double duration_s = 3;
  SceneEnd end = SceneEnd::at_duration;

  long frames() const;             // N = ⌊duration · rate⌋ (1e-9 slack for round-off)
  double end_s() const;            // N / rate
  // False with the first problem, naming the option, in *why (includes the coupled limit).
  bool valid(std::string* why = nullptr) const;
};

// What the stone is doing at a frame.
enum class StoneStatus { in_play, sank, ended };
const char* to_string(StoneStatus s);

// What the recorder sees at the end of a frame (pointers valid during the call only).
struct SceneFrame {
  long index = 0;                  // 1 … N
  double t_s = 0;                  // k / rate
  StoneStatus stone_status = StoneStatus::in_play;
  RigidState stone;                // in play: at the first step start ≥ t_s; else where it ended
  const HeightField* field = nullptr;  // nullptr for coupling none
  FieldPlacement placement;
  double draught_volume_m3 = 0;    // Σ b d² of the last sample taken (two_way)
};
using FrameRecorder = std::function<void(const SceneFrame&)>;

// One frame's cost.
struct FrameCost {
  double t_s = 0;
  double cpu_s = 0, wall_s = 0;    // thread CPU, wall
  double stone_wall_s = 0, draught_wall_s = 0, water_wall_s = 0, recording_wall_s = 0;
  double energy_budget_wall_s = 0;  // measuring the waves' energy budget (SceneOptions::energy_budget), not in water_wall_s
  int stone_steps = 0, water_steps = 0, draught_samples = 0;
};

// A run of consecutive draught samples with the stone in the water (two_way): how much it pressed
// on the water and how far the water under it had sunk — what makes two-way coupling differ from
// one-way (model/README.md §2.4: the depression forms on the time scale footprint/c).
struct DraughtEpisode {
  double start_s = 0, end_s = 0;     // first and last sample in the water
  double max_volume_m3 = 0;          // largest Σ b d² of a sample
  double volume_time_m3_s = 0;       // Σ over samples of Σ b d² · Δt/K
  double surface_at_start_m = 0;     // η under the stone's centre at the first sample
  double lowest_surface_m = 0;       // lowest η under the stone's centre over the samples
};

// The vertical impulse over one run of consecutive stone steps with the stone pressing on the
// water (pressure forcing): what the stone received (its momentum change less gravity's and the
// air's, step by step: SceneSummary::stone_vertical_impulse_N_s), and what the grid received from
// the rasterised head, Σ (Σ h ρ_w g d²) h (model/coupling/pressure_head.hpp) over the points the
// grid keeps (none beyond a pond's rim: there the water receives nothing).
struct ContactImpulse {
  double start_s = 0, end_s = 0;
  double stone_N_s = 0, water_N_s = 0;
};

// The waves' energy budget over the scene (solvers/scene/wave_energy.hpp):
// E_end − E_start = W − D up to round-off.
struct EnergyBudget {
  bool measured = false;
  double start_J = 0, end_J = 0;    // E^{n+½} at the first and the last level
  double pressure_work_J = 0;       // Σ Wₙ
  double damping_loss_J = 0;        // Σ Dₙ
  double grid_scale_fraction = 0;   // of E_end at |k| d > π/2
  // |E_end − E_start − W + D| / max(|W|, |E_end − E_start|, D): 0 when nothing moved.
  double residual() const;
};

struct SceneSummary {
  SceneOptions options_brief;      // the options as run, without the field's initial heights
  ThrowResult stone;               // the throw: contacts, bounces, trajectory, its own stats
  long frames = 0;
  double simulated_s = 0;          // frames / rate
  long water_steps = 0;
  // two_way. Displacement: the draught b's samples; pressure: the heads h = p/(ρ_w g), one per stone
  // step (the same fields: what forces the water, whichever it is).
  long draught_samples = 0;
  double max_draught_volume_m3 = 0;    // largest Σ b d² of one sample (pressure: Σ h d² of one head as rastered at its step's start, before scaling)
  double draught_impulse_m3_s = 0;     // ∫ Σ b d² dt as applied to the water (Σ over steps of Δt Σ b̄ d²; pressure: of h)
  std::vector<DraughtEpisode> episodes;  // two_way, displacement
  // two_way: the water's vertical impulse on the stone over its steps (up to the scene's end or
  // the throw's), from the stone's own momentum, step by step: m Δv_z + m g Δt less the air's
  // impulse (trapezoidal on the step's ends); it is what the stepper applied, under every scheme.
  // And the vertical impulse the field's steps received, Σ Δt Σ h̄ ρ_w g d² over the grid's points
  // (pressure: each step's head is scaled to carry the stone's impulse of that step, so the two
  // are equal up to what lies beyond a non-periodic pond's rim, a step that began dry, or the last
  // unfinished water step; displacement: ρ_w g times the draught's impulse, a different quantity).
  double stone_vertical_impulse_N_s = 0;
  double water_vertical_impulse_N_s = 0;
  // Pressure: the impulse the stone gave in its last pieces that the water steps taken had not yet
  // received when the scene ended (their hats reach past the end): the contacts' water impulses
  // sum to water_vertical_impulse_N_s plus this.
  double water_impulse_pending_N_s = 0;
  // Pressure: the stone steps whose head at the start could not carry the step's impulse within a
  // factor 0.1–10 (pushes that nearly cancel, a force changing sign): that impulse went on |h|.
  long heads_on_footprint = 0;
  // Pressure only: the runs of stone steps that began pressing. One ends with the last such step,
  // which can be before the contact's own end (a receding face under water presses with p = 0).
  std::vector<ContactImpulse> contact_impulses;
  EnergyBudget energy;
  double volume_start_m3 = 0, volume_end_m3 = 0;  // Σ z d² of the field at the start and the end
  ActiveTileSummary tiles;         // the field's (all tiles every step in full mode)
  std::vector<FrameCost> frame_costs;
  // Totals over the frames.
  double cpu_s = 0, wall_s = 0;
  double stone_wall_s = 0, draught_wall_s = 0, water_wall_s = 0, recording_wall_s = 0;
  double energy_budget_wall_s = 0;  // the budget's measurement: a diagnostic, not what the scene needs
  long slowest_frame = 0;          // by wall time
  double slowest_frame_wall_s = 0, slowest_frame_cpu_s = 0;
  double frames_per_s_cpu() const { return cpu_s > 0 ? frames / cpu_s : 0; }
  double frames_per_s_wall() const { return wall_s > 0 ? frames / wall_s : 0; }
  std::string brief() const;  // "270 frames (3 s) at 4100 frames/s CPU, 3900 wall; slowest frame 2.1 ms wall (#7)"
};

// What a stone-step recorder sees: the stone's state at the start of each of its steps, and its
// last state when the throw ends — the stone between frames (the movie's slow motion).
using StoneStepRecorder = std::function<void(double t_s, const RigidState& stone)>;

// Runs the scene; throws std::invalid_argument when the options are not valid.
SceneSummary run_scene(const SceneOptions& options, const FrameRecorder& recorder = {},
                       const StoneStepRecorder& stone_steps = {});

}  // namespace stoneskip
