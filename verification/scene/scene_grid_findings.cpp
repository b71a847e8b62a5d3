#include <algorithm>
#include <cmath>

#include "verification/scene/scene_findings_support.hpp"
#include "verification/scene/scene_studies.hpp"
#include "verification/study/verdict_rules.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {

using namespace scene_findings;

// ---- grid -------------------------------------------------------------------------------------

namespace {

// The largest grid side run: a finer grid is left out (said), not run for minutes.
constexpr int kMaxGridSide = 2048;

struct GridQuantity {
  const char* key;    // the table's column and the verdict input's suffix
  const char* words;  // as the report names it
};
constexpr GridQuantity kQuantities[] = {{"pressure_work_J", "the pressure work put into the waves"},
                                        {"first_duration_s", "the first contact's duration"},
                                        {"first_exit_m_s", "the first contact's exit speed"}};

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? "; " : "") + v[i];
  return s;
}

}  // namespace

Record scene_grid_findings(const SceneStudiesOptions& o, const ProgressFactory& progress) {
  const SceneStudyCase& c = find_case(o, o.grid.case_name);
  const SceneGridOptions& g = o.grid;
  SceneOptions base = capped(o, c.scene);
  base.coupling = Coupling::two_way;
  base.water->field.mode = StepMode::full;
  base.water->field.threads = 1;
  Record out;
  out.set("case", c.name);
  out.set("title", c.title);
  out.set("pond_m", g.pond_m);
  out.set("base_cell_m", base.water->field.cell_m);
  out.set("base_water_dt_s", base.water->field.dt_s);
  out.set("stone_diameter_m", 2 * base.stone.disk_radius_m);
  out.set("forcing", std::string(to_string(base.forcing)));
  // Where and when the stone first meets still water: the pond is put around it.
  SceneOptions still = base;
  still.coupling = Coupling::none;
  const SceneSummary first = run_scene(still);
  Record in;
  std::string reason;
  Table t = table({"cell_fraction", "cell_m", "n", "water_dt_s", "cells_across_stone", "pressure_work_J", "first_start_s",
                   "first_duration_s", "first_exit_m_s", "contacts", "wall_s"});
  t.units = {"1", "m", "1", "s", "1", "J", "s", "s", "m/s", "1", "s"};
  int left_out = 0;
  if (first.stone.contacts.empty()) {
    in.set("grids", 0.0);
    reason = "the stone never touches still water in " + c.name + "'s " + duration(base.duration_s);
  } else {
    const ContactRecord& k = first.stone.contacts.front();
    const double end_s = std::min(base.duration_s, k.start_s + 5 * k.duration_s() + g.after_s);
    out.set("end_s", end_s);
    out.set("still_first_start_s", k.start_s);
    out.set("still_first_duration_s", k.duration_s());
    // The grids that fit, known before any run: fewer than three decide nothing, so none is run.
    std::vector<double> fractions;
    for (double f : g.cell_fractions)
      if (static_cast<int>(std::ceil(g.pond_m / (base.water->field.cell_m * f))) + 1 <= kMaxGridSide) fractions.push_back(f);
    left_out = static_cast<int>(g.cell_fractions.size() - fractions.size());
    if (fractions.size() < 3) fractions.clear();
    auto ticker = start_progress(progress, "scene: grids", fractions.size());
    for (double f : fractions) {
      SceneOptions s = base;
      s.duration_s = end_s;
      s.energy_budget = true;  // the pressure work W (solvers/scene/wave_energy.hpp)
      HeightFieldOptions& w = s.water->field;
      w.cell_m = base.water->field.cell_m * f;
      w.dt_s = base.water->field.dt_s * f;  // σ fixed
      w.nx = w.ny = static_cast<int>(std::ceil(g.pond_m / w.cell_m)) + 1;
      s.water->placement.origin_x_m = k.first_touch_m.x() - 0.25 * g.pond_m;
      s.water->placement.origin_y_m = k.first_touch_m.y() - 0.5 * g.pond_m;
      const SceneSummary r = run_scene(s);
      const bool touched = !r.stone.contacts.empty();
      const ContactRecord* c1 = touched ? &r.stone.contacts.front() : nullptr;
      t.add_row({f, w.cell_m, double(w.nx), w.dt_s, 2 * base.stone.disk_radius_m / w.cell_m, r.energy.pressure_work_J,
                 c1 ? c1->start_s : kNaN, c1 ? c1->duration_s() : kNaN, c1 ? c1->exit_speed_m_s : kNaN,
                 double(r.stone.contacts.size()), r.wall_s});
      ticker->tick();
    }
    const std::size_t n = t.rows();
    in.set("grids", double(n));
    if (n < 3) {
      reason = std::to_string(g.cell_fractions.size() - left_out) + " grids fit under " + std::to_string(kMaxGridSide) +
               "² cells, fewer than the three a change against the one before needs: none was run";
    } else {
      // Each change of each quantity against the one before as the cells get finer: the largest
      // such ratio must be < 1 (every change shrinking). A change after none is NaN (not < 1).
      std::vector<std::string> growing, shrinking;
      for (const GridQuantity& q : kQuantities) {
        const auto v = t.column(q.key);
        double ratio = 0;
        for (std::size_t j = 2; j < n; ++j) {
          const double d_prev = std::abs(v[j - 1] - v[j - 2]), d = std::abs(v[j] - v[j - 1]);
          const double r = d_prev > 0 ? d / d_prev : (d > 0 ? kNaN : 0.0);
          ratio = std::isnan(ratio) || std::isnan(r) ? kNaN : std::max(ratio, r);
        }
        in.set(std::string("ratio_") + q.key, ratio);
        (ratio < 1 ? shrinking : growing).push_back(std::string(q.words) + " (a change " + num(ratio, 3) + "× the one before)");
      }
      reason = growing.empty() ? "each quantity's change shrinks with the finer grid: " + joined(shrinking)
                               : "changes that do not shrink as the cells get finer: " + joined(growing);
    }
  }
  out.set_table("grids", t);
  out.set("left_out", left_out);
  decide_verdict(out, "verdict", "grid_differences", in, reason);
  return out;
}

}  // namespace stoneskip
