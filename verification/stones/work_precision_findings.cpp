// Findings of the speed-against-error study (section "work_precision" of the stones report): per
// throw, every run's error and cost, the runs that failed with their reasons, the cheapest setting
// of each solver family for each target error, and the answer: the cheapest real-time setting and
// the cheapest CVODE setting for each target (picked here, not in the report).
#include <cmath>

#include "verification/stones/stone_studies.hpp"
#include "verification/study/order_record.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {

namespace {

bool is_realtime_family(const std::string& family) { return family.rfind("realtime", 0) == 0; }

}  // namespace

Record work_precision_findings(const WorkPrecisionResult& wp, const WorkPrecisionOptions& o) {
  Record r;
  r.set_table("realtime_dt_s", value_list(o.dt_s, "dt_s"));
  r.set_table("rtol", value_list(o.rtol, "rtol"));
  r.set("atol_ratio", o.atol_ratio);
  r.set("truth_rtol", o.truth_rtol);
  r.set("truth_check_rtol", o.truth_rtol * o.truth_check_factor);
  r.set("repeats", o.repeats);
  r.set_table("targets_m", value_list(o.target_errors_m, "target_m"));
  r.set("clock", std::string("CPU time of the solving thread, the minimum over the repeats"));
  std::vector<std::string> throws;
  for (std::size_t k = 0; k < wp.throws.size(); ++k) {
    const WorkPrecisionThrow& t = wp.throws[k];
    const std::string key = "throw" + std::to_string(k);
    throws.push_back(key);
    Record& g = r.child(key);
    g.set("label", t.label);
    g.set("headline", std::string(to_string(t.headline)));
    g.set("truth_contacts", t.truth.contacts.size());
    g.set("truth_bounces", t.truth.bounces);
    g.set("truth_outcome", std::string(to_string(t.truth.outcome)));
    g.set("truth_end_time_s", t.truth.end_time_s);
    g.set("truth_steps", t.truth.stats.steps);
    g.set("truth_rhs_evaluations", t.truth.stats.rhs_evaluations);
    g.set("truth_segments", t.truth.stats.segments);
    g.set("truth_cpu_s", t.truth.stats.cpu_s);
    g.set("truth_uncertainty_m", t.truth_uncertainty_m);
    g.set("truth_check_problem", t.truth_check_problem);
    std::vector<std::string> families, failures;
    auto family_index = [&](const std::string& f) {
      for (std::size_t i = 0; i < families.size(); ++i)
        if (families[i] == f) return static_cast<double>(i);
      families.push_back(f);
      return static_cast<double>(families.size() - 1);
    };
    Table pts{{"family", "realtime", "setting", "ok", "bounces", "headline_error_m", "bounce_position_error_m",
               "sink_position_error_m", "touch_error_m", "contact_time_error_s", "cpu_s", "rhs_evaluations", "steps"},
              {}};
    for (const auto& p : t.points) {
      pts.add_row({family_index(p.family), p.realtime ? 1.0 : 0.0, p.setting, p.ok ? 1.0 : 0.0, double(p.bounces),
                   p.headline_error_m, p.bounce_position_error_m, p.sink_position_error_m, p.touch_error_m,
                   p.contact_time_error_s, p.cpu_s, double(p.rhs_evaluations), double(p.steps)});
      if (!p.ok) failures.push_back(p.family + " at " + num(p.setting) + ": " + p.problem);
    }
    g.set_table("points", pts);
    g.set_strings("failures", failures);
    Table cheap{{"target_m", "family", "found", "setting", "cpu_s", "rhs_evaluations", "error_m"}, {}};
    for (const auto& c : t.cheapest)
      cheap.add_row({c.target_error_m, family_index(c.family), c.found ? 1.0 : 0.0, c.setting, c.cpu_s,
                     double(c.rhs_evaluations), c.error_m});
    g.set_table("cheapest", cheap);
    // The answer per target: the cheapest real-time family and the cheapest CVODE family.
    Table answer{{"target_m", "realtime_family", "realtime_setting", "realtime_cpu_s", "realtime_rhs_evaluations",
                  "cvode_family", "cvode_setting", "cvode_cpu_s", "cvode_rhs_evaluations"},
                 {}};
    for (double target : o.target_errors_m) {
      const CheapestSetting* best[2] = {nullptr, nullptr};  // [realtime, CVODE]
      for (const auto& c : t.cheapest) {
        if (c.target_error_m != target || !c.found) continue;
        const CheapestSetting*& slot = best[is_realtime_family(c.family) ? 0 : 1];
        if (!slot || c.cpu_s < slot->cpu_s) slot = &c;
      }
      auto cols = [&](const CheapestSetting* c) -> std::vector<double> {
        if (!c) return {-1, NAN, NAN, NAN};
        return {family_index(c->family), c->setting, c->cpu_s, double(c->rhs_evaluations)};
      };
      std::vector<double> row{target};
      for (double x : cols(best[0])) row.push_back(x);
      for (double x : cols(best[1])) row.push_back(x);
      answer.add_row(row);
    }
    g.set_table("answer", answer);
    g.set_strings("families", families);  // after every family_index call
  }
  r.set_strings("throws", throws);
  return r;
}

}  // namespace stoneskip
