#include "tools/scene/scene_throw.hpp"

namespace stoneskip {

SceneOptions scene_options(const StoneCase& c, SceneEnd end) {
  SceneOptions o;
  o.stone = c.stone;
  o.environment = c.environment;
  o.initial = c.initial;
  o.stone_steps = c.realtime;
  o.end = end;
  o.frame_rate_hz = c.frames.frame_rate_hz;
  o.free_water = c.frames.free_water;
  o.duration_s = c.frames.duration_s ? *c.frames.duration_s : c.realtime.t_max_s;
  o.coupling = c.water ? c.water->coupling : Coupling::none;
  if (c.water && c.water->coupling != Coupling::none) {
    const WaterScene& w = *c.water;
    SceneWater sw;
    sw.field = w.field;
    if (w.initial) sample_disturbance(*w.initial, w.field.nx, w.field.ny, w.field.cell_m, sw.initial_m);
    sw.placement = FieldPlacement{w.origin_x_m, w.origin_y_m};
    o.water = std::move(sw);
    o.draught_samples = w.draught_samples;
    o.forcing = w.forcing;
    o.head_width_m = w.head_width_m;
    o.level_in_time = w.level_in_time;
  }
  return o;
}

SceneThrow run_scene_realtime(const StoneCase& c) {
  const SceneSummary s = run_scene(scene_options(c, SceneEnd::with_the_throw));
  SceneThrow out;
  out.result = s.stone;
  out.water_steps = s.water_steps;
  out.water_wall_s = s.water_wall_s;
  return out;
}

}  // namespace stoneskip
