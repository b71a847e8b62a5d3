#include "verification/scene/scene_studies.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "verification/scene/scene_probe.hpp"
#include "verification/study/order_record.hpp"
#include "verification/study/verdict_rules.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Table table(std::vector<std::string> columns) { return Table{std::move(columns), {}}; }

// The scene as the study runs it: cut to the preset's duration cap.
SceneOptions capped(const SceneStudiesOptions& o, SceneOptions s) {
  if (o.duration_cap_s > 0) s.duration_s = std::min(s.duration_s, o.duration_cap_s);
  return s;
}

const SceneStudyCase& find_case(const SceneStudiesOptions& o, const std::string& name) {
  if (name.empty()) return o.cases.front();
  for (const auto& c : o.cases)
    if (c.name == name) return c;
  throw std::invalid_argument("scene study: no case named '" + name + "'");
}

std::string us(double s) { return num(1e6 * s, 3) + " µs"; }
std::string ms(double s) { return num(1e3 * s, 3) + " ms"; }
std::string mm(double m) { return num(1e3 * m, 3) + " mm"; }

Table contacts_table(const ThrowResult& r) {
  Table t = table({"start_s", "end_s", "touch_x_m", "touch_y_m", "exit_speed_m_s", "bounced"});
  for (const auto& c : r.contacts)
    t.add_row({c.start_s, c.end_s, c.first_touch_m.x(), c.first_touch_m.y(), c.exit_speed_m_s, c.bounced ? 1.0 : 0.0});
  return t;
}

// A matrix (rows y, columns x) as a table with one column per x.
Table matrix_table(const std::vector<double>& v, int nx, int ny) {
  std::vector<std::string> cols;
  for (int i = 0; i < nx; ++i) cols.push_back("x" + std::to_string(i));
  Table t = table(cols);
  for (int j = 0; j < ny; ++j) t.add_row(std::vector<double>(v.begin() + static_cast<long>(j) * nx, v.begin() + static_cast<long>(j + 1) * nx));
  return t;
}

Table xy_table(const std::vector<double>& x, const std::vector<double>& y) {
  Table t = table({"x_m", "y_m"});
  for (std::size_t k = 0; k < x.size(); ++k) t.add_row({x[k], y[k]});
  return t;
}

void store_scene_settings(Record& r, const SceneStudyCase& c, const SceneOptions& s) {
  r.set("title", c.title);
  r.set("file", c.file);
  r.set("convention", std::string(to_string(s.environment.convention)));
  r.set("coupling", std::string(to_string(s.coupling)));
  r.set("frame_rate_hz", s.frame_rate_hz);
  r.set("duration_s", s.end_s());
  r.set("frames", s.frames());
  r.set("stone", s.stone.description);
  r.set("stone_radius_m", s.stone.disk_radius_m);
  r.set("speed_m_s", s.initial.velocity_m_s.norm());
  r.set("contact_dt_s", s.stone_steps.contact_dt_s);
  r.set("draught_samples", s.draught_samples);
  if (s.water) {
    const HeightFieldOptions& f = s.water->field;
    r.set("nx", f.nx);
    r.set("ny", f.ny);
    r.set("cell_m", f.cell_m);
    r.set("wave_speed_m_s", f.wave_speed_m_s);
    r.set("damping_per_s", f.damping_per_s);
    r.set("water_dt_s", f.dt_s);
    r.set("courant", f.courant());
    r.set("coupled_limit", coupled_courant_limit(f.stencil));
    r.set("stencil", f.stencil.name);
    r.set("precision", std::string(to_string(f.precision)));
    r.set("mode", std::string(to_string(f.mode)));
  }
}

}  // namespace

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

// ---- coupling ---------------------------------------------------------------------------------

Record scene_coupling_findings(const SceneStudiesOptions& o, const ProgressFactory& progress) {
  Record out;
  std::vector<std::string> names;
  auto ticker = start_progress(progress, "scene: coupling", 3 * o.cases.size());
  for (const auto& c : o.cases) {
    names.push_back(c.name);
    SceneOptions two = capped(o, c.scene), one = two, none = two;
    two.coupling = Coupling::two_way;
    one.coupling = Coupling::one_way;
    none.coupling = Coupling::none;
    const ProbedScene a = run_probed(two, 0, 1);
    ticker->tick();
    const ProbedScene b = run_probed(one, 0, 1);
    ticker->tick();
    const ProbedScene n = run_probed(none, 0, 1);
    ticker->tick();
    Record& r = out.child(c.name);
    store_scene_settings(r.child("settings"), c, two);
    const double radius = two.stone.disk_radius_m, cw = two.water->field.wave_speed_m_s;
    r.set("footprint_time_s", 2 * radius / cw);
    for (const auto& [key, p] : {std::pair<const char*, const ProbedScene*>{"two_way", &a}, {"one_way", &b}, {"none", &n}}) {
      Record& k = r.child(key);
      k.set_table("contacts", contacts_table(p->summary.stone));
      k.set("contacts", static_cast<long>(p->summary.stone.contacts.size()));
      k.set("bounces", p->summary.stone.bounces);
      k.set("outcome", std::string(to_string(p->summary.stone.outcome)));
      k.set("end_time_s", p->summary.stone.end_time_s);
      k.set("distance_m", p->summary.stone.distance_m);
    }
    const SceneDifference d = compare_scenes(a, b);
    const SceneDifference still = compare_scenes(b, n);
    r.set("one_way_equals_still", still.identical());
    r.set("max_start_change_s", d.max_start_change_s);
    r.set("max_end_change_s", d.max_end_change_s);
    r.set("max_touch_change_m", d.max_touch_change_m);
    r.set("first_exit_speed_change_m_s", d.first_contact_exit_speed_change_m_s);
    // Why they differ: the draught and the water under the stone, contact by contact.
    Table e = table({"start_s", "end_s", "max_volume_m3", "volume_time_m3_s", "surface_at_start_m", "lowest_surface_m"});
    for (const auto& x : a.summary.episodes)
      e.add_row({x.start_s, x.end_s, x.max_volume_m3, x.volume_time_m3_s, x.surface_at_start_m, x.lowest_surface_m});
    r.set_table("draught_episodes", e);
    r.set("max_draught_volume_m3", a.summary.max_draught_volume_m3);
    r.set("water_volume_change_m3", a.summary.volume_end_m3 - a.summary.volume_start_m3);
    const auto& ca = a.summary.stone.contacts;
    std::string why;
    if (!ca.empty() && !a.summary.episodes.empty()) {
      const DraughtEpisode& first = a.summary.episodes.front();
      const double duration = ca.front().end_s - ca.front().start_s;
      const double depression = first.surface_at_start_m - first.lowest_surface_m;
      const double mean_draught = first.max_volume_m3 / (M_PI * radius * radius);
      r.set("first_contact_duration_s", duration);
      r.set("first_depression_m", depression);
      r.set("first_mean_draught_m", mean_draught);
      why = "the first contact lasts " + ms(duration) + ", " + num(duration / (2 * radius / cw), 2) +
            " of the time footprint/c = " + num(2 * radius / cw, 3) + " s in which the water under the stone can answer it (spec §2.4): the stone's draught (up to " +
            num(1e6 * first.max_volume_m3, 3) + " cm³, " + mm(mean_draught) + " deep over its disk) lowered the water under its centre by " +
            mm(depression) + " before it left";
      double worst = 0;
      std::size_t at = 0;
      for (std::size_t k = 0; k < a.summary.episodes.size(); ++k) {
        const auto& x = a.summary.episodes[k];
        if (x.surface_at_start_m - x.lowest_surface_m > worst) {
          worst = x.surface_at_start_m - x.lowest_surface_m;
          at = k;
        }
      }
      if (a.summary.episodes.size() > 1)
        why += "; the deepest depression under the stone in any contact was " + mm(worst) + " (contact " + std::to_string(at + 1) + " of " +
               std::to_string(a.summary.episodes.size()) + ")";
      if (d.common > 0)
        why += "; after the first contact the two runs leave at speeds " + num(d.first_contact_exit_speed_change_m_s, 2) + " m/s apart";
    } else {
      why = "the stone never touched the water";
    }
    r.set("why", why);
    const long count_change = std::labs(d.contacts_a - d.contacts_b) + std::abs(d.bounces_a - d.bounces_b);
    std::ostringstream reason;
    reason << "two-way: " << d.contacts_a << " contacts (" << d.bounces_a << " bounces) in " << num(two.end_s(), 3) << " s against one-way's "
           << d.contacts_b << " (" << d.bounces_b << "); over the first " << d.common << " contacts the times differ by up to "
           << us(std::max(d.max_start_change_s, d.max_end_change_s)) << " and the first touches by up to " << mm(d.max_touch_change_m);
    Record in;
    in.set("count_change", static_cast<double>(count_change));
    in.set("max_time_change_s", std::max(d.max_start_change_s, d.max_end_change_s));
    in.set("time_tolerance_s", o.coupling.time_tolerance_s);
    decide_verdict(r, "verdict", "coupling_change", in, reason.str());
  }
  out.set_strings("cases", names);
  out.set("time_tolerance_s", o.coupling.time_tolerance_s);
  return out;
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
  out.set_strings("stencils", o.convergence.stencils);
  auto ticker = start_progress(progress, "scene: forced convergence", o.convergence.stencils.size());
  for (const auto& name : o.convergence.stencils) {
    const ForcedConvergenceStudy s = run_forced_convergence(named_stencil(name), f);
    Record& r = out.child(name);
    for (const ConvergenceSequence* q : {&s.space, &s.time, &s.both}) {
      Record& k = r.child(q->kind);
      Table t = table({"n", "steps", "h", "l2_error_m", "max_error_m"});
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

// ---- shortcuts --------------------------------------------------------------------------------

Record scene_shortcuts_findings(const SceneStudiesOptions& o, const ProgressFactory& progress) {
  const SceneStudyCase& c = find_case(o, o.shortcuts.case_name);
  const SceneShortcutOptions& so = o.shortcuts;
  SceneOptions base = capped(o, c.scene);
  base.coupling = Coupling::two_way;
  base.water->field.mode = StepMode::full;
  base.water->field.precision = Precision::float64;
  base.water->field.threads = 1;
  struct Variant {
    std::string key, what;
    SceneOptions reference, shortcut;
  };
  std::vector<Variant> v;
  {
    SceneOptions one = base, none = base;
    one.coupling = Coupling::one_way;
    none.coupling = Coupling::none;
    v.push_back({"no_field", "no field at all (coupling none) against one-way on the still pond", one, none});
  }
  {
    SceneOptions t = base;
    t.water->field.mode = StepMode::active_tiles;
    t.water->field.tiles.tile_cells = so.tile_cells;
    t.water->field.tiles.epsilon_m = 0;
    v.push_back({"tiles_eps_0", "active tiles, ε = 0", base, t});
    for (std::size_t k = 0; k < so.epsilons_m.size(); ++k) {
      t.water->field.tiles.epsilon_m = so.epsilons_m[k];
      v.push_back({"tiles_eps_" + std::to_string(k + 1), "active tiles, ε = " + num(so.epsilons_m[k], 2) + " m", base, t});
    }
  }
  {
    SceneOptions f = base;
    f.water->field.precision = Precision::float32;
    v.push_back({"float32", "float32 heights", base, f});
  }
  {
    SceneOptions k1 = base;
    k1.draught_samples = 1;
    v.push_back({"one_sample", "one draught sample per water step (the spec's point sample) against " + std::to_string(base.draught_samples), base, k1});
  }
  {
    SceneOptions everywhere = base;
    everywhere.stone_steps.dt_s = everywhere.stone_steps.contact_dt_s;
    v.push_back({"contact_step_near_water", "the contact step only near the water (" + num(base.stone_steps.dt_s, 2) + " s in flight) against " +
                                                num(base.stone_steps.contact_dt_s, 2) + " s everywhere",
                 everywhere, base});
  }
  Record out;
  out.set("case", c.name);
  out.set("title", c.title);
  out.set("repeats", so.repeats);
  out.set("checkpoint_every", so.checkpoint_every);
  out.set("field_tolerance", so.field_tolerance);
  out.set("time_tolerance_s", so.time_tolerance_s);
  out.set("tile_cells", so.tile_cells);
  std::vector<std::string> keys;
  auto ticker = start_progress(progress, "scene: shortcuts", v.size());
  // The base is the reference of most variants: run it once.
  const ProbedScene base_run = run_probed(base, so.checkpoint_every, so.repeats);
  for (const auto& x : v) {
    const bool same_ref = x.key != "no_field" && x.key != "contact_step_near_water";
    const ProbedScene ref = same_ref ? base_run : run_probed(x.reference, so.checkpoint_every, so.repeats);
    const ProbedScene cut = run_probed(x.shortcut, so.checkpoint_every, so.repeats);
    const SceneDifference d = compare_scenes(ref, cut);
    Record& r = out.child(x.key);
    keys.push_back(x.key);
    r.set("what", x.what);
    r.set("field_max_change_m", d.field_max_change_m);
    r.set("field_scale_m", d.field_scale_m);
    r.set("field_relative", d.field_relative());
    r.set("start_change_s", std::max(d.max_start_change_s, d.max_end_change_s));
    r.set("touch_change_m", d.max_touch_change_m);
    r.set("contacts_reference", d.contacts_a);
    r.set("contacts_shortcut", d.contacts_b);
    r.set("count_change", static_cast<double>(std::labs(d.contacts_a - d.contacts_b) + std::abs(d.bounces_a - d.bounces_b)));
    r.set("reference_cpu_s", ref.min_cpu_s);
    r.set("shortcut_cpu_s", cut.min_cpu_s);
    r.set("saving", ref.min_cpu_s > 0 ? 1 - cut.min_cpu_s / ref.min_cpu_s : kNaN);
    r.set("tile_fraction", cut.summary.tiles.fraction());
    Record in;
    in.set("field_relative", d.field_relative());
    in.set("start_change_s", std::max(d.max_start_change_s, d.max_end_change_s));
    in.set("count_change", static_cast<double>(std::labs(d.contacts_a - d.contacts_b) + std::abs(d.bounces_a - d.bounces_b)));
    in.set("field_tolerance", so.field_tolerance);
    in.set("time_tolerance_s", so.time_tolerance_s);
    std::ostringstream reason;
    reason << "largest surface difference " << num(d.field_max_change_m, 2) << " m (" << num(d.field_relative(), 2) << " of the largest |z|), contacts moved by up to "
           << us(std::max(d.max_start_change_s, d.max_end_change_s)) << ", " << d.contacts_b << " contacts against " << d.contacts_a << "; CPU "
           << ms(cut.min_cpu_s) << " against " << ms(ref.min_cpu_s) << " (" << num(100 * (ref.min_cpu_s > 0 ? 1 - cut.min_cpu_s / ref.min_cpu_s : 0), 3)
           << " % saved)";
    decide_verdict(r, "verdict", "shortcut", in, reason.str());
    ticker->tick();
  }
  out.set_strings("shortcuts", keys);
  return out;
}

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
  r.set("sweep_contact_dt_s", h.sweep.base.realtime.contact_dt_s);
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
      r.set("near_x0_m", s.near_x0_m);
      r.set("near_y0_m", s.near_y0_m);
      r.set("near_dx_m", s.near_dx_m);
      r.set_table("near", matrix_table(s.near_m, s.near_n, s.near_n));
      r.set_table("track", xy_table(s.track_x_m, s.track_y_m));
      r.set_table("touches", xy_table(s.touch_x_m, s.touch_y_m));
      r.set("why", "frame " + std::to_string(s.frame) + " of " + std::to_string(s.frames) + " (t = " + num(s.t_s, 3) + " s) has the most disturbed water, " +
                       std::to_string(s.disturbed_cells) + " cells above " + num(1e3 * s.threshold_m, 2) + " mm (" +
                       num(100 * o.frames.threshold_fraction, 2) + " % of the scene's largest |z|, " + num(1e3 * s.largest_m, 3) + " mm), among the " +
                       std::to_string(s.frames_considered) + " frames before the waves reach the pond's edge");
    }
    ticker->tick();
  }
  out.set_strings("cases", names);
  out.set("threshold_fraction", o.frames.threshold_fraction);
  return out;
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
  run_section(sink, "speed", [&] { return scene_speed_findings(o, p); });
  run_section(sink, "frames", [&] { return scene_frames_findings(o, p); });
  Record root;
  root.set("preset", o.preset);
  return root;
}

}  // namespace stoneskip
