#pragma once
// A stone case as a scene (solvers/scene/coupled_scene.hpp): the case's stone, throw and solver,
// its [water] (a live height field, coupled as water.coupling says; none without [water]) and
// its [scene] frames. `stoneskip run` runs the scene as long as the throw; `stoneskip scene` to
// the scene's duration (default: the stone's t_max_s), whether or not the stone has sunk.
#include "solvers/scene/coupled_scene.hpp"
#include "tools/scene/stone_case.hpp"

namespace stoneskip {

// The scene's options from the case (the initial surface sampled on the grid).
SceneOptions scene_options(const StoneCase& c, SceneEnd end);

struct SceneThrow {
  ThrowResult result;
  long water_steps = 0;       // height-field steps taken
  double water_wall_s = 0;    // their wall time (within result.stats.wall_s)
};

// The throw on the case's water, for `stoneskip run`: the scene until the throw ends.
SceneThrow run_scene_realtime(const StoneCase& c);

}  // namespace stoneskip
