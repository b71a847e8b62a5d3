#include "verification/scene/scene_probe.hpp"

#include <algorithm>
#include <cmath>

namespace stoneskip {

ProbedScene run_probed(const SceneOptions& o, long every, int repeats) {
  ProbedScene p;
  FrameRecorder keep;
  if (every > 0)
    keep = [&](const SceneFrame& f) {
      if (!f.field || f.index % every != 0) return;
      p.checkpoint_frames.push_back(f.index);
      p.checkpoints.emplace_back();
      f.field->heights(p.checkpoints.back());
    };
  p.summary = run_scene(o, keep);
  // Timed apart from the probing run, whose recorder is not the scene's cost.
  for (int k = 0; k < repeats; ++k) {
    const SceneSummary s = run_scene(o);
    p.min_cpu_s = k == 0 ? s.cpu_s : std::min(p.min_cpu_s, s.cpu_s);
    p.min_wall_s = k == 0 ? s.wall_s : std::min(p.min_wall_s, s.wall_s);
  }
  return p;
}

bool SceneDifference::identical() const {
  return contacts_a == contacts_b && bounces_a == bounces_b && max_start_change_s == 0 && max_end_change_s == 0 &&
         max_touch_change_m == 0 && first_contact_exit_speed_change_m_s == 0 && field_max_change_m == 0;
}

SceneDifference compare_scenes(const ProbedScene& a, const ProbedScene& b) {
  SceneDifference d;
  const auto& ca = a.summary.stone.contacts;
  const auto& cb = b.summary.stone.contacts;
  d.contacts_a = static_cast<long>(ca.size());
  d.contacts_b = static_cast<long>(cb.size());
  d.bounces_a = a.summary.stone.bounces;
  d.bounces_b = b.summary.stone.bounces;
  d.common = std::min(d.contacts_a, d.contacts_b);
  for (long k = 0; k < d.common; ++k) {
    d.max_start_change_s = std::max(d.max_start_change_s, std::abs(ca[k].start_s - cb[k].start_s));
    d.max_end_change_s = std::max(d.max_end_change_s, std::abs(ca[k].end_s - cb[k].end_s));
    d.max_touch_change_m = std::max(d.max_touch_change_m, (ca[k].first_touch_m - cb[k].first_touch_m).head<2>().norm());
  }
  if (d.common > 0) d.first_contact_exit_speed_change_m_s = std::abs(ca[0].exit_speed_m_s - cb[0].exit_speed_m_s);
  const std::size_t n = std::min(a.checkpoints.size(), b.checkpoints.size());
  for (std::size_t k = 0; k < n; ++k) {
    const auto& za = a.checkpoints[k];
    const auto& zb = b.checkpoints[k];
    for (std::size_t i = 0; i < za.size() && i < zb.size(); ++i) {
      d.field_max_change_m = std::max(d.field_max_change_m, std::abs(za[i] - zb[i]));
      d.field_scale_m = std::max(d.field_scale_m, std::abs(za[i]));
    }
  }
  return d;
}

}  // namespace stoneskip
