#include <algorithm>
#include <cmath>

#include "verification/scene/scene_findings_support.hpp"
#include "verification/scene/scene_step_findings.hpp"
#include "verification/scene/scene_studies.hpp"
#include "verification/study/verdict_rules.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {

using namespace scene_findings;

// ---- grid -------------------------------------------------------------------------------------

namespace {

// The largest grid side run: a finer grid is left out (said), not run for minutes.
constexpr int kMaxGridSide = 2048;

constexpr SectionQuantity kQuantities[] = {{"pressure_work_J", "the pressure work put into the waves", 1, "J"},
                                        {"first_duration_s", "the first contact's duration", 1e3, "ms"},
                                        {"first_exit_m_s", "the first contact's exit speed", 1, "m/s"}};

Table grid_table() {
  // first_bounced: 1 where the first contact ends with the stone leaving the water, 0 where it does
  // not (it sinks, or the run ends in it), NaN without a contact (stored since 7 December).
  Table t = table({"cell_fraction", "cell_m", "n", "water_dt_s", "cells_across_stone", "smoothing_passes", "pressure_work_J",
                   "first_start_s", "first_duration_s", "first_exit_m_s", "contacts", "wall_s", "first_bounced"});
  t.units = {"1", "m", "1", "s", "1", "1", "J", "s", "s", "m/s", "1", "s", "1"};
  return t;
}

// One sequence of grids with the head smoothed as `head_width_m` says (0: a fixed number of
// cells), into `out`: the tables "grids" and "half_step" (its finest grid with the water step
// halved), what was left out and why, the verdict.
void grid_sequence(const SceneOptions& base, const SceneStudyCase& c, const ContactRecord& k, double end_s, const SceneGridOptions& g,
                   double head_width_m, const ProgressFactory& progress, const std::string& label, Record& out) {
  out.set("head_width_m", head_width_m);
  Record in;
  std::string reason;
  Table t = grid_table();
  // The grids that fit, known before any run: fewer than three decide nothing, so none is run.
  std::vector<double> fractions;
  int too_large = 0, too_wide = 0;
  const bool pressure = base.forcing == Forcing::pressure;  // the displacement forcing smooths nothing
  for (double f : g.cell_fractions) {
    const double cell = base.water->field.cell_m * f;
    if (static_cast<int>(std::ceil(g.pond_m / cell)) + 1 > kMaxGridSide)
      ++too_large;
    else if (pressure && pressure_smoothing_passes(head_width_m, cell) == 0)
      ++too_wide;
    else
      fractions.push_back(f);
  }
  const int left_out = too_large + too_wide;
  if (fractions.size() < 3) fractions.clear();
  // Each grid's own first contact against the pond: the section checked the contact's track on
  // still water, and on live water the contact may run longer and elsewhere (on swell_8ms, 140–158
  // ms on the finer grids against 27 ms on still water). Its own track must stay on the pond and,
  // on a disturbed surface, out of the walls' reach at c until the contact ends.
  std::vector<std::string> walls_reach;
  const bool disturbed = starts_disturbed(c);
  auto check_track = [&](const ContactRecord& own, double cell_m, const std::string& grid) {
    const PondWalls w = pond_walls(c, k.first_touch_m, own, g.pond_m, cell_m);
    if (w.nearest_m <= 0)
      walls_reach.push_back(grid + ": its first contact's track leaves the pond");
    else if (disturbed && w.reach_s <= own.end_s)
      walls_reach.push_back(grid + ": the walls' waves reach its first contact's track after " + duration(w.reach_s) +
                            ", before that contact ends at " + duration(own.end_s));
  };
  // The grid of `f` of the case's cell, its water step `dt_scale` × the case's scaled alike (σ × dt_scale).
  auto run_grid = [&](double f, double dt_scale) {
    SceneOptions s = base;
    s.duration_s = end_s;
    s.energy_budget = true;  // the pressure work W (solvers/scene/wave_energy.hpp)
    s.head_width_m = head_width_m;
    place_on_pond(s, c, k.first_touch_m, g.pond_m, base.water->field.cell_m * f, base.water->field.dt_s * f * dt_scale);
    const HeightFieldOptions& w = s.water->field;
    const SceneSummary r = run_scene(s);
    const bool touched = !r.stone.contacts.empty();
    const ContactRecord* c1 = touched ? &r.stone.contacts.front() : nullptr;
    if (c1) check_track(*c1, w.cell_m, num(100 * w.cell_m, 3) + " cm" + (dt_scale != 1.0 ? ", step ½" : ""));
    return std::vector<double>{f, w.cell_m, double(w.nx), w.dt_s, 2 * base.stone.disk_radius_m / w.cell_m,
                               pressure ? double(pressure_smoothing_passes(head_width_m, w.cell_m)) : 0.0, r.energy.pressure_work_J,
                               c1 ? c1->start_s : kNaN, c1 ? c1->duration_s() : kNaN, c1 ? c1->exit_speed_m_s : kNaN,
                               double(r.stone.contacts.size()), r.wall_s, c1 ? double(c1->bounced) : kNaN};
  };
  // One more run on the finest grid with the water step halved (σ halved): how far the water's
  // step alone moves each quantity there (the stone sees level n held over [t_n, t_n+1), so an
  // event time carries a first-order error of the step; model/README.md §2.4).
  auto ticker = start_progress(progress, label, fractions.empty() ? 0 : fractions.size() + 1);
  for (double f : fractions) {
    t.add_row(run_grid(f, 1.0));
    ticker->tick();
  }
  Table half_step = grid_table();
  if (!fractions.empty()) {
    half_step.add_row(run_grid(fractions.back(), 0.5));
    ticker->tick();
  }
  const std::size_t n = t.rows();
  in.set("grids", double(n));
  if (n < 3) {
    reason = std::to_string(g.cell_fractions.size() - left_out) + " grids fit under " + std::to_string(kMaxGridSide) +
             "² cells" + (too_wide ? " and a head " + std::to_string(kMaxHeadWidthCells) + " cells wide" : std::string()) +
             ", fewer than the three a change against the one before needs: none was run";
  } else {
    // A first contact that ends in a bounce on one grid and not on the next is not the same
    // contact refined: its duration and exit speed then compare different endings.
    const auto bounced = t.column("first_bounced");
    std::vector<std::string> endings;
    double outcome_changes = 0;
    for (std::size_t j = 0; j < n; ++j) {
      endings.push_back(num(100 * t.column("cell_m")[j], 3) + " cm: " +
                        (std::isnan(bounced[j]) ? "no contact" : bounced[j] > 0 ? "a bounce" : "no bounce"));
      if (j > 0 && !(bounced[j] == bounced[j - 1])) ++outcome_changes;
    }
    in.set("outcome_changes", outcome_changes);
    // Each change of each quantity against the one before as the cells get finer: the largest
    // such ratio must be < 1 (every change shrinking). A change after none is NaN (not < 1).
    std::vector<std::string> growing, shrinking;
    for (const SectionQuantity& q : kQuantities) {
      const auto v = t.column(q.key);
      double ratio = 0;
      for (std::size_t j = 2; j < n; ++j) {
        const double d_prev = std::abs(v[j - 1] - v[j - 2]), d = std::abs(v[j] - v[j - 1]);
        const double r = d_prev > 0 ? d / d_prev : (d > 0 ? kNaN : 0.0);
        ratio = std::isnan(ratio) || std::isnan(r) ? kNaN : std::max(ratio, r);
      }
      in.set(std::string("ratio_") + q.key, ratio);
      // The last change's size beside its ratio, and beside what halving the water step alone
      // moves the quantity on the finest grid: a change no larger than that is the water step's,
      // which the grid sequence (σ fixed) does not separate from the cell's.
      const double last = std::abs(v[n - 1] - v[n - 2]);
      const double by_step = std::abs(half_step.column(q.key)[0] - v[n - 1]);
      in.set(std::string("last_change_") + q.key, last);
      in.set(std::string("time_change_") + q.key, by_step);
      const std::string sizes = "the last " + num(q.scale * last, 3) + " " + q.unit + ", halving the water step " +
                                num(q.scale * by_step, 3) + " " + q.unit;
      (ratio < 1 ? shrinking : growing)
          .push_back(std::string(q.words) + " (a change " + num(ratio, 3) + "× the one before; " + sizes + ")");
    }
    reason = growing.empty() ? "each quantity's change shrinks with the finer grid: " + joined(shrinking, "; ")
                             : "changes that do not shrink as the cells get finer: " + joined(growing, "; ");
    if (outcome_changes > 0)
      reason = "the first contact ends differently as the cells get finer (" + joined(endings, ", ") + "); " + reason;
    in.set("walls_reach_track", double(walls_reach.size()));
    if (!walls_reach.empty())
      reason = "on some grid the pond's walls are not clear of the stone's own first contact (" + joined(walls_reach, "; ") +
               "): those answers are partly the pond's; widen grid.pond_m; " + reason;
  }
  out.set("walls_reach_track", double(walls_reach.size()));
  out.set_table("grids", t);
  out.set_table("half_step", half_step);
  out.set("left_out", left_out);
  out.set("left_out_too_large", too_large);
  out.set("left_out_too_wide", too_wide);
  decide_verdict(out, "verdict", "grid_differences", in, reason);
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
  out.set("case_coupling", std::string(to_string(c.scene.coupling)));  // the section runs two-way whatever the case says
  out.set("case", c.name);
  out.set("title", c.title);
  out.set("pond_m", g.pond_m);
  out.set("base_cell_m", base.water->field.cell_m);
  out.set("base_water_dt_s", base.water->field.dt_s);
  out.set("stone_diameter_m", 2 * base.stone.disk_radius_m);
  out.set("forcing", std::string(to_string(base.forcing)));
  out.set("level_in_time", std::string(to_string(base.level_in_time)));
  out.set("max_width_cells", double(kMaxHeadWidthCells));
  out.set("default_passes", double(kPressureSmoothingPasses));
  // Where and when the stone first meets still water: the pond is put around it.
  SceneOptions still = base;
  still.coupling = Coupling::none;
  const SceneSummary first = run_scene(still);
  // The section not run, and why: no grid, the verdict's reason.
  auto not_run = [&](const std::string& why) {
    Record in;
    in.set("grids", 0.0);
    out.set("head_width_m", base.head_width_m);
    out.set_table("grids", grid_table());
    out.set("left_out", 0);
    decide_verdict(out, "verdict", "grid_differences", in, why);
    return out;
  };
  if (first.stone.contacts.empty())
    return not_run("the stone never touches still water in " + c.name + "'s " + duration(base.duration_s));
  const ContactRecord& k = first.stone.contacts.front();
  const double end_s = std::min(base.duration_s, k.start_s + 5 * k.duration_s() + g.after_s);
  out.set("end_s", end_s);
  out.set("still_first_start_s", k.start_s);
  out.set("still_first_duration_s", k.duration_s());
  // On any case, the first contact's track must lie on the pond: a two-way pond takes none of the
  // stone's push outside it (model/README.md §2.4). A case starting from a disturbed surface: each
  // pond samples it afresh, but the pond's walls are its own, not the case's, and from t = 0 they
  // send waves into the surface (a still pond sends none until the stone's waves reach them). The
  // answers are the case's only while those waves, at c, have not reached the first contact's
  // track by the section's end.
  const PondWalls walls = pond_walls(c, k, g.pond_m, base.water->field.cell_m);
  out.set("wall_distance_m", walls.nearest_m);
  out.set("walls_reach_s", walls.reach_s);
  out.set("wave_speed_m_s", base.water->field.wave_speed_m_s);
  out.set("boundary", std::string(to_string(base.water->field.boundary)));
  std::string why;
  if (walls.nearest_m <= 0)
    why = "the first contact's track on still water, with the stone's disk around it, reaches " + length(-walls.nearest_m) +
          " past the walls of the " + num(g.pond_m, 3) + " m pond around the first touch: widen grid.pond_m";
  if (why.empty() && starts_disturbed(c)) {
    out.set("initial_surface", initial_surface_words(*c.initial));
    out.set("pond_inside_case", walls.inside_case ? 1.0 : 0.0);
    if (!walls.inside_case)
      why = "the " + num(g.pond_m, 3) + " m pond around the first touch reaches past " + c.name +
            "'s own walled field, where its initial surface is not defined: a smaller grid.pond_m, or a first touch farther inside";
    else if (walls.reach_s <= end_s)
      why = "the " + num(g.pond_m, 3) + " m pond's " +
            (base.water->field.boundary == Boundary::periodic ? "edges (its periodic seams)" : "walls") + " are not " + c.name +
            "'s: the waves they send from its initial surface, at c = " +
            num(base.water->field.wave_speed_m_s, 3) + " m/s from " + length(walls.nearest_m) +
            " away, reach the first contact's track after " + duration(walls.reach_s) + ", before the section's end at " +
            duration(end_s) + ": its answers would be the pond's, not the case's; widen grid.pond_m";
  }
  if (!why.empty()) return not_run(why);
  // The scene as the case has it (its own head width, 0 for the shipped scenes).
  grid_sequence(base, c, k, end_s, g, base.head_width_m, progress, "scene: grids", out);
  // A head of fixed width in metres: only the pressure forcing has a head to widen.
  if (base.forcing == Forcing::pressure) {
    Record& widths = out.child("fixed_width");
    for (std::size_t i = 0; i < g.head_widths_m.size(); ++i)
      grid_sequence(base, c, k, end_s, g, g.head_widths_m[i], progress, "scene: grids, head " + num(100 * g.head_widths_m[i], 3) + " cm",
                    widths.child(std::to_string(i)));
  }
  // The water step alone, at the case's cell: the level held against extrapolated; left out (said)
  // where the pond at that cell is larger than the grids above may be (a 100 m pond of 2 cm cells
  // took 217 s a run, 14 runs).
  const int own_side = static_cast<int>(std::ceil(g.pond_m / base.water->field.cell_m)) + 1;
  if (own_side > kMaxGridSide)
    out.set("water_step_left_out", "the " + num(g.pond_m, 3) + " m pond at the case's own cell is " + std::to_string(own_side) +
                                       "² cells, above the " + std::to_string(kMaxGridSide) + "² the section runs");
  else
    water_step_study(base, c, k, end_s, g, progress, out.child("water_step"));
  return out;
}

}  // namespace stoneskip
