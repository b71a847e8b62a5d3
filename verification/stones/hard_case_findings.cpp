// Findings of the hard cases (section "hard_cases" of the stones report): per case, every run with
// what went wrong, the largest single step before anything does, and over all cases which kind of
// failure appears first as the step grows (decided here from the runs, not asserted in words);
// and the largest stable step against throw speed.
#include <cmath>

#include "verification/stones/stone_studies.hpp"
#include "verification/study/order_record.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {

namespace {

// The first kind of departure from the reference a run shows, in the order the list names them.
enum class Departure { none, spurious, missed, bounce_count, energy, failure };
const char* to_string(Departure d) {
  switch (d) {
    case Departure::none: return "none";
    case Departure::spurious: return "contacts the reference does not have";
    case Departure::missed: return "missed contacts";
    case Departure::bounce_count: return "a different bounce count";
    case Departure::energy: return "energy created over a contact";
    case Departure::failure: return "the state becomes NaN or the run fails";
  }
  return "?";
}

// What goes wrong in a run: the gravest kind it shows.
Departure departure_of(const HardRun& r, Convention conv) {
  if (!r.finite) return Departure::failure;
  if (r.energy_created && conv == Convention::physical) return Departure::energy;
  if (r.contacts.missed) return Departure::missed;
  if (r.contacts.spurious) return Departure::spurious;
  if (!r.contacts.same_bounces()) return Departure::bounce_count;
  return Departure::none;
}

}  // namespace

Record hard_cases_findings(const std::vector<HardCaseResult>& hard, const std::vector<StableStepRow>& stable,
                           const HardCaseOptions& ho, const StableStepOptions& so) {
  Record r;
  r.set("reference_rtol", ho.reference_rtol);
  r.set("energy_tolerance_fraction", ho.energy_tolerance_fraction);
  r.set_table("single_steps_s", value_list(ho.single_steps_s, "dt_s"));
  r.set("single_step_scheme", std::string(to_string(ho.single_step_scheme)));
  std::vector<std::string> keys, ref_failed, case_bad, energy;
  // How often each kind of departure is the first one as the single step grows.
  std::vector<double> first_count(6, 0);
  for (const auto& h : hard) {
    const std::string key = record_key(h.file);
    keys.push_back(key);
    Record& c = r.child(key);
    c.set("title", h.title);
    c.set("file", h.file);
    c.set("convention", std::string(to_string(h.convention)));
    c.set("reference_verdict", h.reference_verdict);
    c.set("reference_failed", h.reference.outcome == Outcome::failed);
    Table t{{"dt_s", "contact_dt_s", "finite", "bounces", "contacts", "missed", "spurious", "max_energy_gain_J", "cpu_s",
             "departure"},
            {}};
    std::vector<std::string> settings, verdicts;
    double largest_ok = 0;
    bool prefix_ok = true;
    Departure first = Departure::none;
    for (std::size_t i = 0; i < h.runs.size(); ++i) {
      const HardRun& run = h.runs[i];
      const Departure d = departure_of(run, h.convention);
      t.add_row({run.dt_s, run.contact_dt_s, run.finite ? 1.0 : 0.0, double(run.result.bounces),
                 double(run.result.contacts.size()), double(run.contacts.missed), double(run.contacts.spurious),
                 run.result.max_energy_gain_J, run.result.stats.cpu_s, double(static_cast<int>(d))});
      settings.push_back(run.setting);
      verdicts.push_back(run.verdict);
      if (i > 0) {  // the single-step runs, in growing order
        prefix_ok = prefix_ok && run.verdict == "ok";
        if (prefix_ok) largest_ok = run.dt_s;
        if (first == Departure::none && d != Departure::none) first = d;
      }
    }
    c.set_table("runs", t);
    c.set_strings("settings", settings);
    c.set_strings("verdicts", verdicts);
    c.set("largest_ok_single_step_s", largest_ok);
    c.set("first_departure", std::string(to_string(first)));
    first_count[static_cast<int>(first)] += 1;
    if (h.reference.outcome == Outcome::failed) ref_failed.push_back(h.file);
    if (!h.runs.empty() && h.runs.front().verdict != "ok") case_bad.push_back(h.file);
    if (h.convention == Convention::physical)
      for (const auto& run : h.runs)
        if (run.energy_created) {
          energy.push_back(h.file + " (from h = " + num(run.dt_s, 4) + " s)");  // the steps are 1e-5 × 2^k: 4 digits
          break;
        }
  }
  r.set_strings("cases", keys);
  r.set_strings("reference_failed", ref_failed);
  r.set_strings("case_settings_depart", case_bad);
  r.set_strings("energy_created_physical", energy);
  Table firsts{{"departure", "cases"}, {}};
  std::vector<std::string> names;
  for (int d = 0; d < 6; ++d) {
    firsts.add_row({double(d), first_count[d]});
    names.push_back(to_string(static_cast<Departure>(d)));
  }
  r.set_table("first_departure_counts", firsts);
  r.set_strings("departure_names", names);

  Record& s = r.child("largest_stable_step");
  s.set("scheme", std::string(to_string(so.scheme)));
  s.set("reference_rtol", so.reference_rtol);
  Table st{{"speed_m_s", "reference_bounces", "reference_contacts", "largest_finite_s", "largest_no_energy_gain_s",
            "largest_same_contacts_s"},
           {}};
  for (const auto& row : stable) {
    st.add_row({row.speed_m_s, double(row.reference_bounces), double(row.reference_contacts), row.largest_finite_s,
                row.largest_no_energy_gain_s, row.largest_same_contacts_s});
    Table b{{"dt_s", "bounces", "energy_gain_J"}, {}};
    for (std::size_t i = 0; i < row.steps_s.size(); ++i) b.add_row({row.steps_s[i], double(row.bounces[i]), row.energy_gain_J[i]});
    s.set_table("steps_at_" + record_key(num(row.speed_m_s, 4)) + "_m_s", b);
  }
  s.set_table("rows", st);
  if (!stable.empty()) s.set_table("steps_s", value_list(stable.front().steps_s, "dt_s"));
  return r;
}

}  // namespace stoneskip
