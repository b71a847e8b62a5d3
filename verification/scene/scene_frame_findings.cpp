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

namespace {

// A matrix (rows y, columns x) as a table with one column per x.
Table matrix_table(const std::vector<double>& v, int nx, int ny) {
  std::vector<std::string> cols;
  for (int i = 0; i < nx; ++i) cols.push_back("x" + std::to_string(i));
  Table t = table(cols);
  t.units.assign(cols.size(), "m");  // water heights
  for (int j = 0; j < ny; ++j) t.add_row(std::vector<double>(v.begin() + static_cast<long>(j) * nx, v.begin() + static_cast<long>(j + 1) * nx));
  return t;
}

Table xy_table(const std::vector<double>& x, const std::vector<double>& y) {
  Table t = table({"x_m", "y_m"});
  for (std::size_t k = 0; k < x.size(); ++k) t.add_row({x[k], y[k]});
  return t;
}

}  // namespace

// ---- frames -----------------------------------------------------------------------------------

Record scene_frames_findings(const SceneStudiesOptions& o, const ProgressFactory& progress) {
  Record out;
  std::vector<std::string> names;
  auto ticker = start_progress(progress, "scene: still frames", o.cases.size());
  for (const auto& c : o.cases) {
    const StillFrame s = capture_telling_frame(capped(o, c.scene), o.frames);
    Record& r = out.child(c.name);
    names.push_back(c.name);
    r.set("title", c.title);
    r.set("found", s.found);
    r.set("problem", s.problem);
    if (s.found) {
      r.set("frame", s.frame);
      r.set("frames", s.frames);
      r.set("t_s", s.t_s);
      r.set("disturbed_cells", s.disturbed_cells);
      r.set("frames_considered", s.frames_considered);
      r.set("threshold_m", s.threshold_m);
      r.set("largest_m", s.largest_m);
      r.set("scale_m", s.scale_m);
      r.set("stone_status", std::string(to_string(s.stone_status)));
      r.set("stone_x_m", s.stone_x_m);
      r.set("stone_y_m", s.stone_y_m);
      r.set("stone_z_m", s.stone_z_m);
      r.set("stone_radius_m", s.stone_radius_m);
      r.set("pond_x0_m", s.pond_x0_m);
      r.set("pond_x1_m", s.pond_x1_m);
      r.set("pond_y0_m", s.pond_y0_m);
      r.set("pond_y1_m", s.pond_y1_m);
      r.set("top_x0_m", s.top_x0_m);
      r.set("top_y0_m", s.top_y0_m);
      r.set("top_dx_m", s.top_dx_m);
      r.set_table("top", matrix_table(s.top_m, s.top_nx, s.top_ny));
      r.set("near_on_touch", s.near_on_touch);
      r.set("near_x0_m", s.near_x0_m);
      r.set("near_y0_m", s.near_y0_m);
      r.set("near_dx_m", s.near_dx_m);
      r.set_table("near", matrix_table(s.near_m, s.near_n, s.near_n));
      r.set_table("track", xy_table(s.track_x_m, s.track_y_m));
      r.set_table("touches", xy_table(s.touch_x_m, s.touch_y_m));
      r.set("why", "frame " + std::to_string(s.frame) + " of " + std::to_string(s.frames) + " (t = " + num(s.t_s, 3) + " s) has the most disturbed water, " +
                       std::to_string(s.disturbed_cells) + " cells above " + num(1e3 * s.threshold_m, 2) + " mm (" +
                       num(100 * o.frames.threshold_fraction, 2) + " % of the scene's largest |z|, " + num(1e3 * s.largest_m, 3) + " mm), among the " +
                       std::to_string(s.frames_considered) + " frames before a cell above that height reaches the pond's edge");
    }
    ticker->tick();
  }
  out.set_strings("cases", names);
  out.set("threshold_fraction", o.frames.threshold_fraction);
  return out;
}

}  // namespace stoneskip
