// Findings of the validation study (section "validation" of the stones report): each model
// variant's values beside the measured ones (which come from the study file and are stored with
// them), the fitted exponents with their intervals and verdicts, the facts that explain why the
// two conventions disagree (whether the fluids ever do positive work, whether contacts end with
// more energy than they began with, which way the first contact pitches the stone), and the
// answer: the laws ranked by their distance from the measurements and by their cost,
// and the cheapest law that skips like a real stone, if any.
#include <algorithm>
#include <cmath>
#include <numeric>

#include "model/stone/environment.hpp"
#include "verification/stones/stone_studies.hpp"
#include "verification/stones/validation_score.hpp"
#include "verification/stones/validation_scored_value.hpp"
#include "verification/study/order_record.hpp"
#include "verification/study/verdict_rules.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// An attitude change through a contact smaller than this is "held": far above the reference's own
// error in an angle at the validation's rtol (about 1e-5°), and about the smallest change the
// attitude figures show; Clanet et al. state no resolution for their "remains constant".
constexpr double kAttitudeHeld_deg = 0.5;

// Rosellini et al.'s surfing: the stone stays at the surface and does not take off. A stone that
// sinks without a bounce may instead have plunged straight in, which the count alone cannot tell
// apart. A plunge passes the stone through its own height in t_p = height / vertical entry speed
// (the water slows it, so somewhat longer); a contact lasting at least twice that without a bounce
// means the water held the stone up for as long again as it would take to fall through: a surf.
// The factor is this report's rule (Rosellini et al. give no duration), stated beside the verdict.
constexpr double kSurfPlungeRatio = 2;

// Each contact's energy balance |ΔE − ∫P dt| is allowed the trapezoidal rule's estimated error plus
// this many times the integrator's tolerance rtol of the energy scale: CVODE controls each step's
// local error to rtol, and a contact of some hundred steps accumulates a global error of up to
// that many local ones.
constexpr double kIntegratorErrorFactor = 100;

void store_bisected(Record& r, const std::string& key, const BisectedValue& b) {
  Record& c = r.child(key);
  c.set("found", b.found);
  c.set("value", b.found ? b.value() : kNaN);
  c.set("half_width", b.found ? 0.5 * (b.hi - b.lo) : kNaN);
  c.set("bound", b.bounces_at_both_ends ? b.lo : kNaN);  // bounced at both ends: the value lies beyond this
  c.set("note", b.note);
  c.set("runs", b.runs);
}

// A fitted exponent with its 95 % interval and its verdict against the expected one; where the
// series bends in log–log coordinates (power_law_shape.hpp) the verdict says that no single power
// law describes it, and the local exponents stand beside the fit.
void store_exponent(Record& parent, const std::string& key, const OrderFit& f, const PowerLawShape& shape, double expected,
                    double tolerance, const std::string& what) {
  Record& r = parent.child(key);
  r.set("valid", f.valid);
  r.set("exponent", f.valid ? f.order : kNaN);
  r.set("exponent_low", f.valid ? f.order_low : kNaN);
  r.set("exponent_high", f.valid ? f.order_high : kNaN);
  r.set("points", f.points);
  r.set("r_squared", f.valid ? f.r_squared : kNaN);
  r.set("problem", f.problem);
  r.set("shape_tested", shape.tested);
  r.set("curved", shape.curved);
  r.set("curvature_f", shape.tested ? shape.f_statistic : kNaN);
  r.set("curvature_f_critical", shape.tested ? shape.f_critical : kNaN);
  r.set("local_exponent_min", shape.local_min);
  r.set("local_exponent_max", shape.local_max);
  Record in;
  in.set("valid", f.valid);
  in.set("exponent", r.number("exponent"));
  in.set("exponent_low", r.number("exponent_low"));
  in.set("exponent_high", r.number("exponent_high"));
  in.set("points", f.points);
  in.set("expected", expected);
  in.set("tolerance", tolerance);
  in.set("curved", shape.curved);
  in.set("curvature_f", r.number("curvature_f"));
  in.set("curvature_f_critical", r.number("curvature_f_critical"));
  in.set("local_exponent_min", shape.local_min);
  in.set("local_exponent_max", shape.local_max);
  std::string reason =
      !f.valid ? what + ": no fit, " + f.problem
      : f.points < 3
          ? what + ": " + num(f.order) + " from only " + num(f.points, 2) + " points (an interval needs 3)"
          : what + ": " + num(f.order) + " [" + num(f.order_low) + ", " + num(f.order_high) + "] (95 %, " +
                num(f.points, 2) + " points) against the expected " + num(expected) + " ± " + num(tolerance);
  if (f.valid && shape.curved)
    reason += "; the series bends in log–log coordinates (quadratic term: F = " + num(shape.f_statistic) + " > " +
              num(shape.f_critical) + ", 95 %), local exponents " + num(shape.local_min) + " to " + num(shape.local_max);
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
  const double roll = h.result.contacts.empty()
                          ? kNaN
                          : h.result.contacts.front().exit_roll_deg - h.result.contacts.front().entry_roll_deg;
  c.set("roll_change_deg", roll);
  c.set("tolerance_deg", kAttitudeHeld_deg);
  if (h.result.contacts.empty()) return;
  const ContactRecord& k = h.result.contacts.front();
  {
    // The smallest attack angle through the first contact (the trout's dip).
    const auto t = h.table.column("t_s"), a = h.table.column("attack_deg");
    double lo = k.entry_attack_angle_deg;
    for (std::size_t i = 0; i < t.size(); ++i)
      if (t[i] >= k.start_s && t[i] <= k.end_s) lo = std::min(lo, a[i]);
    c.set("min_attack_deg", std::min(lo, k.exit_attack_angle_deg));
  }
  c.set("entry_roll_deg", k.entry_roll_deg);
  c.set("exit_roll_deg", k.exit_roll_deg);
  c.set("start_s", k.start_s);
  c.set("end_s", k.end_s);
  c.set("entry_attack_deg", k.entry_attack_angle_deg);
  c.set("exit_attack_deg", k.exit_attack_angle_deg);
  c.set("entry_speed_m_s", k.entry_speed_m_s);
  c.set("exit_speed_m_s", k.exit_speed_m_s);
  c.set("entry_energy_J", k.entry_energy_J);
  c.set("exit_energy_J", k.exit_energy_J);
  c.set("bounced", k.bounced);
  c.set("plunge_s", h.plunge_s);
  Record in;
  in.set("change_deg", change);
  in.set("tolerance_deg", kAttitudeHeld_deg);
  decide_verdict(c, "pitch", "attack_change", in,
                 "the attack angle goes from " + num(k.entry_attack_angle_deg) + "° at entry to " +
                     num(k.exit_attack_angle_deg) + "° at the end of the contact (a change within ±" +
                     num(kAttitudeHeld_deg) + "° would count as held)");
  Record rin;
  rin.set("change_deg", roll);
  rin.set("tolerance_deg", kAttitudeHeld_deg);
  decide_verdict(c, "roll", "roll_change", rin,
                 "the roll angle goes from " + num(k.entry_roll_deg) + "° at entry to " + num(k.exit_roll_deg) +
                     "° at the end of the contact (a change within ±" + num(kAttitudeHeld_deg) +
                     "° would count as held)");
}

// The energy balance of each contact (ContactEnergy) of a reference run at tolerance rtol, and its
// verdict, into g's child `name` (`throw_words`: which throw, for the reason).
void store_energy(Record& g, const std::string& name, const std::vector<ContactEnergy>& energy, double rtol,
                  const std::string& throw_words) {
  Record& e = g.child(name);
  Table t{{"start_s", "end_s", "energy_change_J", "work_J", "quadrature_error_J", "tolerance_J", "samples"}, {}};
  double max_residual = 0, max_gain = -1e300;
  for (const auto& c : energy) {
    const double tol = c.quadrature_error_J + kIntegratorErrorFactor * rtol * c.energy_scale_J;
    t.add_row({c.start_s, c.end_s, c.energy_change_J, c.work_J, c.quadrature_error_J, tol, double(c.samples)});
    const double r = std::abs(c.energy_change_J - c.work_J) / tol;
    max_residual = std::isnan(r) ? r : (std::isnan(max_residual) ? max_residual : std::max(max_residual, r));
    max_gain = std::max(max_gain, c.energy_change_J / tol);
  }
  e.set_table("contacts", t);
  e.set("rtol", rtol);
  e.set("integrator_error_factor", kIntegratorErrorFactor);
  Record in;
  in.set("contacts", double(energy.size()));
  in.set("max_residual_ratio", energy.empty() ? kNaN : max_residual);
  in.set("max_gain_ratio", energy.empty() ? kNaN : max_gain);
  decide_verdict(e, "verdict", "contact_energy", in,
                 num(energy.size(), 3) + " contacts of " + throw_words + ": the largest |ΔE − ∫P dt| is " + num(max_residual) +
                     " of its tolerance, the largest energy change " + num(max_gain) + " of it (positive: a gain)");
}

// The three regimes of Rosellini et al. and their verdicts, from the stored histories.
void store_regimes(Record& g, const ValidationOptions& o) {
  const Record& dive = g.at("regime_" + record_key(num(o.diving_spin_rev_s, 4)));
  const Record& trout = g.at("regime_" + record_key(num(o.trout_spin_rev_s, 4)));
  const Record& surf = g.at("surfing");
  const double tol = o.ranking.bounds.attitude_deg;
  Record& r = g.child("regime_verdicts");
  {
    Record in;
    in.set("contacts", surf.number("contact_count"));
    in.set("bounces", surf.number("bounces"));
    const Record& c = surf.at("first_contact");
    const double duration_s = c.flag("exists") ? c.number("end_s") - c.number("start_s") : kNaN;
    const double plunge_s = c.flag("exists") ? c.number("plunge_s") : kNaN;
    in.set("duration_s", duration_s);
    in.set("plunge_s", plunge_s);
    in.set("surf_plunge_ratio", kSurfPlungeRatio);
    decide_verdict(r, "surfing", "surfing", in,
                   num(surf.number("contact_count"), 3) + " contacts, " + num(surf.number("bounces"), 3) + " bounces (" +
                       surf.text("outcome") + "); the first contact lasts " +
                       (c.flag("exists") ? num(1000 * duration_s) + " ms" : std::string("–")) +
                       ", against the " + num(1000 * plunge_s) +
                       " ms in which the stone would pass through its own height at its vertical entry speed (a surf: at "
                       "least " + num(kSurfPlungeRatio) + " times that without leaving the water)");
  }
  {
    const Record& c = dive.at("first_contact");
    Record in;
    in.set("bounces", dive.number("bounces"));
    in.set("attack_change_deg", c.number("attack_change_deg"));
    in.set("tolerance_deg", tol);
    decide_verdict(r, "diving", "diving", in,
                   num(dive.number("bounces"), 3) + " bounces; the first contact changes the attack angle by " +
                       num(c.number("attack_change_deg")) + "° (tumbles: more than " + num(tol) + "°)");
  }
  {
    const Record& c = trout.at("first_contact");
    Record in;
    in.set("bounces", trout.number("bounces"));
    in.set("entry_attack_deg", c.flag("exists") ? c.number("entry_attack_deg") : kNaN);
    in.set("min_attack_deg", c.flag("exists") ? c.number("min_attack_deg") : kNaN);
    in.set("tolerance_deg", tol);
    decide_verdict(r, "trout", "trout", in,
                   num(trout.number("bounces"), 3) + " bounces; the attack angle dips from " +
                       num(in.number("entry_attack_deg")) + "° to " + num(in.number("min_attack_deg")) +
                       "° in the first contact (a dip: more than " + num(tol) + "°)");
  }
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
  g.set("distribution", std::string(to_string(v.distribution)));
  g.set("attitude", std::string(to_string(v.attitude)));
  g.set("beside_models", v.beside_models());
  g.set("ranked", v.ranked());
  g.set("convention", std::string(to_string(v.convention)));
  g.set("solver", std::string(v.solver == SolverKind::realtime ? "realtime" : "reference"));
  g.set("title", v.title());
  // Clanet's disk.
  {
    // The bracket's ends too: the figure draws them beside each point.
    Table t{{"attack_deg", "min_speed_m_s", "half_width_m_s", "low_m_s", "high_m_s"}, {}};
    std::vector<std::string> notes;
    for (std::size_t i = 0; i < o.clanet_attack_deg.size(); ++i) {
      const BisectedValue& b = R.min_speed[i];
      t.add_row({o.clanet_attack_deg[i], b.found ? b.value() : kNaN, b.found ? 0.5 * (b.hi - b.lo) : kNaN, b.found ? b.lo : kNaN,
                 b.found ? b.hi : kNaN});
      notes.push_back(b.note);
    }
    g.set_table("min_speed", t);
    g.set_strings("min_speed_notes", notes);
    const std::size_t at = index_of(o.clanet_attack_deg, o.min_speed_attack_deg);
    if (at < R.min_speed.size()) store_bisected(g, "min_speed_at_compared_attack", R.min_speed[at]);
    double best = kNaN, speed = 1e300;
    std::size_t best_i = 0;
    for (std::size_t i = 0; i < R.min_speed.size(); ++i)
      if (R.min_speed[i].found && R.min_speed[i].value() < speed) {
        speed = R.min_speed[i].value();
        best = o.clanet_attack_deg[i];
        best_i = i;
      }
    // One angle on the grid: the argmin is that angle, given, not found (stored as NaN; the
    // ranking leaves the row out and the skip rule cannot meet it).
    if (o.clanet_attack_deg.size() < 2) best = kNaN;
    g.set("best_attack_deg", best);
    // The grid's argmin is not one angle where another angle's minimum-speed bracket overlaps the
    // lowest one's (equal to the bisection's resolution): the span of such angles is stored, and
    // the ranking's argmin row holds only if every angle of it lies within the bound.
    double tied_lo = best, tied_hi = best;
    if (std::isfinite(best))
      for (std::size_t i = 0; i < R.min_speed.size(); ++i) {
        const BisectedValue& b = R.min_speed[i];
        if (!b.found || b.lo > R.min_speed[best_i].hi) continue;
        tied_lo = std::min(tied_lo, o.clanet_attack_deg[i]);
        tied_hi = std::max(tied_hi, o.clanet_attack_deg[i]);
      }
    g.set("best_attack_tied_low_deg", tied_lo);
    g.set("best_attack_tied_high_deg", tied_hi);
    store_bisected(g, "largest_path_angle", R.largest_path_angle);
    Table ct{{"speed_m_s", "contact_s"}, {}};
    for (std::size_t i = 0; i < o.clanet_contact_speeds_m_s.size(); ++i)
      ct.add_row({o.clanet_contact_speeds_m_s[i], R.contact_time_s[i]});
    g.set_table("contact_time", ct);
    store_exponent(g, "contact_exponent", R.contact_time_fit, R.contact_time_shape, o.contact_exponent_expected, o.exponent_tolerance,
                   "exponent of the contact time against U");
    std::vector<std::string> regimes;
    for (std::size_t i = 0; i < o.regime_spins_rev_s.size(); ++i) {
      const std::string key = "regime_" + record_key(num(o.regime_spins_rev_s[i], 4));
      regimes.push_back(key);
      g.add_child(key, stored_history(R.regimes[i], o.history_dt_s)).set("spin_rev_s", o.regime_spins_rev_s[i]);
    }
    g.set_strings("regimes", regimes);
    g.add_child("surfing", stored_history(R.surfing, o.history_dt_s));
    store_regimes(g, o);
    if (v.solver == SolverKind::reference) store_energy(g, "energy", R.energy, R.energy_rtol, "the reference throw");
    store_bisected(g, "sphere_path_angle", R.sphere_path_angle);
  }
  if (!v.beside_models()) return g;
  // Bocquet's stone.
  {
    Table s{{"speed_m_s", "count"}, {}};
    for (std::size_t i = 0; i < o.bocquet_speeds_m_s.size(); ++i) s.add_row({o.bocquet_speeds_m_s[i], double(R.count_vs_speed[i])});
    g.set_table("bocquet_speed", s);
    Table w{{"spin_rev_s", "count"}, {}};
    for (std::size_t i = 0; i < o.bocquet_spins_rev_s.size(); ++i) w.add_row({o.bocquet_spins_rev_s[i], double(R.count_vs_spin[i])});
    g.set_table("bocquet_spin", w);
    store_exponent(g, "speed_exponent", R.speed_fit, R.speed_shape, o.count_exponent_expected, o.exponent_tolerance,
                   "exponent of N against V² (N > 0)");
    store_exponent(g, "spin_exponent", R.spin_fit, R.spin_shape, o.count_exponent_expected, o.exponent_tolerance,
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

}  // namespace

namespace {

// The measured range of a scored row, NaN when the study file does not score it.
MeasuredRange range_of(const ValidationOptions& o, const std::string& key) {
  for (const auto& m : o.measured)
    if (m.key == key && m.score) return *m.score;
  return {kNaN, kNaN};
}

// A variant's inputs to skips_like_a_stone, under `prefix` ("" or "V."), from its record.
void skip_inputs(Record& in, const std::string& prefix, const Record& g, const std::string& held_key,
                 const ValidationOptions& o) {
  auto value = [&](const std::string& key) {
    const ScoredValue v = scored_value(g, key, o);
    return v.has_value ? v.model : kNaN;
  };
  in.set(prefix + "min_speed", value("clanet_min_speed"));
  // The bisections' half-brackets: a row is decided only where the whole bracket lies on one side
  // of its bound (skips_like_a_stone).
  auto half_width = [&](const char* child) {
    return g.has_child(child) && g.at(child).flag("found") ? g.at(child).number("half_width") : 0.0;
  };
  in.set(prefix + "min_speed_half_width", half_width("min_speed_at_compared_attack"));
  in.set(prefix + "max_path_angle_half_width", half_width("largest_path_angle"));
  in.set(prefix + "best_attack", value("clanet_best_attack"));
  // A one-angle grid measures no argmin (scored_value): its tied span, the angle itself, would meet
  // the row; without it the NaN misses, as an unmeasured row must not be met.
  if (g.has_number("best_attack_tied_low_deg") && std::isfinite(value("clanet_best_attack"))) {
    in.set(prefix + "best_attack_tied_low", g.number("best_attack_tied_low_deg"));
    in.set(prefix + "best_attack_tied_high", g.number("best_attack_tied_high_deg"));
    in.set(prefix + "best_attack_tied_placed", 1.0);  // the span judged as an interval (verdict_rules.cpp)
  }
  in.set(prefix + "max_path_angle", value("clanet_max_path_angle"));
  in.set(prefix + "contact_time", value("clanet_contact_time"));
  // The exponent's interval counts only where one power law describes the series (records written
  // before the shape test have no "curved": their fit counts as before).
  const Record& e = g.at("contact_exponent");
  const bool fitted = e.flag("valid") && e.number("points") >= 3 && !(e.has_number("curved") && e.flag("curved"));
  in.set(prefix + "contact_exponent_low", fitted ? e.number("exponent_low") : kNaN);
  in.set(prefix + "contact_exponent_high", fitted ? e.number("exponent_high") : kNaN);
  const Record& held = g.at(held_key).at("first_contact");
  in.set(prefix + "pitch_change_deg", held.number("attack_change_deg"));
  in.set(prefix + "roll_change_deg", held.number("roll_change_deg"));
  const Record& r = g.at("regime_verdicts");
  in.set(prefix + "surfing", r.at("surfing").text("verdict") == "never leaves the water" ? 1.0 : 0.0);
  in.set(prefix + "diving", r.at("diving").text("verdict") == "tumbles and dives" ? 1.0 : 0.0);
  in.set(prefix + "trout", r.at("trout").text("verdict") == "dips and still bounces" ? 1.0 : 0.0);
  const Record& en = g.at("energy").at("verdict");
  in.set(prefix + "max_residual_ratio", en.number("max_residual_ratio"));
  in.set(prefix + "max_gain_ratio", en.number("max_gain_ratio"));
}

// The measured ranges and the bounds (unprefixed inputs of skips_like_a_stone).
void bound_inputs(Record& in, const ValidationOptions& o) {
  const SkipBounds& b = o.ranking.bounds;
  const MeasuredRange u = range_of(o, "clanet_min_speed"), a = range_of(o, "clanet_best_attack"),
                      p = range_of(o, "clanet_max_path_angle"), c = range_of(o, "clanet_contact_time"),
                      k = range_of(o, "clanet_contact_exponent");
  in.set("min_speed_low", u.low).set("min_speed_high", u.high).set("min_speed_fraction", b.min_speed_fraction);
  in.set("best_attack_low", a.low).set("best_attack_high", a.high).set("best_attack_bound", b.best_attack_deg);
  in.set("max_path_angle_low", p.low).set("max_path_angle_high", p.high).set("max_path_angle_bound", b.max_path_angle_deg);
  in.set("contact_time_low", c.low).set("contact_time_high", c.high).set("contact_time_fraction", b.contact_time_fraction);
  in.set("contact_exponent_measured", 0.5 * (k.low + k.high));
  in.set("contact_exponent_tolerance", o.exponent_tolerance);  // the power_law_exponent rule's (§5)
  in.set("attitude_bound_deg", b.attitude_deg);
}

// The answer: each ranked variant (law × distribution × attitude, CVODE,
// physical convention) against the rows and bounds, its distance from the measurements and its
// cost, and the cheapest passive law and distribution (free attitude) that skips like a real stone.
Record ranking_record(const Record& variants, const ValidationResult& v, const ValidationOptions& o) {
  const RankingOptions& k = o.ranking;
  Record r;
  r.set("miss_distance", k.miss_distance);
  r.set("held_spin_rev_s", k.held_spin_rev_s);
  r.set("regime_attack_deg", o.regime_attack_deg);
  r.set("cost_repeats", k.cost_repeats);
  r.set("clock", std::string("thread CPU time of one throw, the minimum over the repeats"));
  bound_inputs(r.child("bounds"), o);
  std::vector<std::string> scored;
  std::vector<MeasuredRange> ranges;
  for (const auto& m : o.measured)
    // A one-angle grid measures no argmin: the row is left out of the distance (a miss for every
    // variant would only shift them all).
    if (m.score && !(m.key == "clanet_best_attack" && o.clanet_attack_deg.size() < 2)) {
      scored.push_back(m.key);
      ranges.push_back(*m.score);
    }
  r.set_strings("scored", scored);
  const std::string held_key = "regime_" + record_key(num(k.held_spin_rev_s, 4));
  r.set("held_regime", held_key);  // the variants' child holding that regime
  std::vector<std::string> keys;
  Record answer_in;
  bound_inputs(answer_in, o);
  std::string reason;
  for (const LawCost& c : v.costs) {
    const std::string key = c.variant.key();
    keys.push_back(key);
    const Record& g = variants.at(key);
    Record& L = r.child(key);
    L.set("title", c.variant.title());
    L.set("free", c.variant.attitude == Attitude::free);
    std::vector<ScoredValue> values;
    for (const auto& q : scored) values.push_back(scored_value(g, q, o));
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
    const Record& held = g.at(held_key);
    L.set("pitch_change_deg", held.at("first_contact").number("attack_change_deg"));
    L.set("roll_change_deg", held.at("first_contact").number("roll_change_deg"));
    L.set("held_bounces", held.number("bounces"));
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
    bound_inputs(in, o);
    skip_inputs(in, "", g, held_key, o);
    // The exponent as the row judges it: its interval, or why there is none (skip_inputs).
    const Record& ex = g.at("contact_exponent");
    const std::string exponent_words =
        std::isfinite(in.number("contact_exponent_low"))
            ? "exponent [" + num(in.number("contact_exponent_low")) + ", " + num(in.number("contact_exponent_high")) + "]"
        : !(ex.flag("valid") && ex.number("points") >= 3)
            ? std::string("exponent not fitted (fewer than 3 contact times)")
            : "exponent " + num(ex.number("exponent")) + " not counted: the contact times bend (no single power law)";
    const std::string argmin_words =
        !std::isfinite(in.number("best_attack")) ? std::string("not measured")
        : in.has_number("best_attack_tied_low") && in.number("best_attack_tied_low") != in.number("best_attack_tied_high")
            ? num(in.number("best_attack")) + "° (tied over " + num(in.number("best_attack_tied_low")) + "–" +
                  num(in.number("best_attack_tied_high")) + "°)"
            : num(in.number("best_attack")) + "°";
    decide_verdict(L, "skips", "skips_like_a_stone", in,
                   "U_min " + num(in.number("min_speed")) + " ± " + num(in.number("min_speed_half_width")) + " m/s, argmin α " +
                       argmin_words + ", β_max " + num(in.number("max_path_angle")) + " ± " +
                       num(in.number("max_path_angle_half_width")) + "°, contact " + num(1000 * in.number("contact_time")) +
                       " ms, " + exponent_words + ", pitch " + num(in.number("pitch_change_deg")) +
                       "° and roll " + num(in.number("roll_change_deg")) + "° through the first contact at " +
                       num(k.held_spin_rev_s) + " rev/s; regimes: " + g.at("regime_verdicts").at("surfing").text("verdict") +
                       " / " + g.at("regime_verdicts").at("diving").text("verdict") + " / " +
                       g.at("regime_verdicts").at("trout").text("verdict") + "; energy " +
                       g.at("energy").at("verdict").text("verdict"));
    skip_inputs(answer_in, key + ".", g, held_key, o);
    answer_in.set(key + ".free", c.variant.attitude == Attitude::free);
    answer_in.set(key + ".cost_s", c.mean_realtime_cpu_s);
    answer_in.set(key + ".distance", d.mean);
    reason += (reason.empty() ? "" : "; ") + key + ": " + L.at("skips").text("verdict") + ", distance " + num(d.mean) + ", " +
              num(1000 * c.mean_realtime_cpu_s) + " ms real-time CPU per throw";
  }
  r.set_strings("variants", keys);
  auto sorted_by = [&](const std::string& field) {
    std::vector<std::string> s = keys;
    std::stable_sort(s.begin(), s.end(), [&](const std::string& a, const std::string& b) {
      const double x = r.at(a).number(field), y = r.at(b).number(field);
      return x < y || (std::isnan(y) && !std::isnan(x));
    });
    return s;
  };
  r.set_strings("by_distance", sorted_by("distance"));
  r.set_strings("by_cost", sorted_by("realtime_cpu_s"));
  decide_verdict(r, "answer", "cheapest_skipping_variant", answer_in, reason);
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
  r.set("default_law", std::string(to_string(o.laws.front())));  // the study's first law (real-time column, Fig. 9)
  {
    // The model's own default in the physical convention (what a case that names no law runs), which
    // the study's first law need not be: the prose names both.
    Environment model_default;
    set_convention(model_default, Convention::physical);
    set_default_water_model(model_default);
    r.set("model_default_law", std::string(to_string(model_default.water_law)));
    r.set("model_default_distribution", std::string(to_string(model_default.pressure_distribution)));
  }
  r.set("attitude_held_deg", kAttitudeHeld_deg);
  {
    std::vector<std::string> d;
    for (auto x : o.distributions) d.push_back(to_string(x));
    r.set_strings("distributions", d);
  }
  {
    // Johnson & Reid 1975 (quoted by Nagahiro & Hayakawa 2005): θ_max ≈ 18°/√σ.
    Record& sp = r.child("sphere");
    sp.set("stone", v.sphere_stone);
    sp.set("density_ratio", o.sphere_density_ratio);
    sp.set("speed_m_s", o.sphere_speed_m_s);
    sp.set("theta_max_deg", o.sphere_theta_coefficient_deg / std::sqrt(o.sphere_density_ratio));
  }
  r.set("peer_description", o.peer_description);
  // The measured contact time as a point for the contact-time figure (ms, at its speed).
  for (const auto& x : o.measured)
    if (x.key == "clanet_contact_time" && x.score) {
      Table t{{"speed_m_s", "contact_ms"}, {}};
      t.add_row({o.contact_time_speed_m_s, 1000 * x.score->low});
      r.set_table("measured_contact_time", t);
    }
  r.set("surfing_attack_deg", o.surfing_attack_deg);
  r.set("surfing_path_angle_deg", o.surfing_path_angle_deg);
  r.set("diving_spin_rev_s", o.diving_spin_rev_s);
  r.set("trout_spin_rev_s", o.trout_spin_rev_s);
  r.set("diving_regime", "regime_" + record_key(num(o.diving_spin_rev_s, 4)));  // the variants' children
  r.set("trout_regime", "regime_" + record_key(num(o.trout_spin_rev_s, 4)));
  r.set("held_regime", "regime_" + record_key(num(o.ranking.held_spin_rev_s, 4)));
  {
    Record& m = r.child("measured");
    std::vector<std::string> keys;
    for (const auto& x : o.measured) {
      keys.push_back(x.key);
      Record& k = m.child(x.key);
      k.set("quantity", x.quantity);
      k.set("measured", x.measured);
      k.set("expected", x.expected);
      k.set("peer", x.peer.empty() ? std::string("–") : x.peer);
      k.set("source", x.source);
      k.set("kind", x.kind);
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
      // The one model curve (clanet_min_speed): the least speed that skips against the attack angle.
      Table t{{"x", "low", "high"}, {}, {"deg", "m/s", "m/s"}};
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
    const Record& pap = why.at("paper");
    const double p_pap = pap.number("max_fluid_power_W");
    // Energy, a check that can fail: each contact's energy change against the integrated fluid
    // power, for the default law's reference run of the same seed throw the paper's verdict is on
    // (store_energy). P ≤ 0 holds face by face in the physical convention (an identity of the law):
    // the balance is what is checked.
    store_energy(why, "physical_seed_energy", phys_run->with_spin_energy, o.reference_rtol, "the seed's spinning throw");
    why.add_child("physical_energy", why.at("physical_seed_energy").at("verdict"));
    // A positive rate of work in the paper convention counts only above round-off of the stone's
    // own energy scale.
    const double round_off_W = 1e-9 * std::max(1.0, std::abs(pap.number("max_energy_gain_J")));
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
