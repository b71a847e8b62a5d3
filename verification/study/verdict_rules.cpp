#include "verification/study/verdict_rules.hpp"

#include "verification/study/order_record.hpp"
#include "verification/study/stored_values.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <vector>

#include "verification/convergence/order_fit.hpp"

namespace stoneskip {

namespace {

using Rule = std::function<std::string(const Record&)>;

std::string capture_verdict_phrase(const Record& in) {
  const CaptureConditions c = capture_conditions(in);
  return !c.unusable.empty() ? "unusable" : (c.caveats.empty() ? "usable" : "usable with caveats");
}

// The names P of the inputs "P.field" that have the given field (the variants a rule compares).
std::vector<std::string> prefixes_with(const Record& in, const std::string& field) {
  std::vector<std::string> out;
  const std::string tail = "." + field;
  for (const auto& [key, value] : in.numbers())
    if (key.size() > tail.size() && key.compare(key.size() - tail.size(), tail.size(), tail) == 0)
      out.push_back(key.substr(0, key.size() - tail.size()));
  return out;  // sorted by name (numbers() is ordered)
}

// skips_like_a_stone: the rows a variant misses and the rows its intervals leave undecided (prefix
// "V." for the variant's own numbers, the measured ranges and bounds unprefixed), by name, in the
// order of the page. A NaN misses.
bool within(double x, double lo, double hi) { return x >= lo && x <= hi; }
// An interval [lo, hi] against a band: wholly inside, wholly outside, or across it (a NaN end is
// neither inside nor outside).
enum class Placement { inside, outside, across };
Placement placement(double lo, double hi, double band_lo, double band_hi) {
  if (lo >= band_lo && hi <= band_hi) return Placement::inside;
  return hi < band_lo || lo > band_hi ? Placement::outside : Placement::across;
}
struct RowJudgement {
  std::vector<std::string> missed, undecided;
};
RowJudgement judge_rows(const Record& in, const std::string& v) {
  RowJudgement out;
  auto row = [&](bool met, const char* name) {
    if (!met) out.missed.emplace_back(name);
  };
  // An interval against its row's band: a NaN end misses, as a NaN value does.
  auto placed = [&](double lo, double hi, double band_lo, double band_hi, const char* name) {
    const Placement p = std::isfinite(lo) && std::isfinite(hi) ? placement(lo, hi, band_lo, band_hi) : Placement::outside;
    if (p == Placement::outside) out.missed.emplace_back(name);
    else if (p == Placement::across) out.undecided.emplace_back(name);
  };
  // A bisected value x ± h (its bracket; records before the brackets were stored: h = 0) against
  // [lo, hi]: met when the whole bracket lies within, missed when none of it does, else undecided.
  auto bracketed = [&](const std::string& key, double lo, double hi, const char* name) {
    const double x = in.number(v + key);
    const double h = in.has_number(v + key + "_half_width") && std::isfinite(in.number(v + key + "_half_width"))
                         ? in.number(v + key + "_half_width")
                         : 0.0;
    placed(x - h, x + h, lo, hi, name);
  };
  const double f = in.number("min_speed_fraction"), g = in.number("contact_time_fraction");
  bracketed("min_speed", in.number("min_speed_low") * (1 - f), in.number("min_speed_high") * (1 + f), "U_min");
  // The argmin: where the grid's lowest minimum speeds tie over a span of angles (records since
  // the span was stored), the span against the bound like any interval: met when every angle of it
  // lies within, missed when none does, else undecided.
  const double a_lo = in.number("best_attack_low") - in.number("best_attack_bound"),
               a_hi = in.number("best_attack_high") + in.number("best_attack_bound");
  // Records written before the span was judged as an interval (no best_attack_tied_placed): a span
  // not wholly within missed, as then.
  if (in.has_number(v + "best_attack_tied_low") && in.has_number(v + "best_attack_tied_placed"))
    placed(in.number(v + "best_attack_tied_low"), in.number(v + "best_attack_tied_high"), a_lo, a_hi, "argmin α");
  else if (in.has_number(v + "best_attack_tied_low"))
    row(within(in.number(v + "best_attack_tied_low"), a_lo, a_hi) && within(in.number(v + "best_attack_tied_high"), a_lo, a_hi),
        "argmin α");
  else
    row(within(in.number(v + "best_attack"), a_lo, a_hi), "argmin α");
  bracketed("max_path_angle", in.number("max_path_angle_low") - in.number("max_path_angle_bound"),
            in.number("max_path_angle_high") + in.number("max_path_angle_bound"), "β_max");
  row(within(in.number(v + "contact_time"), in.number("contact_time_low") * (1 - g), in.number("contact_time_high") * (1 + g)),
      "contact time");
  // The exponent's 95 % interval against the measured exponent ± the tolerance of the report's
  // power_law_exponent rule: met inside, missed disjoint, else undecided (a wider, noisier fit no
  // longer passes more easily). Records before the tolerance was stored: the interval containing
  // the measured exponent, as then.
  {
    const double m = in.number("contact_exponent_measured"), lo = in.number(v + "contact_exponent_low"),
                 hi = in.number(v + "contact_exponent_high");
    if (!in.has_number("contact_exponent_tolerance")) {
      row(within(m, lo, hi), "contact exponent");
    } else {
      const double tol = in.number("contact_exponent_tolerance");
      placed(lo, hi, m - tol, m + tol, "contact exponent");
    }
  }
  row(std::abs(in.number(v + "pitch_change_deg")) <= in.number("attitude_bound_deg") &&
          std::abs(in.number(v + "roll_change_deg")) <= in.number("attitude_bound_deg"),
      "attitude");
  row(in.number(v + "surfing") == 1, "surfing");
  row(in.number(v + "diving") == 1, "diving");
  row(in.number(v + "trout") == 1, "trout");
  return out;  // each list in the page's order: the rows are judged in it
}
constexpr int kSkipRows = 9;  // the rows missed_rows judges
bool passive(const Record& in, const std::string& v) {
  return in.number(v + "max_residual_ratio") <= 1 && in.number(v + "max_gain_ratio") <= 1;
}
std::string joined(const std::vector<std::string>& xs) {
  std::string s;
  for (const auto& x : xs) s += (s.empty() ? "" : ", ") + x;
  return s;
}

// The cheapest of the named candidates that pass: by cost, ties to the smaller tie_break, then by
// name. Empty when none passes.
struct Candidate {
  std::string name;
  double cost = 0, tie_break = 0;
};
std::string cheapest(const std::vector<Candidate>& passing) {
  const Candidate* best = nullptr;
  for (const auto& c : passing)
    if (!best || c.cost < best->cost || (c.cost == best->cost && c.tie_break < best->tie_break)) best = &c;
  return best ? best->name : std::string();
}

// Two ensembles' counts: does the difference of the means exclude 0? Without spread the interval
// is the difference itself and an exact permutation test decides (ensemble_difference.hpp); a
// difference seen but not established is "no difference established", never "same". Records
// written before exact_p was an input have none, and are judged by the interval as before.
bool exact_test_made(const Record& in) { return in.has_number("exact_p") && std::isfinite(in.number("exact_p")); }
bool difference_established(const Record& in) {
  if (!(in.number("difference_low") > 0 || in.number("difference_high") < 0)) return false;
  return !exact_test_made(in) || in.number("exact_p") <= in.number("alpha");
}
bool difference_seen(const Record& in) { return in.number("count_spread") > 0 || exact_test_made(in); }

const std::map<std::string, Rule>& rules() {
  static const std::map<std::string, Rule> r{
      {"order_fit",
       [](const Record& in) {
         OrderFit f;
         f.valid = in.flag("valid");
         f.order = in.number("order");
         f.order_low = in.number("order_low");
         f.order_high = in.number("order_high");
         f.points = static_cast<int>(stored_count(in, "points", kMostFitPoints));
         // Only how many refinements grew the error matters to the rule (order_fit.hpp); records
         // written before it was an input have none.
         if (in.has_number("refinements") && in.has_number("growing_refinements")) {
           const long n = static_cast<long>(stored_count(in, "refinements", kMostFitPoints)),
                    grew = static_cast<long>(stored_count(in, "growing_refinements", kMostFitPoints));
           f.pairwise.assign(static_cast<std::size_t>(std::max(0L, n)), 1.0);
           for (long k = 0; k < grew && k < n; ++k) f.pairwise[static_cast<std::size_t>(k)] = -1.0;
         }
         // Failed runs and the drift of the local order (order_fit.hpp); records written before
         // they were inputs have none.
         if (in.has_number("failed_points")) f.failed_points = static_cast<int>(stored_count(in, "failed_points", kMostFitPoints));
         if (in.has("corrected")) f.corrected = in.flag("corrected");
         read_order_shape(in, f);
         OrderJudgement j;
         j.expected_order = in.number("expected_order");
         j.tolerance = in.number("tolerance");
         j.minimum_order = in.number("minimum_order");
         return std::string(to_string(judge_order(f, j).verdict));
       }},
      {"consistency",
       [](const Record& in) {
         const double tol = in.number("tolerance");
         const bool ok = std::abs(in.number("constant_term")) <= tol &&
                         std::abs(in.number("laplacian_coefficient") - 1) <= tol;
         return std::string(ok ? "consistent" : "inconsistent");
       }},
      {"gci_band",
       [](const Record& in) {
         if (!in.flag("usable")) return std::string("no estimate");
         if (in.flag("order_does_not_converge")) return std::string("misleading");
         return std::string(in.number("actual_relative_error") <= in.number("gci_fine") ? "contains the exact value"
                                                                                       : "misses the exact value");
       }},
      {"limit_range",
       [](const Record& in) {
         return std::string(in.number("limit_max") - in.number("limit_min") < in.number("tolerance")
                                ? "independent of the damping"
                                : "depends on the damping");
       }},
      {"counterexample",
       [](const Record& in) {
         const bool inside = in.number("sigma") < in.number("bound");
         const bool grows = in.number("predicted_growth_per_step") > 1 && in.number("measured_growth_per_step") > 1;
         return std::string(inside && grows ? "not sufficient"
                                            : (inside ? "not refuted by this example" : "example outside the bound"));
       }},
      {"work_gain",
       [](const Record& in) {
         const double g = in.number("gain");
         if (std::isnan(g)) return std::string("not established");
         return std::string(g < in.number("material_gain") ? "no other stencil is materially faster"
                                                           : "another stencil is faster");
       }},
      {"minimum_ratio",
       [](const Record& in) {
         const double ratio = in.number("ratio");
         if (std::isnan(ratio)) return std::string("not measured");
         return std::string(ratio >= in.number("required") ? "error control works" : "error control falls short");
       }},
      {"thresholds_near_grid",
       [](const Record& in) {
         const double near = in.number("near_grid"), n = in.number("bisected");
         if (n < 3) return std::string("too few thresholds to tell");
         if (2 * near >= n) return std::string("sensitive dependence");
         // Clean steps only where every change was located (data stored before `unlocated`: as then).
         if (in.has_number("unlocated") && !(in.number("unlocated") == 0)) return std::string("not all changes located");
         return std::string("clean steps");
       }},
      {"attack_change",
       [](const Record& in) {
         const double d = in.number("change_deg"), tol = in.number("tolerance_deg");
         if (std::isnan(d)) return std::string("no contact");
         return std::string(d < -tol ? "nose-down" : (d > tol ? "nose-up" : "held"));
       }},
      {"roll_change",
       [](const Record& in) {
         const double d = in.number("change_deg"), tol = in.number("tolerance_deg");
         if (std::isnan(d)) return std::string("no contact");
         return std::string(d < -tol ? "rolls (roll falls)" : (d > tol ? "rolls (roll grows)" : "held"));
       }},
      {"max_fluid_power",
       [](const Record& in) {
         return std::string(in.number("max_fluid_power_W") <= in.number("round_off_W") ? "passive" : "creates energy");
       }},
      {"contact_energy",
       [](const Record& in) {
         if (in.number("contacts") < 1) return std::string("no contact");
         if (!(in.number("max_residual_ratio") <= 1)) return std::string("unbalanced");
         return std::string(in.number("max_gain_ratio") <= 1 ? "balanced, passive" : "balanced, creates energy");
       }},
      {"surfing",
       [](const Record& in) {
         if (in.number("contacts") < 1) return std::string("no contact");
         if (in.number("bounces") > 0) return std::string("leaves the water");
         // Records written before the plunge time was stored: judged by the count alone, as then.
         if (!in.has_number("duration_s")) return std::string("never leaves the water");
         // A stone that sinks within a few plunge times was not held at the surface: it did not
         // surf, whatever its count (NaN: no downward entry to measure a plunge by).
         const double ratio = in.number("duration_s") / in.number("plunge_s");
         if (!(ratio >= 0)) return std::string("not decided: no plunge time");
         return std::string(ratio >= in.number("surf_plunge_ratio") ? "never leaves the water" : "sinks as it plunges");
       }},
      {"diving",
       [](const Record& in) {
         if (in.number("bounces") > 0) return std::string("bounces");
         return std::string(std::abs(in.number("attack_change_deg")) > in.number("tolerance_deg") ? "tumbles and dives"
                                                                                                  : "sinks holding its attitude");
       }},
      {"trout",
       [](const Record& in) {
         if (in.number("bounces") < 1) return std::string("no bounce");
         return std::string(in.number("entry_attack_deg") - in.number("min_attack_deg") > in.number("tolerance_deg")
                                ? "dips and still bounces"
                                : "bounces without a dip");
       }},
      {"power_law_exponent",
       [](const Record& in) {
         if (!in.flag("valid") || in.number("points") < 3) return std::string("too few points to fit");
         // A series that bends in log–log coordinates has no one exponent to judge (inputs written
         // before the shape test carry no "curved").
         if (in.has_number("curved") && in.flag("curved")) return std::string("not a single power law");
         const double lo = in.number("exponent_low"), hi = in.number("exponent_high");
         const double band_lo = in.number("expected") - in.number("tolerance"),
                      band_hi = in.number("expected") + in.number("tolerance");
         switch (placement(lo, hi, band_lo, band_hi)) {
           case Placement::inside: return std::string("consistent with the expected exponent");
           case Placement::outside: return std::string("excludes the expected exponent");
           case Placement::across: break;
         }
         return std::string("exponent not established");
       }},
      {"skips_like_a_stone",
       [](const Record& in) {
         const RowJudgement j = judge_rows(in, "");
         if (!passive(in, "")) return std::string("not passive");
         if (!j.missed.empty())
           return "misses " + joined(j.missed) + (j.undecided.empty() ? std::string() : "; not decided: " + joined(j.undecided));
         return j.undecided.empty() ? std::string("skips like a real stone") : "not decided: " + joined(j.undecided);
       }},
      {"cheapest_skipping_variant",
       [](const Record& in) {
         // Candidates: the free-attitude variants (V.free = 1), passive by their contacts' energy.
         std::vector<Candidate> passing;
         std::vector<std::string> free;
         for (const auto& v : prefixes_with(in, "cost_s")) {
           if (in.number(v + ".free") != 1) continue;
           free.push_back(v);
           const RowJudgement j = judge_rows(in, v + ".");
           if (passive(in, v + ".") && j.missed.empty() && j.undecided.empty())
             passing.push_back({v, in.number(v + ".cost_s"), in.number(v + ".distance")});
         }
         const std::string best = cheapest(passing);
         if (!best.empty()) return best + " is the cheapest passive law and distribution that skips like a real stone";
         if (free.empty()) return std::string("no free-attitude variant was run");
         // The rows no free variant meets, and the closest: most rows met, then the smaller distance, then the name.
         std::map<std::string, int> misses;
         std::string closest;
         int closest_met = -1;
         double closest_distance = 0;
         for (const auto& v : free) {
           const RowJudgement j = judge_rows(in, v + ".");
           for (const auto& row : j.missed) ++misses[row];  // unmet: missed, or not decided
           for (const auto& row : j.undecided) ++misses[row];
           const int met = kSkipRows - static_cast<int>(j.missed.size() + j.undecided.size());
           const double d = in.number(v + ".distance");
           if (met > closest_met || (met == closest_met && d < closest_distance)) {
             closest = v;
             closest_met = met;
             closest_distance = d;
           }
         }
         std::vector<std::string> none;
         for (const char* row : {"U_min", "argmin α", "β_max", "contact time", "contact exponent", "attitude", "surfing",
                                 "diving", "trout"})
           if (misses[row] == static_cast<int>(free.size())) none.emplace_back(row);
         return "no variant skips like a real stone; no free variant meets " + (none.empty() ? std::string("—") : joined(none)) +
                "; closest: " + closest + " (" + std::to_string(closest_met) + " of " + std::to_string(kSkipRows) + " rows)";
       }},
      {"restart_strategy",
       [](const Record& in) {
         std::vector<Candidate> passing;
         for (const auto& s : prefixes_with(in, "rhs_evaluations"))
           if (in.number(s + ".failed") == 0 && in.number(s + ".error_ratio") <= 1)
             passing.push_back({s, in.number(s + ".rhs_evaluations"), 0});
         const std::string best = cheapest(passing);
         return best.empty() ? std::string("no strategy keeps the contact times")
                             : best + " is the cheapest strategy that keeps the contact times";
       }},
      {"grid_differences",
       [](const Record& in) {
         // verification/scene/scene_grid_findings.cpp: each quantity's largest change over the one
         // before as the cells get finer (ratio < 1: every change shrinking); fewer than 3 grids
         // decide nothing.
         // A quantity whose changes do not shrink, but whose last change is no larger than halving
         // the water step alone moves it on the finest grid (time_change_*, where stored), is
         // within the water step's error: the sequence cannot say whether it converges.
         if (in.number("grids") < 3) return std::string("not decided: fewer than three grids");
         // A grid whose own first contact leaves the pond, or (on a disturbed surface) lies within
         // the reach of the pond's walls at c before it ends (walls_reach_track, stored since 8
         // December): its answers are partly the pond's, not the case's.
         if (in.has_number("walls_reach_track") && in.number("walls_reach_track") > 0)
           return std::string("not decided: on some grid the pond's walls are not clear of the first contact");
         // The first contact ending in a bounce on one grid and not on the next (outcome_changes,
         // stored since 7 December): not one contact refined, whatever its numbers do.
         if (in.has_number("outcome_changes") && in.number("outcome_changes") > 0)
           return std::string("does not converge: the first contact bounces on some grids and not on others");
         std::vector<std::string> growing, within_step;
         for (const char* q : {"pressure_work_J", "first_duration_s", "first_exit_m_s"}) {
           if (in.number(std::string("ratio_") + q) < 1) continue;
           const std::string t = std::string("time_change_") + q, l = std::string("last_change_") + q;
           const bool in_step = in.has_number(t) && in.has_number(l) && in.number(t) >= in.number(l);
           (in_step ? within_step : growing).emplace_back(q);
         }
         if (!growing.empty()) return "does not converge: " + joined(growing) + " change no less as the cells get finer";
         if (!within_step.empty())
           return "not decided: " + joined(within_step) + " change no more than halving the water step moves them";
         return std::string("the changes shrink as the cells halve");
       }},
      {"level_in_time",
       [](const Record& in) {
         // verification/scene/scene_step_findings.cpp: at each step and quantity, which reading's
         // error against the fine-step reference is smaller, where the two differ by more than
         // twice the reference's own gap (closer: the extrapolated level's; farther: the held one's).
         if (in.number("missing") > 0) return std::string("not decided: a run made no contact");
         const double closer = in.number("closer"), farther = in.number("farther");
         if (closer + farther == 0) return std::string("not decided: the reference does not resolve the difference");
         if (farther == 0) return std::string("the extrapolated level is closer to the reference wherever the difference is resolved");
         if (closer == 0) return std::string("the held level is closer to the reference wherever the difference is resolved");
         // Both win somewhere: which one wins every resolved comparison at the finest step (records
         // before these inputs: not asked).
         const auto at_finest = [&](const char* k) { return in.has_number(k) ? in.number(k) : 0.0; };
         const double fc = at_finest("finest_closer"), ff = at_finest("finest_farther");
         if (fc > 0 && ff == 0) return std::string("the extrapolated level is closer at the finest step, not at every step");
         if (ff > 0 && fc == 0) return std::string("the held level is closer at the finest step, not at every step");
         return std::string("neither level is closer at every step");
       }},
      {"error_split",
       [](const Record& in) {
         if (in.flag("space_converges")) return std::string("converges in space");
         return std::string(in.flag("time_at_expected")
                                ? "does not converge: the stencil is at fault, not the time stepping"
                                : "does not converge in space; the time stepping is not at its expected order either");
       }},
      {"capture_verdict", capture_verdict_phrase},
      {"bounce_agreement",
       [](const Record& in) {
         // A failed run's bounces until the failure are not its count.
         const auto failed = [&](const char* k) { return in.has_number(k) && in.number(k) > 0; };
         if (failed("realtime_failed") || failed("reference_failed")) return std::string("not decided: a run failed");
         return std::string(in.number("realtime_bounces") == in.number("reference_bounces") ? "same bounce count"
                                                                                          : "different bounce counts");
       }},
      {"reference_resolves",
       [](const Record& in) {
         return std::string(in.number("margin") * in.number("reference_error_m") <= in.number("smallest_error_m")
                                ? "the reference resolves the errors"
                                : "the reference's own error is too large to measure the smallest error");
       }},
      {"bounce_spread",
       [](const Record& in) {
         if (in.has_number("failed_runs") && in.number("failed_runs") > 0) return std::string("not decided: runs failed");
         // Clipped captures: the nominal throw at the corners of the speed and height intervals must make
         // a count inside the members' range too (records written before the corners have none).
         if (in.has_number("corner_failed") && in.number("corner_failed") > 0) return std::string("not decided: runs failed");
         if (in.has_number("corner_bounces_least") &&
             (in.number("corner_bounces_least") < in.number("bounces_low") || in.number("corner_bounces_most") > in.number("bounces_high")))
           return std::string("not decided by the capture");
         return std::string(in.number("bounces_low") == in.number("bounces_high") ? "decided by the capture"
                                                                                 : "not decided by the capture");
       }},
      {"ensemble_bounce_agreement",
       [](const Record& in) {
         // Two solvers' bounce counts on ensembles: the 95 % interval of the difference of the means.
         if (!in.flag("valid")) return std::string("not measured");
         // A failed run has no count, and the runs that fail are not a random sample of the
         // ensemble (a run that blows up or collapses its steps is the one whose contacts went
         // wrong): the survivors' means would be a selected subset's, so nothing is decided on them.
         // (Records written before the failures were inputs have no such key: judged as before.)
         const auto failed = [&](const char* k) { return in.has_number(k) && in.number(k) > 0; };
         if (failed("realtime_failed") || failed("reference_failed")) return std::string("not decided: runs failed");
         if (difference_established(in)) return std::string("different bounce counts");
         return std::string(difference_seen(in) ? "no difference established" : "same bounce count");
       }},
      {"ensemble_count_difference",
       [](const Record& in) {
         // Two settings of one throw (two meshes; a throw and its mirror image) on ensembles: the
         // 95 % interval of the difference of the mean counts; nothing is decided on an ensemble
         // with a failed run (see ensemble_bounce_agreement).
         if (!in.flag("valid")) return std::string("not measured");
         if (in.number("failed_runs") > 0) return std::string("not decided: runs failed");
         if (difference_established(in)) return std::string("different bounce counts");
         return std::string(difference_seen(in) ? "no difference established" : "same bounce count");
       }},
      {"coupling_change",
       [](const Record& in) {
         // Bounce counts on ensembles: the 95 % interval of the difference of the means; nothing is
         // decided on an ensemble with a failed run (see ensemble_bounce_agreement).
         if (in.has_number("failed_runs") && in.number("failed_runs") > 0) return std::string("not decided: runs failed");
         if (difference_established(in)) return std::string("changes the bounce count");
         if (difference_seen(in)) return std::string("no difference established");
         // Counts that did not depend on the perturbation and agree: the first contact decides.
         return std::string(in.number("max_time_change_s") > in.number("time_tolerance_s") ? "moves the contacts"
                                                                                           : "no visible change");
       }},
      {"coupled_limit",
       [](const Record& in) {
         const double tol = in.number("growth_tolerance");
         const bool ok = in.number("growth_below") <= 1 + tol && in.number("growth_above") > 1 + tol &&
                         in.number("growth_free_above") <= 1 + tol;
         return std::string(ok ? "stable below the limit, unstable above it" : "the limit is not confirmed");
       }},
      {"ring_speed",
       [](const Record& in) {
         if (!in.flag("valid")) return std::string("not measured");
         if (in.number("speed_low") > in.number("predicted_high")) return std::string("faster than c");
         if (in.number("speed_high") < in.number("predicted_low")) return std::string("slower than the scheme's dispersion explains");
         return std::string("within c less the scheme's dispersion");
       }},
      {"shortcut",
       [](const Record& in) {
         if (in.number("field_relative") == 0 && in.number("start_change_s") == 0 && in.number("count_change") == 0)
           return std::string("exact");
         const bool within = in.number("field_relative") <= in.number("field_tolerance") &&
                             in.number("start_change_s") <= in.number("time_tolerance_s") && in.number("count_change") == 0;
         return std::string(within ? "within tolerance" : "beyond tolerance");
       }},
      {"speed_target",
       [](const Record& in) {
         return std::string(in.number("value") >= in.number("target") ? "meets the target" : "misses the target");
       }},
  };
  return r;
}

void collect(const Record& r, std::vector<std::string>& out) {
  if (r.has_text("rule") && r.has_text("verdict")) {
    const std::string now = decide(r.text("rule"), r);
    if (now != r.text("verdict")) out.push_back(r.path() + ": stored '" + r.text("verdict") + "', rule says '" + now + "'");
  }
  for (const auto& c : r.child_names()) collect(r.at(c), out);
}

}  // namespace

CaptureConditions capture_conditions(const Record& in) {
  CaptureConditions c;
  auto unusable = [&](bool holds, const char* name) {
    if (holds) c.unusable.emplace_back(name);
  };
  auto caveat = [&](bool holds, const char* name) {
    if (holds) c.caveats.emplace_back(name);
  };
  const bool computed = in.flag("throw_computed");
  const double calibration = in.number("calibration_error_g");
  unusable(!in.flag("has_gyro"), "no_gyro");
  unusable(in.number("samples") < in.number("min_samples"), "too_few_samples");
  unusable(!in.flag("rate_found"), "no_rate");
  unusable(in.flag("rate_found") && in.number("rate_hz") < in.number("min_rate_hz"), "rate_too_low");
  unusable(in.number("samples") >= 2 && !in.flag("press_found"), "no_press");
  unusable(in.flag("release_found") && in.number("release_gap_s") > in.number("max_release_gap_s"), "release_in_gap");
  unusable(in.flag("release_found") && !in.flag("still_found"), "no_still_part");
  if (in.has_number("gyro_held_in_swing"))  // records stored before this input existed lack it
    unusable(in.flag("still_found") && in.number("gyro_held_in_swing") > 0, "gyro_held_in_swing");
  if (in.has_number("min_swing_rate_deg_s"))  // records stored before this input existed lack it
    unusable(in.flag("has_gyro") && in.flag("still_found") &&
                 in.number("swing_peak_rate_deg_s") < in.number("min_swing_rate_deg_s"),
             "gyro_still");
  unusable(computed && !in.flag("throw_finite"), "state_not_finite");
  unusable(computed && calibration > in.number("calibration_unusable_g"), "calibration_wrong");
  // Plausibility against a human throw (records stored before these inputs existed lack them).
  if (in.has_number("max_release_speed_m_s"))
    unusable(computed && in.flag("throw_finite") &&
                 (in.number("release_speed_m_s") > in.number("max_release_speed_m_s") ||
                  in.number("release_speed_m_s") < in.number("min_release_speed_m_s")),
             "release_speed_implausible");
  if (in.has_number("max_hand_displacement_m"))
    unusable(computed && in.flag("throw_finite") && in.number("hand_displacement_m") > in.number("max_hand_displacement_m"),
             "hand_displacement_implausible");
  caveat(in.flag("release_at_end") && in.flag("has_buttons"), "button_held_at_end");
  if (in.has_number("max_release_speed_m_s"))  // stored with the plausibility inputs
    caveat(in.flag("release_at_end") && !in.flag("has_buttons"), "no_release_signal");
  caveat(in.flag("clipped_in_swing"), "clipped_in_swing");
  caveat(in.flag("gyro_saturated_in_swing"), "gyro_saturated");
  caveat(in.flag("stamps_given") && in.number("lost_fraction") > in.number("lost_fraction_caveat"), "reports_lost");
  caveat(in.flag("stamps_given") && in.number("jitter_s") > in.number("jitter_caveat_s"), "jitter");
  caveat(computed && calibration > in.number("calibration_caveat_g") && calibration <= in.number("calibration_unusable_g"),
         "calibration_off");
  caveat(in.flag("nominal_timestamps"), "no_timestamps");
  caveat(in.number("inferred_range_switches") > 0, "range_switches_inferred");
  caveat(!in.flag("device_calibration"), "nominal_calibration");
  caveat(computed && in.flag("throw_finite") && !in.flag("clipped_in_swing") && in.number("lever_speed_m_s") > 0 &&
             std::abs(in.number("speed_difference_m_s")) >
                 in.number("accel_lever_disagreement") * in.number("measured_speed_m_s"),
         "accel_lever_disagree");
  caveat(in.number("reader_warnings") > 0, "reader_warnings");
  if (in.has_number("max_tilt_deg"))  // records stored before this input existed lack it
    caveat(computed && in.flag("throw_finite") && in.number("release_tilt_deg") > in.number("max_tilt_deg"),
           "attitude_implausible");
  return c;
}

std::string decide(const std::string& rule, const Record& inputs) {
  const auto it = rules().find(rule);
  if (it == rules().end()) throw RecordError(inputs.path() + ": unknown verdict rule '" + rule + "'");
  return it->second(inputs);
}

Record& decide_verdict(Record& parent, const std::string& key, const std::string& rule, const Record& inputs,
                       const std::string& reason) {
  Record& v = parent.child(key);
  for (const auto& [k, x] : inputs.numbers()) v.set(k, x);
  v.set("rule", rule);
  v.set("verdict", decide(rule, v));
  v.set("reason", reason);
  return v;
}

std::vector<std::string> contradicted_verdicts(const Record& r) {
  std::vector<std::string> out;
  collect(r, out);
  return out;
}

}  // namespace stoneskip
