// Findings of the validation study (section "validation" of the stones report): each model
// variant's values beside the measured ones (which come from the study file and are stored with
// them), the fitted exponents with their intervals and verdicts, the facts that explain why the
// two conventions disagree (whether the fluids ever do positive work, whether contacts end with
// more energy than they began with, which way the first contact pitches the stone), and the
// answer of issue 11: the laws ranked by their distance from the measurements and by their cost,
// and the cheapest law that skips like a real stone, if any.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "verification/stones/stone_studies.hpp"
#include "verification/stones/validation_score.hpp"
#include "verification/study/order_record.hpp"
#include "verification/study/verdict_rules.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void store_bisected(Record& r, const std::string& key, const BisectedValue& b) {
  Record& c = r.child(key);
  c.set("found", b.found);
  c.set("value", b.found ? b.value() : kNaN);
  c.set("half_width", b.found ? 0.5 * (b.hi - b.lo) : kNaN);
  c.set("bound", b.bounces_at_both_ends ? b.lo : kNaN);  // bounced at both ends: the value lies beyond this
  c.set("note", b.note);
  c.set("runs", b.runs);
}

// A fitted exponent with its 95 % interval and its verdict against the expected one.
void store_exponent(Record& parent, const std::string& key, const OrderFit& f, double expected, double tolerance,
                    const std::string& what) {
  Record& r = parent.child(key);
  r.set("valid", f.valid);
  r.set("exponent", f.valid ? f.order : kNaN);
  r.set("exponent_low", f.valid ? f.order_low : kNaN);
  r.set("exponent_high", f.valid ? f.order_high : kNaN);
  r.set("points", f.points);
  r.set("r_squared", f.valid ? f.r_squared : kNaN);
  r.set("problem", f.problem);
  Record in;
  in.set("valid", f.valid);
  in.set("exponent", r.number("exponent"));
  in.set("exponent_low", r.number("exponent_low"));
  in.set("exponent_high", r.number("exponent_high"));
  in.set("points", f.points);
  in.set("expected", expected);
  in.set("tolerance", tolerance);
  const std::string reason =
      !f.valid ? what + ": no fit, " + f.problem
      : f.points < 3
          ? what + ": " + num(f.order) + " from only " + num(f.points, 2) + " points (an interval needs 3)"
          : what + ": " + num(f.order) + " [" + num(f.order_low) + ", " + num(f.order_high) + "] (95 %, " +
                num(f.points, 2) + " points) against the expected " + num(expected) + " ± " + num(tolerance);
  decide_verdict(r, "verdict", "power_law_exponent", in, reason);
}

// A history's table with rows at least dt apart (the first and last kept): what the figures need.
Table thinned(const Table& t, double dt_s) {
  Table out{t.columns, {}};
  const auto time = t.column("t_s");
  double last = -1e300;
  const std::size_t n = t.columns.size();
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (time[i] - last < dt_s && i + 1 != time.size()) continue;
    last = time[i];
    out.values.insert(out.values.end(), t.values.begin() + i * n, t.values.begin() + (i + 1) * n);
  }
  return out;
}

// Attitude facts of a history: range of the attack angle, its value at the end of the first
// contact, the largest roll, the largest fluid power, contacts that gain energy.
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
  const double change = h.result.contacts.empty()
                            ? kNaN
                            : h.result.contacts.front().exit_attack_angle_deg - h.result.contacts.front().entry_attack_angle_deg;
  c.set("attack_change_deg", change);
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
  in.set("change_deg", change);
  decide_verdict(c, "pitch", "attack_change", in,
                 "the attack angle goes from " + num(k.entry_attack_angle_deg) + "° at entry to " +
                     num(k.exit_attack_angle_deg) + "° at the end of the contact");
}

// A history as stored in the section: facts from the full history, the table thinned.
Record stored_history(const ThrowHistory& h, double dt_s) {
  ThrowHistory t = h;
  t.table = thinned(h.table, dt_s);
  Record g = history_record(t);
  store_attitude(g, h);
  store_first_contact(g, h);
  return g;
}

std::size_t index_of(const std::vector<double>& grid, double x) {
  return static_cast<std::size_t>(std::find(grid.begin(), grid.end(), x) - grid.begin());
}

// One variant's values, measured as the table's rows need them.
Record variant_record(const VariantResult& R, const ValidationOptions& o) {
  Record g;
  const ModelVariant& v = R.variant;
  g.set("law", std::string(to_string(v.law)));
  g.set("convention", std::string(to_string(v.convention)));
  g.set("solver", std::string(v.solver == SolverKind::realtime ? "realtime" : "reference"));
  g.set("title", v.title());
  // Clanet's disk.
  {
    Table t{{"attack_deg", "min_speed_m_s", "half_width_m_s"}, {}};
    std::vector<std::string> notes;
    for (std::size_t i = 0; i < o.clanet_attack_deg.size(); ++i) {
      const BisectedValue& b = R.min_speed[i];
      t.add_row({o.clanet_attack_deg[i], b.found ? b.value() : kNaN, b.found ? 0.5 * (b.hi - b.lo) : kNaN});
      notes.push_back(b.note);
    }
    g.set_table("min_speed", t);
    g.set_strings("min_speed_notes", notes);
    const std::size_t at = index_of(o.clanet_attack_deg, o.min_speed_attack_deg);
    if (at < R.min_speed.size()) store_bisected(g, "min_speed_at_compared_attack", R.min_speed[at]);
    double best = kNaN, speed = 1e300;
    for (std::size_t i = 0; i < R.min_speed.size(); ++i)
      if (R.min_speed[i].found && R.min_speed[i].value() < speed) {
        speed = R.min_speed[i].value();
        best = o.clanet_attack_deg[i];
      }
    g.set("best_attack_deg", best);
    store_bisected(g, "largest_path_angle", R.largest_path_angle);
    Table ct{{"speed_m_s", "contact_s"}, {}};
    for (std::size_t i = 0; i < o.clanet_contact_speeds_m_s.size(); ++i)
      ct.add_row({o.clanet_contact_speeds_m_s[i], R.contact_time_s[i]});
    g.set_table("contact_time", ct);
    store_exponent(g, "contact_exponent", R.contact_time_fit, o.contact_exponent_expected, o.exponent_tolerance,
                   "exponent of the contact time against U");
    std::vector<std::string> regimes;
    for (std::size_t i = 0; i < o.regime_spins_rev_s.size(); ++i) {
      const std::string key = "regime_" + record_key(num(o.regime_spins_rev_s[i], 4));
      regimes.push_back(key);
      g.add_child(key, stored_history(R.regimes[i], o.history_dt_s)).set("spin_rev_s", o.regime_spins_rev_s[i]);
    }
    g.set_strings("regimes", regimes);
  }
  // Bocquet's stone.
  {
    Table s{{"speed_m_s", "count"}, {}};
    for (std::size_t i = 0; i < o.bocquet_speeds_m_s.size(); ++i) s.add_row({o.bocquet_speeds_m_s[i], double(R.count_vs_speed[i])});
    g.set_table("bocquet_speed", s);
    Table w{{"spin_rev_s", "count"}, {}};
    for (std::size_t i = 0; i < o.bocquet_spins_rev_s.size(); ++i) w.add_row({o.bocquet_spins_rev_s[i], double(R.count_vs_spin[i])});
    g.set_table("bocquet_spin", w);
    store_exponent(g, "speed_exponent", R.speed_fit, o.count_exponent_expected, o.exponent_tolerance,
                   "exponent of N against V² (N > 0)");
    store_exponent(g, "spin_exponent", R.spin_fit, o.count_exponent_expected, o.exponent_tolerance,
                   "exponent of N against Ω² (N > 0, Ω > 0)");
  }
  // The seed's throws.
  {
    Record& k = g.child("seed");
    k.set("bounces_without_spin", R.without_spin.result.bounces);
    k.set("bounces_with_spin", R.with_spin.result.bounces);
    k.set("lateral_without_spin_m", R.without_spin.result.lateral_m);
    k.set("lateral_with_spin_m", R.with_spin.result.lateral_m);
    k.set("momentum_ratio_without_spin", momentum_ratio(R.without_spin));
    k.set("momentum_ratio_with_spin", momentum_ratio(R.with_spin));
    k.set("with_spin_label", R.with_spin.label);
  }
  return g;
}

// The model value of a scorable quantity (validation.hpp: scorable_quantities) from a variant's record.
ScoredValue scored_value(const Record& g, const std::string& key, const ValidationOptions& o) {
  ScoredValue s;
  s.key = key;
  auto from_bisection = [&](const Record& b) {
    if (b.flag("found")) {
      s.has_value = true;
      s.model = b.number("value");
    } else if (std::isfinite(b.number("bound"))) {
      s.has_value = true;
      s.bound_only = true;
      s.model = b.number("bound");
      s.note = b.text("note") + ": the distance is a lower bound";
    } else {
      s.note = b.text("note");
    }
  };
  auto from_exponent = [&](const Record& e) {
    if (e.flag("valid") && e.number("points") >= 3) {
      s.has_value = true;
      s.model = e.number("exponent");
    } else {
      s.note = "fewer than 3 points to fit";
    }
  };
  if (key == "clanet_min_speed") {
    if (g.has_child("min_speed_at_compared_attack"))
      from_bisection(g.at("min_speed_at_compared_attack"));
    else
      s.note = "the compared attack angle is not on the grid";
  } else if (key == "clanet_best_attack") {
    s.model = g.number("best_attack_deg");
    s.has_value = std::isfinite(s.model);
    if (!s.has_value) s.note = "no bounce at any attack angle tried";
  } else if (key == "clanet_max_path_angle") {
    from_bisection(g.at("largest_path_angle"));
  } else if (key == "clanet_contact_time") {
    const Table& t = g.table("contact_time");
    const std::size_t i = index_of(t.column("speed_m_s"), o.contact_time_speed_m_s);
    s.model = i < t.rows() ? t.column("contact_s")[i] : kNaN;
    s.has_value = std::isfinite(s.model);
    if (!s.has_value) s.note = "the first contact at " + num(o.contact_time_speed_m_s) + " m/s does not end in a bounce";
  } else if (key == "clanet_contact_exponent") {
    from_exponent(g.at("contact_exponent"));
  } else if (key == "bocquet_speed_exponent") {
    from_exponent(g.at("speed_exponent"));
  } else if (key == "bocquet_spin_exponent") {
    from_exponent(g.at("spin_exponent"));
  }
  return s;
}

// The answer (issue 11, item 4): each law's distance from the measurements and its cost, ranked,
// and the cheapest law that skips like a real stone.
Record ranking_record(const Record& variants, const ValidationResult& v, const ValidationOptions& o) {
  const RankingOptions& k = o.ranking;
  Record r;
  r.set("miss_distance", k.miss_distance);
  r.set("distance_bound", k.distance_bound);
  r.set("held_spin_rev_s", k.held_spin_rev_s);
  r.set("attack_bound_deg", k.attack_bound_deg);
  r.set("regime_attack_deg", o.regime_attack_deg);
  r.set("cost_repeats", k.cost_repeats);
  r.set("clock", std::string("thread CPU time of one throw, the minimum over the repeats"));
  std::vector<std::string> scored;
  std::vector<MeasuredRange> ranges;
  for (const auto& m : o.measured)
    if (m.score) {
      scored.push_back(m.key);
      ranges.push_back(*m.score);
    }
  r.set_strings("scored", scored);
  const std::string held_key = "regime_" + record_key(num(k.held_spin_rev_s, 4));
  r.set("held_regime", held_key);  // the variants' child holding that regime
  std::vector<std::string> laws;
  Record answer_in;
  answer_in.set("distance_bound", k.distance_bound);
  answer_in.set("attack_bound_deg", k.attack_bound_deg);
  std::string reason;
  for (std::size_t l = 0; l < o.laws.size(); ++l) {
    const std::string law = to_string(o.laws[l]);
    laws.push_back(law);
    const Record& g = variants.at(law + "_reference");
    Record& L = r.child(law);
    std::vector<ScoredValue> values;
    for (const auto& key : scored) values.push_back(scored_value(g, key, o));
    const ModelDistance d = model_distance(values, ranges, k.miss_distance);
    Table q{{"model", "has_value", "bound_only", "distance"}, {}};
    std::vector<std::string> notes;
    for (std::size_t i = 0; i < values.size(); ++i) {
      q.add_row({values[i].has_value ? values[i].model : kNaN, values[i].has_value ? 1.0 : 0.0,
                 values[i].bound_only ? 1.0 : 0.0, d.distances[i]});
      notes.push_back(values[i].note);
    }
    L.set_table("quantities", q);  // one row per scored key
    L.set_strings("notes", notes);
    L.set("distance", d.mean);
    const Record& held = g.at(held_key).at("first_contact");
    const double change = held.number("attack_change_deg");
    L.set("attack_change_deg", change);
    L.set("held_bounces", g.at(held_key).number("bounces"));
    const LawCost& c = v.costs.at(l);
    Table ct{{"reference_cpu_s", "reference_rhs_evaluations", "realtime_cpu_s", "realtime_steps"}, {}};
    std::vector<std::string> names;
    for (const auto& t : c.throws) {
      names.push_back(t.throw_name);
      ct.add_row({t.reference_cpu_s, double(t.reference_rhs_evaluations), t.realtime_cpu_s, double(t.realtime_steps)});
    }
    L.set_table("cost", ct);
    L.set_strings("cost_throws", names);
    L.set("reference_cpu_s", c.mean_reference_cpu_s);
    L.set("realtime_cpu_s", c.mean_realtime_cpu_s);
    L.set("realtime_cpu_per_step_s", c.mean_realtime_cpu_per_step_s);
    L.set("reference_cpu_per_rhs_s", c.mean_reference_cpu_per_rhs_s);
    Record in;
    in.set("distance", d.mean);
    in.set("distance_bound", k.distance_bound);
    in.set("attack_change_deg", change);
    in.set("attack_bound_deg", k.attack_bound_deg);
    const std::string facts = "mean distance " + num(d.mean) + " (bound " + num(k.distance_bound) + "), attack angle " +
                              (std::isnan(change) ? std::string("without a contact")
                                                  : "changed by " + num(change) + "°") +
                              " through the first contact at " + num(k.held_spin_rev_s) + " rev/s (bound ±" +
                              num(k.attack_bound_deg) + "°)";
    decide_verdict(L, "skips", "skips_like_a_stone", in, facts);
    answer_in.set(law + ".distance", d.mean);
    answer_in.set(law + ".attack_change_deg", change);
    answer_in.set(law + ".cost_s", c.mean_realtime_cpu_s);
    reason += (reason.empty() ? "" : "; ") + law + ": " + facts + ", " + num(1000 * c.mean_realtime_cpu_s) +
              " ms real-time CPU per throw (" + L.at("skips").text("verdict") + ")";
  }
  r.set_strings("laws", laws);
  auto sorted_by = [&](const std::string& field) {
    std::vector<std::string> s = laws;
    std::stable_sort(s.begin(), s.end(), [&](const std::string& a, const std::string& b) {
      const double x = r.at(a).number(field), y = r.at(b).number(field);
      return x < y || (std::isnan(y) && !std::isnan(x));
    });
    return s;
  };
  r.set_strings("by_distance", sorted_by("distance"));
  r.set_strings("by_cost", sorted_by("realtime_cpu_s"));
  decide_verdict(r, "answer", "cheapest_skipping_law", answer_in, reason);
  return r;
}

}  // namespace

Record validation_findings(const ValidationResult& v, const ValidationOptions& o) {
  Record r;
  r.set("reference_rtol", o.reference_rtol);
  r.set("speed_tolerance_m_s", o.speed_tolerance_m_s);
  r.set("angle_tolerance_deg", o.angle_tolerance_deg);
  r.set("contact_time_speed_m_s", o.contact_time_speed_m_s);
  r.set("min_speed_attack_deg", o.min_speed_attack_deg);
  r.set("regime_attack_deg", o.regime_attack_deg);
  r.set("exponent_tolerance", o.exponent_tolerance);
  r.set("default_law", std::string(to_string(o.laws.front())));
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
      k.set("scored", x.score.has_value());
      if (x.score) {
        k.set("score_low", x.score->low);
        k.set("score_high", x.score->high);
        k.set("score_unit", x.score_unit);
      }
    }
    m.set_strings("keys", keys);
  }
  {
    Record& c = r.child("curves");
    std::vector<std::string> keys;
    for (std::size_t i = 0; i < o.curves.size(); ++i) {
      const MeasuredCurve& m = o.curves[i];
      keys.push_back("curve" + std::to_string(i));
      Record& k = c.child(keys.back());
      k.set("quantity", m.key);
      k.set("label", m.label);
      k.set("source", m.source);
      Table t{{"x", "low", "high"}, {}};
      for (std::size_t j = 0; j < m.x.size(); ++j) t.add_row({m.x[j], m.low[j], m.high[j]});
      k.set_table("points", t);
    }
    c.set_strings("keys", keys);
  }

  // Every variant of the table, by name, in the table's order.
  Record& vars = r.child("variants");
  std::vector<std::string> keys;
  for (const auto& R : v.variants) {
    if (R.variant.use != VariantUse::table) continue;
    keys.push_back(R.variant.key());
    vars.add_child(keys.back(), variant_record(R, o));
  }
  vars.set_strings("keys", keys);

  // Bocquet's predictions.
  Record& bq = r.child("bocquet");
  bq.set("stone", v.bocquet_stone);
  {
    Table s{{"speed_m_s", "bocquet_shape"}, {}};
    for (std::size_t i = 0; i < o.bocquet_speeds_m_s.size(); ++i) s.add_row({o.bocquet_speeds_m_s[i], v.bocquet_speed_prediction[i]});
    bq.set_table("speed", s);
    Table w{{"spin_rev_s", "bocquet_N_omega"}, {}};
    for (std::size_t i = 0; i < o.bocquet_spins_rev_s.size(); ++i) w.add_row({o.bocquet_spins_rev_s[i], v.bocquet_spin_prediction[i]});
    bq.set_table("spin", w);
  }

  // Why the conventions disagree: the seed's spinning throw, reference, default law and paper.
  const VariantResult* phys_run = v.find(o.laws.front(), Convention::physical, SolverKind::reference);
  const VariantResult* paper_run = v.find(o.laws.front(), Convention::paper, SolverKind::reference);
  Record& why = r.child("conventions");
  for (const VariantResult* run : {phys_run, paper_run}) {
    Record& g = why.add_child(to_string(run->variant.convention), history_record(run->with_spin));
    store_attitude(g, run->with_spin);
    store_first_contact(g, run->with_spin);
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

  r.add_child("ranking", ranking_record(vars, v, o));
  return r;
}

}  // namespace stoneskip
