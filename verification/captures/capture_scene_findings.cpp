#include "verification/captures/capture_scene_findings.hpp"

#include <algorithm>
#include <cmath>

#include "solvers/scene/pond_extent.hpp"
#include "verification/study/verdict_rules.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {

namespace {

std::string bounce_words(double n) { return num(n) + (n == 1 ? " bounce" : " bounces"); }

Table path_table(const ThrowResult& t) {
  Table p{{"t_s", "x_m", "z_m"}, {}};
  for (const auto& s : t.trajectory) p.add_row({s.t_s, s.state.position_m.x(), s.state.position_m.z()});
  return p;
}

Record settings(const CaptureSceneOptions& o, const std::string& case_file) {
  Record r;
  const SceneOptions& s = o.scene;
  r.set("case_file", case_file);
  r.set("coupling", std::string(to_string(s.coupling)));
  r.set("forcing", std::string(to_string(s.forcing)));  // pressure: the faces' pressure head; displacement: the draught b
  r.set("convention", std::string(to_string(s.environment.convention)));
  r.set("stone_description", s.stone.description);
  r.set("draught_samples", s.draught_samples);
  r.set("frame_rate_hz", s.frame_rate_hz);
  r.set("duration_s", s.end_s());
  r.set("stone_scheme", std::string(to_string(s.stone_steps.scheme)));
  r.set("stone_adaptive", is_adaptive(s.stone_steps.scheme));
  r.set("stone_rtol", s.stone_steps.rtol);
  r.set("stone_dt_s", s.stone_steps.dt_s);
  r.set("stone_contact_dt_s", s.stone_steps.contact_dt_s);
  r.set("reference_rtol", o.reference.rtol);
  r.set("reference_output_dt_s", o.reference_output_dt_s);
  r.set("quadrature_nodes", o.quadrature_nodes);
  r.set("quadrature_interval_s", o.quadrature_interval_s);
  const bool water = s.water.has_value();
  r.set("has_water", water);
  if (water) {
    const HeightFieldOptions& f = s.water->field;
    r.set("stencil", f.stencil.name);
    r.set("nx", f.nx).set("ny", f.ny).set("cell_m", f.cell_m);
    r.set("wave_speed_m_s", f.wave_speed_m_s).set("damping_per_s", f.damping_per_s);
    r.set("dt_s", f.dt_s).set("courant", f.courant());
    r.set("periodic", f.boundary == Boundary::periodic);
    r.set("boundary", std::string(to_string(f.boundary)));  // since 7 December: a walled pond's waves are compared too
    r.set("origin_x_m", s.water->placement.origin_x_m).set("origin_y_m", s.water->placement.origin_y_m);
  }
  return r;
}

Record stone(const CaptureSceneComparison& c, const CaptureSceneOptions& o) {
  Record r;
  r.set("scene_bounces", c.scene.stone.bounces);
  r.set("still_bounces", c.still_water.bounces);
  r.set("reference_bounces", c.reference.bounces);
  r.set("scene_contacts", c.scene.stone.contacts.size());
  r.set("reference_contacts", c.reference.contacts.size());
  r.set("scene_outcome", std::string(to_string(c.scene.stone.outcome)));
  r.set("reference_outcome", std::string(to_string(c.reference.outcome)));
  r.set("reference_outcome_detail", c.reference.outcome_detail);
  r.set("compared_contacts", c.contacts.size());
  r.set("max_start_difference_s", c.max_start_difference_s);
  r.set("max_end_difference_s", c.max_end_difference_s);
  r.set("still_max_start_difference_s", c.still_max_start_difference_s);
  Table t{{"index", "scene_start_s", "still_start_s", "reference_start_s", "scene_end_s", "still_end_s", "reference_end_s",
           "scene_exit_x_m", "reference_exit_x_m", "scene_bounced", "reference_bounced"},
          {}};
  for (const auto& k : c.contacts)
    t.add_row({double(k.index), k.scene_start_s, k.still_start_s, k.reference_start_s, k.scene_end_s, k.still_end_s,
               k.reference_end_s, k.scene_exit_x_m, k.reference_exit_x_m, double(k.scene_bounced),
               double(k.reference_bounced)});
  r.set_table("contacts", t);
  r.set_table("scene_path", path_table(c.scene.stone));
  r.set_table("still_path", path_table(c.still_water));
  r.set_table("reference_path", path_table(c.reference));
  r.set("frames", c.scene.frames);
  r.set("scene_cpu_s", c.scene.cpu_s).set("scene_wall_s", c.scene.wall_s);
  r.set("water_steps", c.scene.water_steps);
  r.set("reference_cpu_s", c.reference.stats.cpu_s).set("reference_wall_s", c.reference.stats.wall_s);
  // Contacts begun off a walled pond (solvers/scene/pond_extent.hpp): there the scene's stone read
  // the edge's height and a two-way field took none of its push (`capture throw --scene` prints it).
  std::string off;
  std::size_t off_count = 0;
  if (o.scene.water) {
    const PondExtent p = pond_extent(o.scene.water->field, o.scene.water->placement.origin_x_m,
                                     o.scene.water->placement.origin_y_m, c.scene.stone.contacts);
    off = off_pond_sentence(p, c.scene.stone.contacts, o.scene.coupling == Coupling::two_way);
    off_count = p.off.size();
  }
  r.set("contacts_off_pond", off_count);
  r.set("off_pond", off);
  auto made = [](const ThrowResult& run) {
    return (run.outcome == Outcome::failed ? "fails after " : "makes ") + bounce_words(run.bounces);
  };
  const std::string single =
      "in the scene's " + num(c.scene.simulated_s) + " s the scene's stone on the live water " + made(c.scene.stone) +
      ", the same stepper on still water " + made(c.still_water) + ", the CVODE reference on still water " +
      made(c.reference) + " (one run each); the " + num(double(c.contacts.size()), 9) + " contact(s) of the scene that overlap CVODE's in time start at most " +
      num(1e3 * c.max_start_difference_s) + " ms apart (the stepper on still water: " +
      num(1e3 * c.still_max_start_difference_s) + " ms)";
  r.set("single_runs", single);
  // The count is chaotic: the stepper and CVODE are judged on ensembles on the same (still) water,
  // never run against run. The live water's own change of the count is not judged here: one scene
  // is one run.
  decide_nudged_agreement(r, "agreement", c.agreement, single + "; on still water", "the stepper", "CVODE");
  return r;
}

Record waves(const CaptureSceneComparison& c, const CaptureSceneOptions& o) {
  Record r;
  r.set("compared", c.waves_compared);
  if (!c.waves_compared) {
    r.set("not_compared", c.waves_not_compared);
    return r;
  }
  const WaveComparison& w = c.waves;
  r.set("t_s", w.t_s).set("steps", w.steps);
  r.set("amplitude_m", w.amplitude_m);
  r.set("path_m", w.path_m).set("feedback_m", w.feedback_m);
  r.set("total_m", w.total_m).set("model_m", w.model_m).set("time_m", w.time_m).set("space_m", w.space_m);
  r.set("quadrature_m", w.quadrature_m);
  r.set("quadrature_intervals", w.quadrature_intervals);
  r.set("transforms", w.transforms);
  r.set("cpu_s", w.reference_cpu_s).set("wall_s", w.reference_wall_s);
  // The profile along the grid row nearest the first contact of the reference (else the middle row).
  const HeightFieldOptions& f = o.scene.water->field;
  const FieldPlacement& p = o.scene.water->placement;
  double y = p.origin_y_m + 0.5 * (f.ny - 1) * f.cell_m;
  if (!c.reference.contacts.empty()) y = c.reference.contacts.front().entry_position_m.y();
  int j = static_cast<int>(std::lround((y - p.origin_y_m) / f.cell_m));
  j = ((j % f.ny) + f.ny) % f.ny;
  auto row = [&](int jj) {
    Table t{{"x_m", "scene_m", "prescribed_m", "semi_discrete_m", "continuum_m"}, {}};
    for (int i = 0; i < f.nx; ++i) {
      const std::size_t k = static_cast<std::size_t>(jj) * f.nx + i;
      t.add_row({p.origin_x_m + i * f.cell_m, w.scene_m[k], w.prescribed_m[k], w.semi_discrete_m[k], w.continuum_m[k]});
    }
    return t;
  };
  r.set("row_y_m", p.origin_y_m + j * f.cell_m);
  r.set_table("profile", row(j));
  // … and along the row holding the largest |scene − continuum| (total_m), which the first
  // contact's row need not hold: the figure then shows the difference the table gives.
  std::size_t worst = 0;
  for (std::size_t k = 0; k < w.scene_m.size(); ++k)
    if (std::abs(w.scene_m[k] - w.continuum_m[k]) > std::abs(w.scene_m[worst] - w.continuum_m[worst])) worst = k;
  const int jw = static_cast<int>(worst / static_cast<std::size_t>(f.nx));
  r.set("worst_row_y_m", p.origin_y_m + jw * f.cell_m);
  r.set("worst_x_m", p.origin_x_m + static_cast<double>(worst % static_cast<std::size_t>(f.nx)) * f.cell_m);
  r.set_table("worst_profile", row(jw));
  const double smallest = std::min({w.time_m, w.space_m, w.total_m});
  Record in;
  in.set("reference_error_m", w.quadrature_m).set("smallest_error_m", smallest).set("margin", kReferenceMargin);
  decide_verdict(r, "reference", "reference_resolves", in,
                 "the forced spectral reference changes by " + num(w.quadrature_m) + " m when its " +
                     num(double(w.quadrature_intervals), 9) + " sub-intervals are halved in number; the smallest error it "
                     "measures here is " + num(smallest) + " m");
  return r;
}

}  // namespace

Record capture_scene_findings(const CaptureSceneComparison& c, const CaptureSceneOptions& o, const std::string& case_file) {
  Record r;
  r.add_child("settings", settings(o, case_file));
  r.add_child("stone", stone(c, o));
  r.add_child("waves", waves(c, o));
  return r;
}

}  // namespace stoneskip
