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

std::string grid_case_problem(const SceneStudiesOptions& o) {
  const SceneStudyCase* c = &o.cases.front();
  for (const auto& k : o.cases)
    if (k.name == o.grid.case_name) c = &k;
  const auto& z = c->scene.water ? c->scene.water->initial_m : std::vector<double>{};
  const bool still = std::all_of(z.begin(), z.end(), [](double v) { return v == 0; });
  if (c->initial) {
    const std::string why = resample_problem(*c->initial);
    if (why.empty() || still) return "";
    return "'" + c->name + "' starts from a disturbed surface the grid section's ponds cannot sample afresh ([water.initial]): " + why;
  }
  if (still) return "";
  return "'" + c->name + "' starts from a disturbed surface given as heights on its own grid, without a shape ([water.initial]) "
         "that the grid section's ponds could sample afresh; name a case on still water or one with [water.initial]";
}

bool SceneStudiesOptions::valid(std::string* why) const {
  auto fail = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (cases.empty()) return fail("no scene cases");
  for (const auto& c : cases) {
    std::string w;
    if (!c.scene.valid(&w)) return fail(c.name + ": " + w);
    if (!c.scene.water || c.scene.coupling == Coupling::none) return fail(c.name + ": the scene studies need a field ([water])");
  }
  auto known = [&](const std::string& n) {
    return n.empty() || std::any_of(cases.begin(), cases.end(), [&](const SceneStudyCase& c) { return c.name == n; });
  };
  if (!known(rings_case)) return fail("rings: no case named '" + rings_case + "'");
  if (!known(shortcuts.case_name)) return fail("shortcuts: no case named '" + shortcuts.case_name + "'");
  std::string w;
  if (!stability.is_valid(&w)) return fail("stability: " + w);
  if (!rings.is_valid(&w)) return fail("rings: " + w);
  if (!frames.is_valid(&w)) return fail("frames: " + w);
  if (!convergence.forced.is_valid(&w)) return fail("convergence: " + w);
  for (const auto& s : convergence.stencils)
    if (!is_stencil_name(s)) return fail("convergence: unknown stencil '" + s + "'");
  if (shortcuts.repeats < 1 || shortcuts.checkpoint_every < 1) return fail("shortcuts: repeats and checkpoint_every must be >= 1");
  for (double e : shortcuts.epsilons_m)
    if (!(e > 0)) return fail("shortcuts: epsilons must be > 0 (ε = 0 is always run)");
  if (!(duration_cap_s >= 0)) return fail("duration_cap_s must be >= 0");
  if (!known(grid.case_name)) return fail("grid: no case named '" + grid.case_name + "'");
  {
    const std::string problem = grid_case_problem(*this);
    if (!problem.empty()) return fail("grid: " + problem);
  }
  if (grid.cell_fractions.size() < 3) return fail("grid: at least three cell fractions (the differences of three grids)");
  for (std::size_t i = 0; i < grid.cell_fractions.size(); ++i)
    if (!(grid.cell_fractions[i] > 0 && grid.cell_fractions[i] <= 1) || (i > 0 && !(grid.cell_fractions[i] < grid.cell_fractions[i - 1])))
      return fail("grid: cell fractions must lie in (0, 1] and decrease strictly (coarse to fine)");
  if (!(grid.pond_m > 0) || !(grid.after_s >= 0)) return fail("grid: pond_m > 0 and after_s >= 0");
  for (double width : grid.head_widths_m)
    if (!(width > 0 && width <= 1)) return fail("grid: head widths must lie in (0, 1] m");
  if (grid.step_fractions.size() < 2) return fail("grid: at least two step fractions");
  for (std::size_t i = 0; i < grid.step_fractions.size(); ++i)
    if (!(grid.step_fractions[i] > 0 && grid.step_fractions[i] <= 1) || (i > 0 && !(grid.step_fractions[i] < grid.step_fractions[i - 1])))
      return fail("grid: step fractions must lie in (0, 1] and decrease strictly (coarse to fine)");
  if (!(grid.reference_step_fraction > 0 && grid.reference_step_fraction < grid.step_fractions.back()))
    return fail("grid: the reference step fraction must be > 0 and below the finest step fraction");
  return true;
}

// ---- settings ---------------------------------------------------------------------------------

Record scene_settings_findings(const SceneStudiesOptions& o) {
  Record r;
  r.set("preset", o.preset);
  std::vector<std::string> names;
  for (const auto& c : o.cases) {
    names.push_back(c.name);
    store_scene_settings(r.child(c.name), c, capped(o, c.scene));
  }
  r.set_strings("cases", names);
  r.set("duration_cap_s", o.duration_cap_s);
  return r;
}

// ---- stability --------------------------------------------------------------------------------

Record scene_stability_findings(const SceneStudiesOptions& o) {
  const CoupledStability s = measure_coupled_stability(o.stability);
  Record r;
  r.set("stencil", s.stencil);
  r.set("free_limit", s.free_limit);
  r.set("coupled_limit", s.coupled_limit);
  r.set("margin", o.stability.margin);
  r.set("n", o.stability.n);
  r.set("steps", o.stability.steps);
  r.set("steps_above", o.stability.steps_above);
  r.set("sigma_below", s.sigma_below);
  r.set("sigma_above", s.sigma_above);
  r.set("growth_below", s.growth_below);
  r.set("growth_above", s.growth_above);
  r.set("growth_free_above", s.growth_free_above);
  r.set("departure_above_m", s.departure_above_m);
  Record in;
  in.set("growth_below", s.growth_below);
  in.set("growth_above", s.growth_above);
  in.set("growth_free_above", s.growth_free_above);
  in.set("growth_tolerance", o.stability_growth_tolerance);
  decide_verdict(r, "verdict", "coupled_limit", in,
                 "with the stone held on the water the departure from its equilibrium grows by ×" + num(s.growth_below, 5) + " per step at σ = " +
                     num(s.sigma_below, 4) + " and by ×" + num(s.growth_above, 4) + " at σ = " + num(s.sigma_above, 4) +
                     ", while without the stone σ = " + num(s.sigma_above, 4) + " gives ×" + num(s.growth_free_above, 5));
  return r;
}

// ---- convergence ------------------------------------------------------------------------------

Record scene_convergence_findings(const SceneStudiesOptions& o, const ProgressFactory& progress) {
  Record out;
  const ForcedConvergenceOptions& f = o.convergence.forced;
  out.set("draught_depth_m", f.problem.draught.depth_m);
  out.set("draught_width_m", f.problem.draught.width_m);
  out.set("draught_speed_m_s", std::hypot(f.problem.draught.vx_m_s, f.problem.draught.vy_m_s));
  out.set("wave_speed_m_s", f.problem.wave.wave_speed_m_s);
  out.set("damping_per_s", f.problem.wave.damping_per_s);
  out.set("t_end_s", f.problem.wave.t_end_s);
  out.set("length_m", f.problem.wave.length_m);
  out.set("expected_order", f.judgement.expected_order);
  out.set("tolerance", f.judgement.tolerance);
  out.set_table("space_grids", value_list(std::vector<double>(f.space_grids.begin(), f.space_grids.end())));
  out.set_table("time_steps", value_list(std::vector<double>(f.time_steps.begin(), f.time_steps.end())));
  out.set_table("both_grids", value_list(std::vector<double>(f.both_grids.begin(), f.both_grids.end())));
  out.set("time_grid", f.time_grid);
  out.set("both_sigma", f.both_sigma);
  std::vector<std::string> walls;
  for (const Boundary b : f.walls) walls.push_back(to_string(b));
  out.set_strings("walls", walls);
  out.set("walls_t_end_s", f.walls_t_end_s);
  out.set_strings("stencils", o.convergence.stencils);
  auto ticker = start_progress(progress, "scene: forced convergence", o.convergence.stencils.size());
  for (const auto& name : o.convergence.stencils) {
    const ForcedConvergenceStudy s = run_forced_convergence(named_stencil(name), f);
    Record& r = out.child(name);
    std::vector<const ConvergenceSequence*> sequences{&s.space, &s.time, &s.both};
    for (const ConvergenceSequence& q : s.walls) sequences.push_back(&q);
    for (const ConvergenceSequence* q : sequences) {
      Record& k = r.child(q->kind);
      Table t = table({"n", "steps", "h", "l2_error_m", "max_error_m"});
      t.units = {"1", "1", q->kind == "time" ? "s" : "m", "m", "m"};  // h: Δt (time) or d (space, both)
      for (const auto& p : q->points) t.add_row({double(p.n), double(p.steps), p.h, p.l2_m, p.max_m});
      k.set_table("points", t);
      store_order_fit(k, "fit", q->fit, f.judgement);
    }
    r.set("reference_quadrature_m", s.reference_quadrature_m);
    r.set("smallest_error_m", s.smallest_error_m);
    r.set("reference_transforms", s.reference_transforms);
    ticker->tick();
  }
  return out;
}

// ---- rings ------------------------------------------------------------------------------------

Record scene_rings_findings(const SceneStudiesOptions& o) {
  const SceneStudyCase& c = find_case(o, o.rings_case);
  const SceneOptions scene = capped(o, c.scene);
  const RingSpeed s = measure_ring_speed(scene, o.rings);
  Record r;
  r.set("case", c.name);
  r.set("title", c.title);
  r.set("contact", o.rings.contact + 1);
  r.set("start_after_s", o.rings.start_after_s);
  r.set("end_after_s", o.rings.end_after_s);
  r.set("min_radius_m", o.rings.min_radius_m);
  r.set("max_radius_m", o.rings.max_radius_m);
  r.set("found", s.found);
  r.set("problem", s.problem);
  r.set("stencil", scene.water->field.stencil.name);
  r.set("courant", scene.water->field.courant());
  r.set("cell_m", scene.water->field.cell_m);
  r.set("c_m_s", s.c_m_s);
  r.set("centre_x_m", s.centre_x_m);
  r.set("centre_y_m", s.centre_y_m);
  r.set("contact_end_s", s.contact_end_s);
  r.set("speed_m_s", s.found ? s.speed_m_s : kNaN);
  r.set("speed_low_m_s", s.found ? s.speed_low_m_s : kNaN);
  r.set("speed_high_m_s", s.found ? s.speed_high_m_s : kNaN);
  r.set("r_squared", s.found ? s.r_squared : kNaN);
  r.set("intercept_m", s.found ? s.intercept_m : kNaN);
  r.set("wavelength_m", s.found ? s.wavelength_m : kNaN);
  r.set("kd", s.found ? s.kd : kNaN);
  r.set("phase_speed_m_s", s.found ? s.phase_speed_m_s : kNaN);
  r.set("group_speed_m_s", s.found ? s.group_speed_m_s : kNaN);
  Table t = table({"t_s", "radius_m"});
  for (std::size_t k = 0; k < s.t_s.size(); ++k) t.add_row({s.t_s[k], s.radius_m[k]});
  r.set_table("radius", t);
  Table p = table({"r_m", "rms_m", "mean_m"});
  for (std::size_t k = 0; k < s.profile_r_m.size(); ++k) p.add_row({s.profile_r_m[k], s.profile_rms_m[k], s.profile_mean_m[k]});
  r.set_table("profile", p);
  r.set("profile_t_s", s.profile_t_s);
  const bool valid = s.found && std::isfinite(s.group_speed_m_s);
  Record in;
  in.set("valid", valid);
  in.set("speed_low", valid ? s.speed_low_m_s : kNaN);
  in.set("speed_high", valid ? s.speed_high_m_s : kNaN);
  in.set("predicted_low", valid ? s.group_speed_m_s : kNaN);
  in.set("predicted_high", s.c_m_s);
  std::string reason;
  if (!s.found) reason = "no ring was measured: " + s.problem;
  else if (!valid)
    reason = "the ring spreads at " + num(s.speed_m_s, 4) + " m/s, but its wavelength could not be read from the profile";
  else
    reason = "the leading edge spreads at " + num(s.speed_m_s, 4) + " m/s [" + num(s.speed_low_m_s, 4) + ", " + num(s.speed_high_m_s, 4) +
             "] (" + num(s.speed_m_s / s.c_m_s, 3) + " c); the ring's wavelength " + num(100 * s.wavelength_m, 3) + " cm (kd = " + num(s.kd, 3) +
             ") travels at " + num(s.phase_speed_m_s, 4) + " m/s (phase) and " + num(s.group_speed_m_s, 4) +
             " m/s (group) in this scheme, c = " + num(s.c_m_s, 4) + " m/s";
  decide_verdict(r, "verdict", "ring_speed", in, reason);
  return r;
}

// ---- all --------------------------------------------------------------------------------------

Record run_scene_studies(const SceneStudiesOptions& o, StudySink& sink) {
  std::string why;
  if (!o.valid(&why)) throw std::invalid_argument("scene study settings: " + why);
  const ProgressFactory& p = sink.progress();
  run_section(sink, "settings", [&] { return scene_settings_findings(o); });
  run_section(sink, "coupling", [&] { return scene_coupling_findings(o, p); });
  run_section(sink, "stability", [&] { return scene_stability_findings(o); });
  run_section(sink, "convergence", [&] { return scene_convergence_findings(o, p); });
  run_section(sink, "rings", [&] { return scene_rings_findings(o); });
  run_section(sink, "shortcuts", [&] { return scene_shortcuts_findings(o, p); });
  run_section(sink, "grid", [&] { return scene_grid_findings(o, p); });
  run_section(sink, "speed", [&] { return scene_speed_findings(o, p); });
  run_section(sink, "frames", [&] { return scene_frames_findings(o, p); });
  Record root;
  root.set("preset", o.preset);
  return root;
}

}  // namespace stoneskip
