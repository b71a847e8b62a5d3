// Findings of the validation study (section "validation" of the stones report): the model's
// values beside the measured ones (which come from the study file and are stored with them), and
// the facts that explain why the two conventions disagree, decided here from the histories:
// whether the fluids ever do positive work, whether contacts end with more energy than they
// began with, and which way the first contact pitches the stone.
#include <algorithm>
#include <cmath>

#include "verification/stones/stone_studies.hpp"
#include "verification/study/order_record.hpp"
#include "verification/study/verdict_rules.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Positions of the study's runs, named (validation.cpp fills them in this order).
enum ConventionIndex { kPhysical = 0, kPaper = 1 };
enum SolverIndex { kReference = 0, kRealtime = 1 };
const ThrowHistory& fig9_of(const ValidationResult& v, bool spin, ConventionIndex c, SolverIndex s) {
  return v.fig9.at(4 * (spin ? 1 : 0) + 2 * c + s);
}
const ThrowHistory& regime_of(const ClanetResult& c, std::size_t spin_index, ConventionIndex conv) {
  return c.spin_regimes.at(2 * spin_index + conv);
}

void store_bisected(Record& r, const std::string& key, const BisectedValue& b) {
  Record& c = r.child(key);
  c.set("found", b.found);
  c.set("value", b.found ? b.value() : kNaN);
  c.set("half_width", b.found ? 0.5 * (b.hi - b.lo) : kNaN);
  c.set("note", b.note);
  c.set("runs", b.runs);
}

// Attitude facts of a history: range of the attack angle, its value at the end of the first
// contact, the largest roll, the bounces.
void store_attitude(Record& r, const ThrowHistory& h) {
  const auto t = h.table.column("t_s"), a = h.table.column("attack_deg"), roll = h.table.column("roll_deg");
  const auto power = h.table.column("fluid_power_W");
  double lo = kNaN, hi = kNaN, max_roll = 0, max_power = kNaN, at_end = kNaN;
  if (!t.empty()) {
    lo = *std::min_element(a.begin(), a.end());
    hi = *std::max_element(a.begin(), a.end());
    for (double x : roll) max_roll = std::max(max_roll, std::abs(x));
    for (double p : power)
      if (std::isfinite(p)) max_power = std::isnan(max_power) ? p : std::max(max_power, p);
    const double t_end = h.result.contacts.empty() ? t.back() : h.result.contacts[0].end_s;
    std::size_t i = 0;
    while (i + 1 < t.size() && t[i] < t_end) ++i;
    at_end = a[i];
  }
  r.set("attack_min_deg", lo);
  r.set("attack_max_deg", hi);
  r.set("attack_after_first_contact_deg", at_end);
  r.set("max_abs_roll_deg", max_roll);
  r.set("max_fluid_power_W", max_power);
  int gaining = 0;
  for (const auto& c : h.result.contacts) gaining += c.exit_energy_J > c.entry_energy_J ? 1 : 0;
  r.set("contacts_gaining_energy", gaining);
}

// Momentum at the end of the last contact that ended in a bounce (else the first contact), over
// the release momentum.
double momentum_ratio(const ThrowHistory& h) {
  const auto& c = h.result.contacts;
  double t_end = -1;
  for (const auto& k : c)
    if (k.bounced) t_end = k.end_s;
  const auto t = h.table.column("t_s");
  const auto p = h.table.column("momentum_kg_m_s");
  if (t.empty()) return kNaN;
  if (t_end < 0) {
    if (c.empty()) return kNaN;
    t_end = c[0].end_s;
  }
  std::size_t i = 0;
  while (i + 1 < t.size() && t[i] < t_end) ++i;
  return p[i] / p[0];
}

// The first contact of a history, as facts, and which way it pitched the stone.
void store_first_contact(Record& r, const ThrowHistory& h) {
  Record& c = r.child("first_contact");
  c.set("exists", !h.result.contacts.empty());
  if (h.result.contacts.empty()) return;
  const ContactRecord& k = h.result.contacts.front();
  c.set("start_s", k.start_s);
  c.set("end_s", k.end_s);
  c.set("entry_attack_deg", k.entry_attack_angle_deg);
  c.set("exit_attack_deg", k.exit_attack_angle_deg);
  c.set("entry_speed_m_s", k.entry_speed_m_s);
  c.set("exit_speed_m_s", k.exit_speed_m_s);
  c.set("entry_energy_J", k.entry_energy_J);
  c.set("exit_energy_J", k.exit_energy_J);
  c.set("bounced", k.bounced);
  Record in;
  in.set("change_deg", k.exit_attack_angle_deg - k.entry_attack_angle_deg);
  decide_verdict(c, "pitch", "attack_change", in,
                          "the attack angle goes from " + num(k.entry_attack_angle_deg) + "° at entry to " +
                              num(k.exit_attack_angle_deg) + "° at the end of the contact");
}

}  // namespace

Record validation_findings(const ValidationResult& v, const ValidationOptions& o) {
  Record r;
  r.set("reference_rtol", o.reference_rtol);
  r.set("speed_tolerance_m_s", o.speed_tolerance_m_s);
  r.set("angle_tolerance_deg", o.angle_tolerance_deg);
  r.set("contact_time_speed_m_s", o.contact_time_speed_m_s);
  r.set("min_speed_attack_deg", o.min_speed_attack_deg);
  {
    Record& m = r.child("measured");
    std::vector<std::string> keys;
    for (const auto& x : o.measured) {
      keys.push_back(x.key);
      Record& k = m.child(x.key);
      k.set("quantity", x.quantity);
      k.set("measured", x.measured);
      k.set("expected", x.expected);
      k.set("source", x.source);
    }
    m.set_strings("keys", keys);
  }

  // Clanet's disk.
  const ClanetResult& C = v.clanet;
  Record& cl = r.child("clanet");
  {
    Table t{{"attack_deg", "min_speed_reference_m_s", "min_speed_realtime_m_s", "min_speed_paper_m_s"}, {}};
    auto val = [](const BisectedValue& b) { return b.found ? b.value() : kNaN; };
    for (std::size_t i = 0; i < C.attack_deg.size(); ++i)
      t.add_row({C.attack_deg[i], val(C.min_speed_reference[i]), val(C.min_speed_realtime[i]), val(C.min_speed_paper[i])});
    cl.set_table("min_speed", t);
    std::vector<std::string> notes;
    for (std::size_t i = 0; i < C.attack_deg.size(); ++i)
      for (const BisectedValue* b : {&C.min_speed_reference[i], &C.min_speed_realtime[i], &C.min_speed_paper[i]})
        notes.push_back(b->note);
    cl.set_strings("min_speed_notes", notes);  // row-major: attack × (reference, realtime, paper)
    // At the compared attack angle, and where each variant's minimum is lowest.
    const char* names[3] = {"reference", "realtime", "paper"};
    const std::vector<BisectedValue>* series[3] = {&C.min_speed_reference, &C.min_speed_realtime, &C.min_speed_paper};
    for (int k = 0; k < 3; ++k) {
      Record& s = cl.child(std::string("min_speed_") + names[k]);
      const auto it = std::find(C.attack_deg.begin(), C.attack_deg.end(), o.min_speed_attack_deg);
      if (it != C.attack_deg.end()) store_bisected(s, "at_compared_attack", (*series[k])[it - C.attack_deg.begin()]);
      double best = kNaN, speed = 1e300;
      for (std::size_t i = 0; i < series[k]->size(); ++i)
        if ((*series[k])[i].found && (*series[k])[i].value() < speed) {
          speed = (*series[k])[i].value();
          best = C.attack_deg[i];
        }
      s.set("best_attack_deg", best);
    }
    store_bisected(cl, "largest_path_angle_reference", C.largest_path_angle_reference);
    store_bisected(cl, "largest_path_angle_realtime", C.largest_path_angle_realtime);
    store_bisected(cl, "largest_path_angle_paper", C.largest_path_angle_paper);
    Table ct{{"speed_m_s", "contact_reference_s", "contact_realtime_s", "contact_paper_s"}, {}};
    for (std::size_t i = 0; i < C.contact_speeds_m_s.size(); ++i)
      ct.add_row({C.contact_speeds_m_s[i], C.contact_time_reference_s[i], C.contact_time_realtime_s[i], C.contact_time_paper_s[i]});
    cl.set_table("contact_time", ct);
    cl.set("contact_time_exponent", C.contact_time_exponent);
    // Spin regimes, named by spin and convention.
    std::vector<std::string> regimes;
    for (std::size_t i = 0; i < o.regime_spins_rev_s.size(); ++i)
      for (ConventionIndex c : {kPhysical, kPaper}) {
        const ThrowHistory& h = regime_of(C, i, c);
        const std::string key = "regime_" + record_key(num(o.regime_spins_rev_s[i], 4)) + "_" + to_string(h.convention);
        regimes.push_back(key);
        Record& g = cl.add_child(key, history_record(h));
        g.set("spin_rev_s", o.regime_spins_rev_s[i]);
        store_attitude(g, h);
      }
    cl.set_strings("regimes", regimes);
    cl.set("regime_attack_deg", o.regime_attack_deg);
  }

  // Bocquet's trends.
  const BocquetResult& B = v.bocquet;
  Record& bq = r.child("bocquet");
  bq.set("stone", B.stone);
  {
    Table s{{"speed_m_s", "count_physical", "count_paper", "bocquet_shape"}, {}};
    for (std::size_t i = 0; i < B.speeds_m_s.size(); ++i)
      s.add_row({B.speeds_m_s[i], double(B.count_vs_speed_physical[i]), double(B.count_vs_speed_paper[i]),
                 B.bocquet_speed_prediction[i]});
    bq.set_table("speed", s);
    Table w{{"spin_rev_s", "count_physical", "count_paper", "bocquet_N_omega"}, {}};
    for (std::size_t i = 0; i < B.spins_rev_s.size(); ++i)
      w.add_row({B.spins_rev_s[i], double(B.count_vs_spin_physical[i]), double(B.count_vs_spin_paper[i]),
                 B.bocquet_spin_prediction[i]});
    bq.set_table("spin", w);
    bq.set("speed_exponent_physical", B.speed_exponent_physical);
    bq.set("speed_exponent_paper", B.speed_exponent_paper);
    bq.set("spin_exponent_physical", B.spin_exponent_physical);
    bq.set("spin_exponent_paper", B.spin_exponent_paper);
  }

  // The seed's claims and Fig. 9.
  Record& seed = r.child("seed");
  std::vector<std::string> fig9_keys;
  for (ConventionIndex c : {kPhysical, kPaper})
    for (SolverIndex s : {kReference, kRealtime}) {
      const ThrowHistory& a = fig9_of(v, false, c, s);
      const ThrowHistory& b = fig9_of(v, true, c, s);
      Record& k = seed.child(std::string(c == kPhysical ? "physical" : "paper") + "_" + (s == kReference ? "reference" : "realtime"));
      k.set("bounces_without_spin", a.result.bounces);
      k.set("bounces_with_spin", b.result.bounces);
      k.set("lateral_without_spin_m", a.result.lateral_m);
      k.set("lateral_with_spin_m", b.result.lateral_m);
      k.set("momentum_ratio_without_spin", momentum_ratio(a));
      k.set("momentum_ratio_with_spin", momentum_ratio(b));
      k.set("with_spin_label", b.label);
    }

  // Why the conventions disagree: the seed's spinning throw, reference, both conventions.
  Record& why = r.child("conventions");
  for (ConventionIndex c : {kPhysical, kPaper}) {
    const ThrowHistory& h = fig9_of(v, true, c, kReference);
    Record& g = why.add_child(c == kPhysical ? "physical" : "paper", history_record(h));
    store_attitude(g, h);
    store_first_contact(g, h);
  }
  {
    const Record& phys = why.at("physical");
    const Record& pap = why.at("paper");
    const double p_phys = phys.number("max_fluid_power_W"), p_pap = pap.number("max_fluid_power_W");
    // Energy: a passive fluid never does positive work (spec §1.6). A positive maximum counts only
    // above round-off of the stone's own energy scale.
    const double round_off_W = 1e-9 * std::max(1.0, std::abs(phys.number("max_energy_gain_J")));
    Record in1;
    in1.set("max_fluid_power_W", p_phys);
    in1.set("round_off_W", round_off_W);
    decide_verdict(why, "physical_energy", "max_fluid_power", in1,
                   "the largest rate of work of water and air on the stone is " + num(p_phys) + " W");
    Record in2;
    in2.set("max_fluid_power_W", p_pap);
    in2.set("round_off_W", round_off_W);
    decide_verdict(
        why, "paper_energy", "max_fluid_power", in2,
        "the fluids' rate of work reaches " + num(p_pap) + " W; " + num(pap.number("contacts_gaining_energy"), 4) + " of " +
            num(pap.number("contact_count"), 4) + " contacts end with more energy than they began with (largest gain " +
            num(pap.number("max_energy_gain_J")) + " J)");
  }
  return r;
}

}  // namespace stoneskip
