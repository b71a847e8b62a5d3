#include "tools/scene/scene_throw.hpp"


#include "model/water/height_field_surface.hpp"
#include "solvers/realtime/clocks.hpp"

namespace stoneskip {

SceneThrow run_scene_realtime(const StoneCase& c) {
  SceneThrow out;
  if (!c.water) {
    out.result = run_realtime(c.stone, c.environment, c.initial, c.realtime);
    return out;
  }
  const WaterScene& w = *c.water;
  HeightField field(w.field);
  std::vector<double> z0;
  sample_disturbance(w.initial, w.field.nx, w.field.ny, w.field.cell_m, z0);
  field.set_state(z0);
  const HeightFieldSurface surface(field, w.origin_x_m, w.origin_y_m);
  double water_cpu = 0;
  // The field is advanced to the nearest of its own time levels at the start of each stone step
  // (the surface is piecewise constant in time at the water's step, as in a game loop).
  auto advance = [&](double t_s) {
    const CpuTimer timer;  // thread CPU, as stats.cpu_s
    while (field.time_s() + 0.5 * w.field.dt_s <= t_s) field.step();
    water_cpu += timer.seconds();
  };
  out.result = run_realtime(c.stone, c.environment, c.initial, c.realtime, &surface, advance);
  out.result.solver += ", on a live " + std::to_string(w.field.nx) + "x" + std::to_string(w.field.ny) + " height field (" +
                       w.field.stencil.name + ")";
  out.water_steps = field.steps();
  out.water_cpu_s = water_cpu;
  return out;
}

}  // namespace stoneskip
