#pragma once
// A stone case file (TOML, documented in cases/README.md) resolved into the model and solver
// structs: [stone], [environment], [throw] (or [throw.state]), [solver], optional [reference].
// Every error is a one-line InputError naming the file and the line or key.
#include <string>
#include <vector>

#include <optional>

#include "model/stone/throw.hpp"
#include "model/water/disturbance.hpp"
#include "model/water/height_field.hpp"
#include "solvers/realtime/stone_stepper.hpp"
#include "solvers/reference/reference_options.hpp"
#include "tools/scene/scene_case.hpp"  // [water], [scene]: WaterScene, SceneFrames
#include "tools/io/toml_table.hpp"

namespace stoneskip {

enum class StoneShape { prism, lens, mesh_file };

struct StoneSpec {
  StoneShape shape = StoneShape::prism;
  double radius_m = 0;
  double thickness_m = 0;
  int segments = 11;
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
StoneCase stone_case_from_document(const TomlDocument& doc);

// Builds the stone of a spec (mesh, mass properties). Throws InputError (key "stone.*").
Stone build_stone(const StoneSpec& spec, const std::string& file);

}  // namespace stoneskip
