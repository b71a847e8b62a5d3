#pragma once
// Runs a stone case's throw with the real-time stepper on the case's water: still water, or a
// live height field ([water] in the case) stepped alongside the stone with its own leapfrog step
// and seen by the stone through bilinear interpolation (model/water/height_field_surface.hpp).
// The coupling is one-way: the stone sees the waves but makes none.
#include "tools/scene/stone_case.hpp"

namespace stoneskip {

struct SceneThrow {
  ThrowResult result;
  long water_steps = 0;       // height-field steps taken
  double water_cpu_s = 0;     // their cost (included in result.stats.cpu_s)
};

SceneThrow run_scene_realtime(const StoneCase& c);

}  // namespace stoneskip
