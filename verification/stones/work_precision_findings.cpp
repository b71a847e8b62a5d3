// Findings of the speed-against-error study (section "work_precision" of the stones report): per
// throw, every run's error and cost, the runs that failed with their reasons, the cheapest setting
// of each solver family for each target error, and the answer: the cheapest real-time setting and
// the cheapest CVODE setting for each target (picked here, not in the report). The restart
// strategies' summaries and the verdict that names the cheapest strategy keeping the contact times
// (restart_findings).
#include <algorithm>
#include <cmath>
#include <limits>

#include "verification/stones/stone_studies.hpp"
#include "verification/study/order_record.hpp"
#include "verification/study/verdict_rules.hpp"
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
    g.set("law", std::string(to_string(t.law)));
    g.set("convention", std::string(to_string(t.convention)));
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
    g.set("fixed_kinks", t.fixed_kinks);
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
    Table kinds{{"adaptive"}, {}};         // per family: 1 where its setting is a tolerance
    for (const auto& f : families) {
      bool adaptive = false;
      for (const auto& p : t.points) adaptive = adaptive || (p.family == f && p.adaptive);
      kinds.add_row({adaptive ? 1.0 : 0.0});
    }
    g.set_table("family_kinds", kinds);
  }
  r.set_strings("throws", throws);

  // The adaptive scheme's tolerance as this study chooses it, beside the cases' default.
  const AdaptiveToleranceChoice& a = wp.adaptive_choice;
  Record& ac = r.child("adaptive_choice");
  ac.set("studied", a.studied);
  ac.set("family", a.family);
  ac.set("found", a.found);
  ac.set("tolerance", a.tolerance);
  ac.set("default_tolerance", a.default_tolerance);
  ac.set("worst_contact_time_error_s", a.worst_contact_time_error_s);
  ac.set("worst_headline_error_m", a.worst_headline_error_m);
  ac.set("rhs_evaluations", a.rhs_evaluations);
  ac.set("throws", a.throws);
  if (!a.set_aside.empty()) ac.set_strings("set_aside", a.set_aside);
  Table per{{"tolerance", "throws_keeping_contacts"}, {}};
  for (std::size_t i = 0; i < a.tolerances.size(); ++i) per.add_row({a.tolerances[i], double(a.throws_keeping_contacts[i])});
  ac.set_table("per_tolerance", per);
  r.set_table("adaptive_rtol", value_list(o.adaptive_rtol, "rtol"));
  return r;
}

Record restart_findings(const WorkPrecisionResult& wp, const WorkPrecisionOptions& o, RestartStrategy default_restart) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  Record r;
  r.set("truth_rtol", o.truth_rtol);
  r.set("atol_ratio", o.atol_ratio);
  r.set("repeats", o.repeats);
  r.set("time_tolerance_s", o.restart_time_tolerance_s);
  r.set("error_factor", o.restart_error_factor);
  r.set("default", std::string(to_string(default_restart)));
  r.set("clock", std::string("CPU time of the solving thread, the minimum over the repeats, summed over the throws"));
  std::vector<std::string> labels;
  for (const auto& t : wp.throws) labels.push_back(t.label);
  r.set_strings("throws", labels);
  std::vector<std::string> strategies, methods;
  for (RestartStrategy s : o.restarts) strategies.push_back(to_string(s));
  for (ReferenceMethod m : o.methods) methods.push_back(to_string(m));
  r.set_strings("strategies", strategies);
  r.set_strings("methods", methods);
  // One row per method × rtol × strategy; method and strategy as positions in the lists above.
  Table t{{"method", "rtol", "strategy", "throws", "failed", "rhs_evaluations", "steps", "segments", "cpu_s",
           "worst_contact_time_error_s", "tolerance_s", "keeps"},
          {}};
  auto position = [](const std::vector<std::string>& list, const std::string& name) {
    return double(std::find(list.begin(), list.end(), name) - list.begin());
  };
  for (const RestartSummary& s : wp.restarts)
    t.add_row({position(methods, to_string(s.method)), s.rtol, position(strategies, to_string(s.restart)), double(s.throws),
               double(s.failed), double(s.rhs_evaluations), double(s.steps), double(s.segments), s.cpu_s,
               s.worst_contact_time_error_s, s.tolerance_s, s.keeps_contact_times ? 1.0 : 0.0});
  r.set_table("summaries", t);
  // Per strategy over the whole study: failures, the worst error against its tolerance, the cost.
  Record in;
  std::string reason;
  for (RestartStrategy rs : o.restarts) {
    const std::string name = to_string(rs);
    double failed = 0, ratio = 0, rhs = 0, cpu = 0, segments = 0;
    for (const RestartSummary& s : wp.restarts) {
      if (s.restart != rs) continue;
      failed += s.failed;
      rhs += double(s.rhs_evaluations);
      cpu += s.cpu_s;
      segments += double(s.segments);
      const double q = s.worst_contact_time_error_s / s.tolerance_s;
      ratio = std::isnan(ratio) || std::isnan(q) ? kNaN : std::max(ratio, q);
    }
    Record& g = r.child(name);
    g.set("failed", failed);
    g.set("error_ratio", ratio);
    g.set("rhs_evaluations", rhs);
    g.set("cpu_s", cpu);
    g.set("segments", segments);
    in.set(name + ".failed", failed);
    in.set(name + ".error_ratio", ratio);
    in.set(name + ".rhs_evaluations", rhs);
    reason += (reason.empty() ? "" : "; ") + name + ": " + num(rhs, 6) + " right-hand sides, " + num(segments, 6) +
              " integration segments, " + num(cpu) + " s CPU, " +
              (failed > 0 ? num(failed, 4) + " failed runs or changed contact lists"
                          : "worst contact-time error " + num(ratio) + "× its tolerance");
  }
  reason += std::string("; the reference's default is ") + to_string(default_restart);
  decide_verdict(r, "verdict", "restart_strategy", in, reason);
  // The study's own choice (work_precision.hpp RestartVerdict), for comparison with the rule's.
  r.set("study_choice", wp.restart_verdict.found ? std::string(to_string(wp.restart_verdict.restart)) : std::string("none"));
  return r;
}

}  // namespace stoneskip
