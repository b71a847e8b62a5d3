#include "tools/scene/scene_study_file.hpp"

#include <algorithm>
#include <filesystem>

#include "tools/io/input_error.hpp"
#include "tools/io/shipped_files.hpp"
#include "tools/scene/case_problem.hpp"
#include "tools/scene/scene_throw.hpp"
#include "tools/scene/study_keys.hpp"

namespace stoneskip {

namespace fs = std::filesystem;

namespace {

StoneCase load_case(const fs::path& dir, TomlTable& t, const std::string& key, const std::string& file) {
  const fs::path path = dir / file;
  std::error_code ec;
  // From any folder: a study's "cases/…" path is looked up in the shipped cases (shipped_files.hpp).
  if (!fs::is_regular_file(locate_input(path), ec)) t.fail(key, "no case file '" + path.string() + "'");
  return load_stone_case(path.string());
}

// [from, to, step] → the values from..to.
std::vector<double> range_of(TomlTable& t, const std::string& key, const std::vector<double>& fallback) {
  auto v = t.maybe_numbers(key);
  if (!v) return fallback;
  if (v->size() != 3) t.fail(key, "must be [from, to, step]");
  return from_to_step(t, key, (*v)[0], (*v)[1], (*v)[2], 1e4 + 1);
}

std::vector<int> int_list(TomlTable& t, const std::string& key, const std::vector<int>& fallback, int lo, int hi) {
  auto v = t.maybe_numbers(key);
  if (!v) return fallback;
  std::vector<int> out;
  for (double x : *v) {
    if (x != std::floor(x) || x < lo || x > hi) t.fail(key, "whole numbers in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] needed");
    out.push_back(static_cast<int>(x));
  }
  if (out.empty()) t.fail(key, "must not be empty");
  return out;
}

std::string case_name(const std::string& file) { return fs::path(file).stem().string(); }

}  // namespace

SceneStudyFile load_scene_study_file(const std::string& path, const std::vector<std::string>& overrides) {
  const TomlDocument doc = load_toml(path, overrides);
  const fs::path dir = fs::path(path).parent_path();
  SceneStudyFile f;
  f.file = doc.file;
  f.text = doc.text;
  f.settings_text = "# " + path + "\n" + doc.text;
  TomlTable top = doc.top();
  f.title = read_case_title(top);
  SceneStudiesOptions& o = f.options;
  {
    TomlTable s = top.table("study");
    o.preset = study_preset(s, "scene");
    const auto files = s.strings("cases");
    if (files.empty()) s.fail("cases", "must name at least one scene case");
    for (const auto& file : files) {
      const StoneCase c = load_case(dir, s, "cases", file);
      if (!c.water || c.water->coupling == Coupling::none)
        s.fail("cases", "'" + file + "' has no live water ([water] with coupling one_way or two_way)");
      SceneStudyCase sc;
      sc.name = case_name(file);
      sc.title = c.title;
      sc.file = file;
      sc.scene = scene_options(c, SceneEnd::at_duration);
      sc.initial = c.water->initial;
      for (const auto& other : o.cases)
        if (other.name == sc.name) s.fail("cases", "two cases named '" + sc.name + "'");
      o.cases.push_back(std::move(sc));
      f.settings_text += "\n# " + (dir / file).string() + "\n" + c.text;
    }
    o.duration_cap_s = s.number_or("duration_cap_s", 0.0);
    s.require_non_negative("duration_cap_s", o.duration_cap_s);
    s.finish();
  }
  auto known_case = [&](TomlTable& t, const std::string& key, std::string& out) {
    if (!t.has(key)) return;
    out = t.string(key);
    for (const auto& c : o.cases)
      if (c.name == out) return;
    t.fail(key, "'" + out + "' is not one of the study's cases (their file stems)");
  };
  if (auto t = top.maybe_table("coupling")) {
    o.coupling.time_tolerance_s = positive(*t, "time_tolerance_s", o.coupling.time_tolerance_s);
    o.coupling.ensemble_members = static_cast<int>(count_in(*t, "ensemble_members", o.coupling.ensemble_members, 2, 1000));
    if (o.coupling.ensemble_members % 2 != 0) t->fail("ensemble_members", "must be even (the perturbations come in ± pairs)");
    o.coupling.perturbation_smallest = positive(*t, "perturbation_smallest", o.coupling.perturbation_smallest);
    o.coupling.perturbation_largest = positive(*t, "perturbation_largest", o.coupling.perturbation_largest);
    if (o.coupling.perturbation_largest < o.coupling.perturbation_smallest || o.coupling.perturbation_largest >= 0.1)
      t->fail("perturbation_largest", "must lie in [perturbation_smallest, 0.1)");
    t->finish();
  }
  if (auto t = top.maybe_table("stability")) {
    o.stability.stencil = t->string_or("stencil", o.stability.stencil);
    if (!is_stencil_name(o.stability.stencil)) t->fail("stencil", "'" + o.stability.stencil + "' is not a named stencil");
    o.stability.margin = t->number_or("margin", o.stability.margin);
    t->require_in("margin", o.stability.margin, 1e-4, 0.49);
    o.stability.n = static_cast<int>(count_in(*t, "n", o.stability.n, 16, 1024));
    o.stability.damping_per_s = t->number_or("damping_per_s", o.stability.damping_per_s);
    t->require_non_negative("damping_per_s", o.stability.damping_per_s);
    o.stability.steps = count_in(*t, "steps", o.stability.steps, 20, 1000000);
    o.stability.steps_above = count_in(*t, "steps_above", o.stability.steps_above, 20, 1000000);
    o.stability_growth_tolerance = positive(*t, "growth_tolerance", o.stability_growth_tolerance);
    t->finish();
  }
  if (auto t = top.maybe_table("convergence")) {
    ForcedConvergenceOptions& c = o.convergence.forced;
    if (auto names = t->maybe_strings("stencils")) {
      for (const auto& n : *names)
        if (!is_stencil_name(n)) t->fail("stencils", "'" + n + "' is not a named stencil");
      if (names->empty()) t->fail("stencils", "must not be empty");
      o.convergence.stencils = *names;
    }
    c.space_grids = int_list(*t, "space_grids", c.space_grids, 8, 4096);
    c.time_grid = static_cast<int>(count_in(*t, "time_grid", c.time_grid, 8, 4096));
    const auto steps = int_list(*t, "time_steps", std::vector<int>(c.time_steps.begin(), c.time_steps.end()), 1, 10000000);
    c.time_steps.assign(steps.begin(), steps.end());
    c.both_grids = int_list(*t, "both_grids", c.both_grids, 8, 4096);
    c.both_sigma = positive(*t, "both_sigma", c.both_sigma);
    if (auto walls = t->maybe_strings("walls")) {  // the walled squares' "both" sequences (forced_convergence.hpp)
      c.walls.clear();
      for (const auto& w : *walls) {
        Boundary b{};
        if (!parse_boundary(w, b) || b == Boundary::periodic) t->fail("walls", "'" + w + "' is not a walled boundary (reflecting, fixed)");
        if (std::find(c.walls.begin(), c.walls.end(), b) != c.walls.end()) t->fail("walls", "'" + w + "' is named twice");
        c.walls.push_back(b);
      }
    }
    c.walls_t_end_s = positive(*t, "walls_t_end_s", c.walls_t_end_s);
    if (c.walls_t_end_s > 1e3) t->fail("walls_t_end_s", "must be at most 1000 s");
    c.quadrature.intervals = static_cast<int>(count_in(*t, "quadrature_intervals", c.quadrature.intervals, 1, 100000));
    c.quadrature.nodes = static_cast<int>(count_in(*t, "quadrature_nodes", c.quadrature.nodes, 1, 64));
    c.fit_points = static_cast<int>(count_in(*t, "fit_points", c.fit_points, 0, 100));
    c.judgement.expected_order = positive(*t, "expected_order", c.judgement.expected_order);
    c.judgement.tolerance = positive(*t, "order_tolerance", c.judgement.tolerance);
    t->finish();
  }
  if (auto t = top.maybe_table("rings")) {
    known_case(*t, "case", o.rings_case);
    o.rings.contact = static_cast<int>(count_in(*t, "contact", o.rings.contact + 1, 1, 1000)) - 1;
    o.rings.start_after_s = t->number_or("start_after_s", o.rings.start_after_s);
    t->require_non_negative("start_after_s", o.rings.start_after_s);
    o.rings.end_after_s = positive(*t, "end_after_s", o.rings.end_after_s);
    if (o.rings.end_after_s <= o.rings.start_after_s) t->fail("end_after_s", "must be after start_after_s");
    o.rings.min_radius_m = t->number_or("min_radius_m", o.rings.min_radius_m);
    t->require_non_negative("min_radius_m", o.rings.min_radius_m);
    o.rings.max_radius_m = positive(*t, "max_radius_m", o.rings.max_radius_m);
    if (o.rings.max_radius_m <= o.rings.min_radius_m) t->fail("max_radius_m", "must be above min_radius_m");
    t->finish();
  }
  if (auto t = top.maybe_table("shortcuts")) {
    SceneShortcutOptions& s = o.shortcuts;
    known_case(*t, "case", s.case_name);
    s.epsilons_m = positive_list(*t, "epsilons_m", s.epsilons_m);
    s.tile_cells = static_cast<int>(count_in(*t, "tile_cells", s.tile_cells, 1, 4096));
    s.repeats = static_cast<int>(count_in(*t, "repeats", s.repeats, 1, 100));
    s.checkpoint_every = count_in(*t, "checkpoint_every", s.checkpoint_every, 1, 1000000);
    s.field_tolerance = positive(*t, "field_tolerance", s.field_tolerance);
    s.time_tolerance_s = positive(*t, "time_tolerance_s", s.time_tolerance_s);
    t->finish();
  }
  if (auto t = top.maybe_table("grid")) {
    SceneGridOptions& g = o.grid;
    known_case(*t, "case", g.case_name);
    g.cell_fractions = refining_fractions(*t, "cell_fractions", g.cell_fractions, 3, "the case's cell");
    g.pond_m = positive(*t, "pond_m", g.pond_m);
    t->require_in("pond_m", g.pond_m, 0.01, 1000.0);
    g.after_s = t->number_or("after_s", g.after_s);
    t->require_in("after_s", g.after_s, 0.0, 100.0);
    if (auto widths = t->maybe_numbers("head_widths_m")) {
      g.head_widths_m = *widths;
      for (double w : g.head_widths_m)
        if (!(w > 0 && w <= 1)) t->fail("head_widths_m", "each a width in (0, 1] m (the head's standard deviation)");
    }
    const std::string problem = grid_case_problem(o);
    if (!problem.empty()) t->fail("case", problem);
    g.step_fractions = refining_fractions(*t, "step_fractions", g.step_fractions, 2, "the case's water step");
    g.reference_step_fraction = positive(*t, "reference_step_fraction", g.reference_step_fraction);
    if (!(g.reference_step_fraction < g.step_fractions.back()))
      t->fail("reference_step_fraction", "must be below the finest of step_fractions (" + std::to_string(g.step_fractions.back()) + ")");
    t->finish();
  } else if (const std::string problem = grid_case_problem(o); !problem.empty()) {
    top.fail("grid", problem + " (without [grid] the section takes the first case)");
  }
  {
    HeadlineSpeedOptions& h = o.speed.headline;
    h.scene = o.cases.front().scene;
    if (o.duration_cap_s > 0) h.scene.duration_s = std::min(h.scene.duration_s, o.duration_cap_s);
    h.stencil.stencil = h.scene.water->field.stencil;
    std::string sweep_file = "../spin_sweep_base.toml";
    std::optional<TomlTable> t = top.maybe_table("speed");
    if (t) {
      h.scene_repeats = static_cast<int>(count_in(*t, "scene_repeats", h.scene_repeats, 1, 100));
      h.many_threads = static_cast<int>(count_in(*t, "many_threads", h.many_threads, 1, 64));
      h.stencil_small_n = static_cast<int>(count_in(*t, "stencil_small_n", h.stencil_small_n, 8, 16384));
      h.stencil_large_n = static_cast<int>(count_in(*t, "stencil_large_n", h.stencil_large_n, 8, 16384));
      h.stencil.samples = static_cast<int>(count_in(*t, "stencil_samples", h.stencil.samples, 1, 10000));
      h.stencil.sample_s = positive(*t, "stencil_sample_s", h.stencil.sample_s);
      sweep_file = t->string_or("sweep_case", sweep_file);
      h.sweep.workers = static_cast<int>(count_in(*t, "sweep_workers", h.sweep.workers, 1, 64));
      h.sweep.repeats = static_cast<int>(count_in(*t, "sweep_repeats", h.sweep.repeats, 1, 100));
      o.speed.scene_fps_target = positive(*t, "scene_fps_target", o.speed.scene_fps_target);
      o.speed.bandwidth_fraction_target = positive(*t, "bandwidth_fraction_target", o.speed.bandwidth_fraction_target);
      o.speed.per_cell_ratio_target = positive(*t, "per_cell_ratio_target", o.speed.per_cell_ratio_target);
      o.speed.throws_per_s_target = positive(*t, "throws_per_s_target", o.speed.throws_per_s_target);
    }
    TomlTable& st = t ? *t : top;
    const StoneCase sweep = load_case(dir, st, t ? "sweep_case" : "speed", sweep_file);
    if (!sweep.throw_from_parameters) st.fail(t ? "sweep_case" : "speed", "the sweep varies spin and attack angle: the case needs [throw] parameters");
    h.sweep.base = problem_from_case(sweep);
    f.settings_text += "\n# " + (dir / sweep_file).string() + "\n" + sweep.text;
    h.sweep.spins_rev_s = {0, 10, 20, 30, 40, 50, 60};
    h.sweep.attack_angles_deg = {0, 10, 20, 30};
    if (t) {
      h.sweep.spins_rev_s = range_of(*t, "sweep_spin_range", h.sweep.spins_rev_s);
      h.sweep.attack_angles_deg = range_of(*t, "sweep_attack_range_deg", h.sweep.attack_angles_deg);
      t->finish();
    }
  }
  if (auto t = top.maybe_table("frames")) {
    StillFrameOptions& s = o.frames;
    s.threshold_fraction = t->number_or("threshold_fraction", s.threshold_fraction);
    t->require_in("threshold_fraction", s.threshold_fraction, 1e-6, 0.99);
    s.top_cells_max = static_cast<int>(count_in(*t, "top_cells_max", s.top_cells_max, 16, 2000));
    s.near_cells_max = static_cast<int>(count_in(*t, "near_cells_max", s.near_cells_max, 8, 1000));
    s.near_window_m = positive(*t, "near_window_m", s.near_window_m);
    s.margin_m = t->number_or("margin_m", s.margin_m);
    t->require_non_negative("margin_m", s.margin_m);
    t->finish();
  }
  top.finish();
  std::string why;
  if (!o.valid(&why)) throw_input_error(path, 0, "study", why);
  return f;
}

}  // namespace stoneskip
