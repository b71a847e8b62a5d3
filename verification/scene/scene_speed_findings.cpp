#include "verification/scene/scene_studies.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "verification/scene/scene_findings_support.hpp"
#include "verification/scene/scene_probe.hpp"
#include "verification/study/order_record.hpp"
#include "verification/study/verdict_rules.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {

using namespace scene_findings;

// ---- speed ------------------------------------------------------------------------------------

Record scene_speed_findings(const SceneStudiesOptions& o, const ProgressFactory& progress) {
  HeadlineSpeedOptions h = o.speed.headline;
  const HeadlineSpeed s = measure_headline_speed(h, progress);
  Record r;
  r.set("case", o.cases.front().name);
  r.set("load_before", s.load_before);
  r.set("load_after", s.load_after);
  r.set("cores", s.cores);
  r.set("scene_frames", s.scene_one.frames);
  r.set("scene_repeats", h.scene_repeats);
  r.set("many_threads", s.scene_many.threads);
  r.set("scene_fps_1core", s.scene_one.fps_best_wall());
  r.set("scene_fps_1core_median", s.scene_one.fps_median_wall());
  r.set("scene_fps_1core_cpu", s.scene_one.fps_cpu());
  r.set("scene_fps_2cores", s.scene_many.fps_best_wall());
  r.set("scene_fps_2cores_median", s.scene_many.fps_median_wall());
  const SceneSummary& b = s.scene_one.best;
  r.set("stone_wall_s", b.stone_wall_s);
  r.set("draught_wall_s", b.draught_wall_s);
  r.set("water_wall_s", b.water_wall_s);
  r.set("recording_wall_s", b.recording_wall_s);
  r.set("wall_s", b.wall_s);
  r.set("cpu_s", b.cpu_s);
  r.set("slowest_frame", b.slowest_frame);
  r.set("slowest_frame_wall_s", b.slowest_frame_wall_s);
  r.set("slowest_frame_cpu_s", b.slowest_frame_cpu_s);
  r.set("slowest_frame_t_s", b.slowest_frame > 0 ? b.frame_costs[b.slowest_frame - 1].t_s : 0.0);
  Table f = table({"t_s", "wall_ms", "cpu_ms", "stone_ms", "water_ms", "stone_steps"});
  for (const auto& x : b.frame_costs)
    f.add_row({x.t_s, 1e3 * x.wall_s, 1e3 * x.cpu_s, 1e3 * x.stone_wall_s, 1e3 * x.water_wall_s, double(x.stone_steps)});
  r.set_table("frames", f);
  r.set("stencil", s.stencil_large.options.stencil.name);
  r.set("kernel_isa", s.stencil_large.kernel_isa);
  r.set("stencil_n_small", s.stencil_small.options.n);
  r.set("stencil_n_large", s.stencil_large.options.n);
  r.set("stencil_cells_per_s_small", s.stencil_small.cells_per_s);
  r.set("stencil_cells_per_s_large", s.stencil_large.cells_per_s);
  r.set("bandwidth_fraction_small", s.stencil_small.fraction);
  r.set("bandwidth_fraction_large", s.stencil_large.fraction);
  r.set("bandwidth_fraction_large_median", s.stencil_large.fraction_median);
  r.set("copy_bytes_per_s_large", s.stencil_large.copy_bytes_per_s);
  r.set("per_cell_ratio", s.per_cell_ratio);
  r.set("sweep_throws", s.sweep.throws);
  r.set("sweep_workers", s.sweep.workers);
  r.set("sweep_throws_per_s", s.sweep.throws_per_s());
  r.set("sweep_cpu_s", s.sweep.cpu_s);
  r.set("sweep_wall_s", s.sweep.best_wall_s);
  r.set("sweep_contact_dt_s", h.sweep.base.realtime.contact_dt_s);  // the fixed schemes' contact step (unused by bs32)
  r.set("sweep_scheme", std::string(to_string(h.sweep.base.realtime.scheme)));
  r.set("sweep_rtol", h.sweep.base.realtime.rtol);  // bs32's tolerance (rtol; atol_m in sweep_atol_m)
  r.set("sweep_atol_m", h.sweep.base.realtime.atol_m);
  r.set("sweep_steps", s.sweep.steps);
  r.set("sweep_contact_steps", s.sweep.contact_steps);
  r.set("sweep_simulated_s", s.sweep.simulated_s);
  {  // The sweep's profile: what one throw costs, and what the target allows it.
    const double n = std::max(1L, s.sweep.throws);
    r.set("sweep_cpu_per_throw_s", s.sweep.cpu_s / n);
    r.set("sweep_simulated_per_throw_s", s.sweep.simulated_s / n);
    r.set("sweep_steps_per_throw", s.sweep.steps / n);
    r.set("sweep_contact_steps_per_throw", s.sweep.contact_steps / n);
    r.set("sweep_cpu_per_step_s", s.sweep.steps > 0 ? s.sweep.cpu_s / s.sweep.steps : kNaN);
    r.set("sweep_cpu_budget_per_throw_s", s.sweep.workers / o.speed.throws_per_s_target);
  }
  auto target = [&](const std::string& key, double value, double goal, const std::string& what) {
    Record in;
    in.set("value", value);
    in.set("target", goal);
    decide_verdict(r, key, "speed_target", in, what + " " + num(value, 4) + " against the target " + num(goal, 4));
  };
  target("scene_target", s.scene_one.fps_best_wall(), o.speed.scene_fps_target, "the seed's scene on one thread: frames/s (wall, best run)");
  target("bandwidth_target", s.stencil_large.fraction, o.speed.bandwidth_fraction_target,
         "the stencil at " + std::to_string(s.stencil_large.options.n) + "²: fraction of the copy bound");
  target("per_cell_target", s.per_cell_ratio, o.speed.per_cell_ratio_target, "the stencil's rate per cell at " +
                                                                                  std::to_string(s.stencil_small.options.n) + "² over " +
                                                                                  std::to_string(s.stencil_large.options.n) + "²");
  target("sweep_target", s.sweep.throws_per_s(), o.speed.throws_per_s_target,
         "a bounce-count sweep on " + std::to_string(s.sweep.workers) + " workers: throws/s (wall)");
  return r;
}

}  // namespace stoneskip
