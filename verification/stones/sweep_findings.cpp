// Findings of the bounce-count sweeps (section "sweeps" of the stones report): each sweep's counts
// and bisected thresholds, and per parameter and convention what the comparison of the two
// solvers shows, decided here: where they agree, and whether the reference's count changes in
// clean steps or as soon as the parameter moves off a grid value (sensitive dependence).
#include <algorithm>
#include <cctype>
#include <cmath>

#include "tools/io/column_units.hpp"
#include "verification/stones/stone_studies.hpp"
#include "verification/study/verdict_rules.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {

std::string record_key(const std::string& label) {
  std::string s;
  for (char c : label) {
    if (std::isalnum(static_cast<unsigned char>(c)))
      s += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    else if (!s.empty() && s.back() != '_')
      s += '_';
  }
  while (!s.empty() && s.back() == '_') s.pop_back();
  return s.empty() ? "unnamed" : s;
}

Record history_record(const ThrowHistory& h) {
  Record g;
  g.set("label", h.label);
  g.set("solver", h.solver);
  g.set("convention", std::string(to_string(h.convention)));
  g.set("bounces", h.result.bounces);
  g.set("contact_count", h.result.contacts.size());
  g.set("outcome", std::string(to_string(h.result.outcome)));
  g.set("lateral_m", h.result.lateral_m);
  g.set("max_energy_gain_J", h.result.max_energy_gain_J);
  g.set_table("history", h.table);
  Table c{{"start_s", "end_s", "entry_speed_m_s", "exit_speed_m_s", "entry_energy_J", "exit_energy_J",
           "entry_attack_angle_deg", "exit_attack_angle_deg", "first_touch_x_m", "first_touch_y_m", "bounced"},
          {}};
  for (const auto& k : h.result.contacts)
    c.add_row({k.start_s, k.end_s, k.entry_speed_m_s, k.exit_speed_m_s, k.entry_energy_J, k.exit_energy_J,
               k.entry_attack_angle_deg, k.exit_attack_angle_deg, k.first_touch_m.x(), k.first_touch_m.y(),
               k.bounced ? 1.0 : 0.0});
  g.set_table("contacts", c);
  return g;
}

namespace {

const char* solver_word(const SolverChoice& s) { return s.kind == SolverKind::realtime ? "realtime" : "reference"; }

// Per parameter and convention: agreement of the solvers and the character of the thresholds.
void compare_solvers(Record& parent, const std::vector<const BounceSweepResult*>& list, Convention conv) {
  const BounceSweepResult* ref = nullptr;
  const BounceSweepResult* rt = nullptr;
  for (const auto* s : list)
    if (s->spec.convention == conv) (s->spec.solver.kind == SolverKind::reference ? ref : rt) = s;
  if (!ref || !rt) return;
  Record& r = parent.child(to_string(conv));
  const int n = static_cast<int>(ref->counts.size());
  int agree = 0, failed = 0, lo = 1 << 30, hi = -1;
  for (int i = 0; i < n; ++i) {
    agree += ref->counts[i] >= 0 && ref->counts[i] == rt->counts[i] ? 1 : 0;  // two failures agree on nothing
    if (ref->counts[i] < 0) {
      ++failed;
    } else {
      lo = std::min(lo, ref->counts[i]);
      hi = std::max(hi, ref->counts[i]);
    }
  }
  // A bisected threshold within two tolerances of a grid value: the count changes as soon as the
  // parameter moves off that value.
  int hugging = 0, bisected = 0, more = 0;
  for (const auto& x : ref->thresholds) {
    more += x.more_in_cell() ? 1 : 0;
    if (!x.bisected) continue;
    ++bisected;
    for (double v : ref->spec.values)
      if (std::abs(x.value() - v) <= 2 * ref->spec.threshold_tolerance) {
        ++hugging;
        break;
      }
  }
  r.set("grid_points", n);
  r.set("agree", agree);
  r.set("reference_failed", failed);
  r.set("reference_min_bounces", hi < 0 ? NAN : double(lo));
  r.set("reference_max_bounces", hi < 0 ? NAN : double(hi));
  r.set("reference_thresholds", ref->thresholds.size());
  r.set("bisected", bisected);
  r.set("near_grid", hugging);
  r.set("cells_with_more_changes", more);  // grid cells holding a change bisection did not follow
  const bool sensitive = bisected >= 3 && 2 * hugging >= bisected;
  const int unlocated = static_cast<int>(ref->thresholds.size()) - bisected + more;
  Record in;
  in.set("near_grid", hugging);
  in.set("bisected", bisected);
  in.set("unlocated", unlocated);
  decide_verdict(
      r, "character", "thresholds_near_grid", in,
      std::to_string(hugging) + " of the " + std::to_string(bisected) +
          " bisected changes of the reference count lie within two bisection tolerances of a grid value" +
          (sensitive ? ": the count changes as soon as the parameter moves off the grid value" : "") +
          (unlocated > 0 ? "; " + std::to_string(unlocated) +
                               " changes were not located (not bisected, bisection stopped at a failed run, or more in a grid "
                               "cell than the one bisected)"
                         : ""));
}

}  // namespace

Record sweeps_findings(const std::vector<BounceSweepResult>& sweeps) {
  Record r;
  if (!sweeps.empty()) {
    const ThrowProblem& b = sweeps.front().spec.base;
    Record& base = r.child("base");
    base.set("label", b.label);
    base.set("stone", b.stone.description);
    base.set("mass_kg", b.stone.mass.mass_kg);
    base.set("triangles", b.stone.body_mesh.triangles.size());  // to find it among the mesh study's meshes
    base.set("speed_m_s", b.parameters.speed_m_s);
    base.set("path_angle_deg", b.parameters.path_angle_deg);
    base.set("attack_angle_deg", b.parameters.attack_angle_deg);
    base.set("spin_rev_s", b.parameters.spin_rev_s);
    base.set("scheme", std::string(to_string(b.realtime.scheme)));
    base.set("adaptive", is_adaptive(b.realtime.scheme));
    base.set("rtol", b.realtime.rtol);
    base.set("atol_m", b.realtime.atol_m);
    base.set("dt_s", b.realtime.dt_s);
    base.set("contact_dt_s", b.realtime.contact_dt_s);
  }
  // One child per swept parameter (in order of first appearance), one per sweep inside it.
  std::vector<std::string> params;
  for (const auto& s : sweeps) {
    const std::string p = to_string(s.spec.parameter);
    if (std::find(params.begin(), params.end(), p) == params.end()) params.push_back(p);
  }
  r.set_strings("parameters", params);
  for (const auto& p : params) {
    Record& pr = r.child(p);
    std::vector<const BounceSweepResult*> list;
    std::vector<std::string> names;
    for (const auto& s : sweeps)
      if (to_string(s.spec.parameter) == p) {
        list.push_back(&s);
        names.push_back(s.spec.name);
      }
    pr.set_strings("sweeps", names);
    const std::string unit = column_unit(p);  // the swept parameter's name carries its unit ("spin_rev_s")
    pr.set_table("values", Table{{"value"}, list.front()->spec.values, {unit}});
    for (const auto* s : list) {
      Record& sr = pr.child(s->spec.name);
      sr.set("convention", std::string(to_string(s->spec.convention)));
      sr.set("solver", std::string(solver_word(s->spec.solver)));
      sr.set("solver_settings", s->spec.solver.label());
      sr.set("threshold_tolerance", s->spec.threshold_tolerance);
      sr.set("runs", s->runs);
      sr.set("cpu_s", s->cpu_s);
      Table t{{"value", "bounces"}, {}, {unit, "1"}};
      for (std::size_t i = 0; i < s->spec.values.size(); ++i) t.add_row({s->spec.values[i], double(s->counts[i])});
      sr.set_table("counts", t);
      sr.set_strings("failures", s->failures);
      Table th{{"lo", "hi", "count_below", "count_above", "bisected", "count_at_cell_end", "failed_at"},
               {},
               {unit, unit, "1", "1", "1", "1", unit}};
      for (const auto& x : s->thresholds)
        th.add_row({x.lo, x.hi, double(x.count_below), double(x.count_above), x.bisected ? 1.0 : 0.0,
                    double(x.count_at_cell_end), x.failed_at});
      sr.set_table("thresholds", th);
      std::vector<std::string> why;  // per threshold: why the run that stopped its bisection failed
      for (const auto& x : s->thresholds) why.push_back(x.failure);
      sr.set_strings("threshold_failures", why);
    }
    Record& cmp = pr.child("comparison");
    for (Convention c : {Convention::physical, Convention::paper}) compare_solvers(cmp, list, c);
  }
  return r;
}

}  // namespace stoneskip
