#pragma once
// The scene keys of a stone case (documented in cases/README.md, "A stone on live water"):
//   [water]          a live height field under the stone: the wave case's [water] keys (without
//                    t_end_s), where it lies (origin_x_m, origin_y_m), how it is coupled to the
//                    stone (coupling, draught_samples) and how it is computed (precision, threads,
//                    mode, tile_cells, epsilon_m);
//   [water.initial]  the surface at t = 0 (at rest; optional: still water);
//   [scene]          the frames of `stoneskip scene`: frame_rate_hz, duration_s (optional), and how
//                    the water's unforced steps are taken (free_water).
// Read strictly (an unknown key is an error) with one-line errors naming the file, line and key;
// a two-way field above the coupled stability limit (model/README.md §2.4) is refused at water.dt_s.
#include <optional>
#include <string>

#include "model/water/disturbance.hpp"
#include "model/water/height_field.hpp"
#include "solvers/scene/coupled_scene.hpp"
#include "tools/io/toml_table.hpp"

namespace stoneskip {

// A live water surface under the stone (optional [water] in a stone case): a height field
// stepped alongside the stone, its grid point (0, 0) at (origin_x_m, origin_y_m) of the throw's
// frame, starting at rest from a disturbance (or still), coupled to the stone as `coupling` says.
struct WaterScene {
  HeightFieldOptions field;
  std::optional<Disturbance> initial;  // absent: still water
  double origin_x_m = 0, origin_y_m = 0;
  Coupling coupling = Coupling::one_way;
  // What forces the water under two_way (model/README.md §2.4): the stone's pressure in both
  // conventions. The paper convention keeps the stone's printed equations (Lee & Baek 2013
  // Eq. 1–6); how the water is forced is not among them, so the convention does not choose it,
  // and with pressure the water receives what the stone receives in either.
  Forcing forcing = Forcing::pressure;
  int draught_samples = 8;             // K samples of b per water step (two_way, displacement)
  double head_width_m = 0;             // two_way, pressure: SceneOptions::head_width_m (0: a fixed number of cells)
  LevelInTime level_in_time = LevelInTime::held;  // SceneOptions::level_in_time
};

// [scene]: the frames. Without a duration the scene lasts the stone's t_max_s.
struct SceneFrames {
  double frame_rate_hz = 90;
  std::optional<double> duration_s;
  FreeWater free_water = FreeWater::to_the_next_frame;  // SceneOptions::free_water (bit-identical choices)
};

// Reads [water] (and [water.initial]) and [scene] from a stone case's top table, if present.
void read_scene_keys(TomlTable& top, std::optional<WaterScene>& water, SceneFrames& frames);

// The same settings as TOML, after defaults and overrides (for a case's resolved_settings()).
std::string scene_settings_toml(const std::optional<WaterScene>& water, const SceneFrames& frames);

}  // namespace stoneskip
