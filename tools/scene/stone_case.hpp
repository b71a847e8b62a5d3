#pragma once
// A stone case file (TOML, documented in cases/README.md) resolved into the model and solver
// structs: [stone], [environment], [throw] (or [throw.state]), [solver], optional [reference].
// Every error is a one-line InputError naming the file and the line or key.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "model/stone/throw.hpp"
#include "model/water/disturbance.hpp"
#include "model/water/height_field.hpp"
#include "solvers/realtime/stone_stepper.hpp"
#include "solvers/reference/reference_options.hpp"
#include "tools/scene/scene_case.hpp"  // [water], [scene]: WaterScene, SceneFrames
#include "tools/io/toml_table.hpp"

namespace stoneskip {

// Plausibility bounds of the keys (documented per key in cases/README.md): inputs outside them are
// not a stone throw (a stone of 1e-30 m, water of density 0), and refused with the bound.
struct Bounds {
  double lo, hi;
};
constexpr Bounds kStoneRadius{1e-3, 10};        // radius_m, disk_radius_m, an OBJ stone's extent (m)
constexpr Bounds kStoneThickness{1e-4, 10};     // thickness_m (m)
constexpr Bounds kStoneDensity{1, 1e5};         // density_kg_m3, also as implied by mass_kg
constexpr Bounds kStoneMass{1e-6, 1e7};         // mass_kg, also as implied by density_kg_m3
constexpr long long kMaxSegments = 100000;      // segments
constexpr Bounds kReleaseHeight{0, 1e4};        // throw.height_m, the z of throw.state.position_m (m)
constexpr double kMaxPosition_m = 1e4;          // |x|, |y| of throw.state.position_m
constexpr double kMaxSpeed_m_s = 1000;          // throw.speed_m_s, each velocity component
constexpr double kMaxSpin_rev_s = 1000;         // |throw.spin_rev_s|
constexpr double kMaxAngularSpeed_rad_s = 1e4;  // |wobble_rad_s|, each angular velocity component
constexpr double kMinStep_s = 1e-9, kMaxStep_s = 1;            // solver dt_s, contact_dt_s
constexpr double kMinTolerance = 1e-14, kMaxTolerance = 0.1;    // solver rtol, atol_m (bs32)
constexpr double kAdaptiveLargestStep_s = 1e-2;  // bs32's dt_s when a case gives none: 3.6 turns at 60 rev/s
                                                 // in flight would fail its error test anyway
constexpr double kAdaptiveOutputStep_s = 1e-3;   // bs32's output_dt_s when a case gives none
constexpr long kMinRhsPerFrame = 4;          // bs32's budget: the first right-hand side and one trial step
constexpr long kMaxRhsPerFrame = 1000000;
constexpr double kMinDuration_s = 1e-6, kMaxDuration_s = 1e5;  // solver t_max_s
constexpr double kMaxStepsPerThrow = 1e9;       // t_max_s / contact_dt_s
constexpr double kMaxWaterOrigin_m = 1e6;       // |water.origin_x_m|, |water.origin_y_m|

enum class StoneShape { prism, lens, mesh_file };

struct StoneSpec {
  StoneShape shape = StoneShape::prism;
  double radius_m = 0;
  double thickness_m = 0;
  int segments = 11;
  RimSplit rim_split = RimSplit::diagonal;  // prism: how its rim faces are cut (model/stone/mesh.hpp)
  double density_kg_m3 = 0;  // one of density and mass is given
  double mass_kg = 0;
  std::string mesh_file;     // resolved relative to the case file's folder
};

struct StoneCase {
  std::string file;                    // path as given
  std::string text;                    // the case file's text, attached to results
  std::vector<std::string> overrides;  // --set assignments applied
  std::string title;                   // [case] title, or the file's stem
  StoneSpec spec;
  Stone stone;
  Environment environment;
  bool throw_from_parameters = true;   // false: [throw.state] gave the full state
  ThrowParameters throw_parameters;
  RigidState initial;
  RealtimeOptions realtime;
  ReferenceOptions reference;
  std::optional<WaterScene> water;     // absent: still water η = 0
  SceneFrames frames;                  // [scene]: the frames of `stoneskip scene`
  std::string resolved_settings() const;  // every setting, as TOML, after defaults and overrides
};

StoneCase load_stone_case(const std::string& path, const std::vector<std::string>& overrides = {});

// The first [solver] setting of the real-time stepper outside its bounds, as (key, what is wrong);
// none if all are in. Used for the case's [solver] and for a baseline's overrides of it.
std::optional<std::pair<std::string, std::string>> realtime_options_problem(const RealtimeOptions& o);
StoneCase stone_case_from_document(const TomlDocument& doc);

// Builds the stone of a spec (mesh, mass properties). Throws InputError (key "stone.*").
Stone build_stone(const StoneSpec& spec, const std::string& file);

}  // namespace stoneskip
