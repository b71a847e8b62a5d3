#pragma once
// The scene studies: every question the scene report answers, as a function
// from settings (cases/studies/scene*.toml) to findings (verification/study/record.hpp), section
// by section:
//   settings     the scenes studied and the settings;
//   coupling     two-way against one-way against still water on each shipped throw: contacts,
//                bounces, first touches, and why they differ (the draught, the depression under
//                the stone, the contact's duration against footprint/c);
//   stability    the coupled limit of model/README.md §2.4 on either side (a held stone);
//   convergence  the forced leapfrog against the forced spectral reference (model/README.md §2.5);
//   rings        a bounce's ring speed against c less the scheme's dispersion;
//   shortcuts    each way of computing less (no field, active tiles, float32, one draught sample,
//                the contact step only near the water): its error and the time it saves;
//   grid         the coupled scene on finer grids: does its water response converge?
//   speed        the headline speed figures against their targets;
//   frames       the most telling still of each scene.
// Each section's record holds the numbers, tables, verdicts and computed reasons the report
// formats (reports/scene/); nothing in the report decides a verdict.
// Files: settings, stability, convergence and rings here (scene_studies.cpp); coupling, shortcuts,
// speed and frames in scene_{coupling,shortcut,speed,frame}_findings.cpp; what they share in
// scene_findings_support.hpp.
#include <optional>
#include <string>
#include <vector>

#include "model/water/disturbance.hpp"
#include "solvers/scene/coupled_scene.hpp"
#include "verification/scene/coupled_stability.hpp"
#include "verification/scene/headline_speed.hpp"
#include "verification/scene/ring_speed.hpp"
#include "verification/scene/scene_still.hpp"
#include "verification/study/study_sink.hpp"
#include "verification/waves/forced_convergence.hpp"

namespace stoneskip {

struct SceneStudyCase {
  std::string name;   // [a-z0-9_], e.g. "seed_8ms"
  std::string title;
  std::string file;   // where it came from (for the report's words)
  SceneOptions scene; // as the case says (two-way for the shipped scenes)
  // The case's initial surface as a shape ([water.initial]; scene.water->initial_m holds its samples
  // on the case's own grid): the grid section samples it afresh on its own grids. Empty: still
  // water, or heights given without a shape (which the grid section cannot resample).
  std::optional<Disturbance> initial;
};

struct SceneCouplingOptions {
  double time_tolerance_s = 1e-4;   // a first contact moved by less is "no visible change"
  // The bounce counts are compared on ensembles (verification/study/ensemble_difference.hpp): each
  // setting runs this many throws with the speed perturbed relatively by ±[smallest, largest].
  int ensemble_members = 16;
  double perturbation_smallest = 1e-9, perturbation_largest = 1e-4;
};

struct SceneConvergenceOptions {
  std::vector<std::string> stencils{"five_point", "nine_point_half", "nine_point_isotropic", "paper_eq11"};
  ForcedConvergenceOptions forced;
};

struct SceneShortcutOptions {
  std::string case_name;                          // which scene (default: the first)
  std::vector<double> epsilons_m{1e-7, 1e-6, 1e-5};  // active tiles with ε > 0
  int tile_cells = 32;
  int repeats = 3;                                // timed runs per variant (the least is kept)
  long checkpoint_every = 30;                     // frames between field comparisons
  double field_tolerance = 1e-3;                  // largest |Δz| / largest |z| called "within tolerance"
  double time_tolerance_s = 1e-4;                 // largest contact-time change called "within tolerance"
};

// Does the coupled scene converge? The scene on its own grid and on grids of half, a quarter and
// an eighth of its cell (the water step scaled alike, σ fixed), on a pond of pond_m × pond_m around
// the first touch (found on still water), until the first contact has ended and `after_s` more: the
// pressure work put into the waves and the first contact's duration and exit speed, whose
// successive differences must shrink as the cells halve. Then the same grids again with the head
// smoothed to each of `head_widths_m` in metres (SceneOptions::head_width_m), not over a fixed
// number of cells: does a head of fixed width make the scene converge? And at the case's own cell,
// the water step alone refined, with the level the stone reads held and extrapolated.
struct SceneGridOptions {
  std::string case_name;                           // which scene (default: the first)
  std::vector<double> cell_fractions{1, 0.5, 0.25, 0.125};  // of the case's cell, coarse to fine (≥ 3)
  double pond_m = 2;
  double after_s = 0.05;
  std::vector<double> head_widths_m{0.02};         // each > 0 (may be empty: pressure forcing only)
  // The level between water steps (scene_step_findings.hpp): at the case's own cell, water steps of
  // these fractions of its own (≥ 2, coarse to fine), the stone reading the level held and
  // extrapolated, against a step of reference_step_fraction (below the finest).
  std::vector<double> step_fractions{1, 0.5, 0.25, 0.125};
  double reference_step_fraction = 1.0 / 64;
};

struct SceneStudiesOptions;
// Why the grid section cannot run its case ("" if it can): a case starting from a disturbed
// surface the section's ponds (other grids) cannot sample afresh: heights without a shape, or an
// impulse (one cell's height).
std::string grid_case_problem(const SceneStudiesOptions& o);

struct SceneSpeedOptions {
  HeadlineSpeedOptions headline;                  // its scene is the first case's unless set
  double scene_fps_target = 3000, bandwidth_fraction_target = 0.9, per_cell_ratio_target = 2, throws_per_s_target = 1000;
};

struct SceneStudiesOptions {
  std::string preset = "full";
  std::vector<SceneStudyCase> cases;
  double duration_cap_s = 0;                      // > 0: every scene cut to this (quick presets)
  SceneCouplingOptions coupling;
  CoupledStabilityOptions stability;
  SceneConvergenceOptions convergence;
  std::string rings_case;                         // default: the first case
  RingSpeedOptions rings;
  SceneShortcutOptions shortcuts;
  SceneGridOptions grid;
  SceneSpeedOptions speed;
  StillFrameOptions frames;
  double stability_growth_tolerance = 1e-3;
  bool valid(std::string* why) const;
};

// The sections in order, each stored in the sink as it finishes (names: "settings", "coupling",
// "stability", "convergence", "rings", "shortcuts", "grid", "speed", "frames"), and the report's summary
// record.
Record run_scene_studies(const SceneStudiesOptions& options, StudySink& sink);

Record scene_settings_findings(const SceneStudiesOptions& o);
Record scene_coupling_findings(const SceneStudiesOptions& o, const ProgressFactory& progress);
Record scene_stability_findings(const SceneStudiesOptions& o);
Record scene_convergence_findings(const SceneStudiesOptions& o, const ProgressFactory& progress);
Record scene_rings_findings(const SceneStudiesOptions& o);
Record scene_shortcuts_findings(const SceneStudiesOptions& o, const ProgressFactory& progress);
Record scene_grid_findings(const SceneStudiesOptions& o, const ProgressFactory& progress);
Record scene_speed_findings(const SceneStudiesOptions& o, const ProgressFactory& progress);
Record scene_frames_findings(const SceneStudiesOptions& o, const ProgressFactory& progress);

}  // namespace stoneskip
