// Section 6 of the stones report (issue 11, item 4): which water law skips like a real stone — the
// laws ranked by their distance from the measurements and by their cost per throw, and the
// cheapest that skips like a real stone, if any. Formatted from the validation section's stored
// "ranking" record: the metric, every distance, the verdicts and their reasons were computed there.
#include <cmath>

#include "reports/common/markdown.hpp"
#include "reports/common/plot.hpp"
#include "reports/stones/report_sections.hpp"

namespace stoneskip {

namespace {

std::string range_text(const Record& measured_row) {
  const double lo = measured_row.number("score_low"), hi = measured_row.number("score_high");
  const std::string unit = measured_row.text("score_unit").empty() ? "" : " " + measured_row.text("score_unit");
  return (lo == hi ? fmt(lo, 3) : "[" + fmt(lo, 3) + ", " + fmt(hi, 3) + "]") + unit;
}

}  // namespace

SectionOutput ranking_section(const Record& v) {
  const Record& r = v.at("ranking");
  const Record& measured = v.at("measured");
  SectionWriter w(r, "6. Which water law skips like a real stone?");
  const auto& scored = r.strings("scored");
  std::string quantities;
  for (const auto& key : scored)
    quantities += (quantities.empty() ? "" : "; ") + measured.at(key).text("quantity") + " (`" + key + "`, scored as " +
                  range_text(measured.at(key)) + ")";
  w.lead("The metric.",
         "For each law (CVODE reference, physical convention, its published C_w) and each measured quantity with a "
         "stated range [low, high]: the distance is 0 inside the range and otherwise |ln(model / nearer end)|, the "
         "factor to the range as a logarithm, so that a factor of 2 too high and too low are equally far. It is capped "
         "at " + fmt(r.number("miss_distance"), 3) + " (a factor of " + fmt(std::exp(r.number("miss_distance")), 3) +
             "), and a quantity the model cannot produce — it does not bounce where the measured stone bounces, its "
             "first contact never ends in a take-off, a fit has fewer than 3 points — gets that worst score. A law's "
             "distance is the mean over the quantities scored: " + quantities +
             ". Bocquet's counts and trends are predictions of his model, not measurements, and the seed's claims are "
             "those of a simulation: both are shown in section 5 but not scored.");
  w.lead("Skips like a real stone",
         "means a mean distance of at most " + fmt(r.number("distance_bound"), 3) + " (a factor of " +
             fmt(std::exp(r.number("distance_bound")), 3) + " on average) and an attitude held through the first contact "
             "at " + fmt(r.number("held_spin_rev_s"), 3) + " rev/s (α = " + fmt(r.number("regime_attack_deg"), 3) +
             "°), where Clanet et al. see it held: the attack angle may change by at most " +
             fmt(r.number("attack_bound_deg"), 3) + "°. The cost of a throw is the " + r.text("clock") + " (" +
             fmt(r.number("cost_repeats")) + " repeats), averaged over the throws listed below; it includes how long "
             "the throw lasts (a planing run of seconds costs more than an early sinking), so the cost per real-time "
             "step and per CVODE right-hand side is shown too: that is the law's own.");
  w.verdict("The answer", r.at("answer"));
  w.end_list();

  std::vector<std::string> head{"rank", "law", "mean distance"};
  for (const auto& key : scored) head.push_back(key + ": model (distance)");
  head.insert(head.end(), {"attack change at " + fmt(r.number("held_spin_rev_s"), 3) + " rev/s (deg)",
                           "reference CPU per throw (ms)", "real-time CPU per throw (ms)", "real-time CPU per step (µs)",
                           "reference CPU per RHS (µs)", "verdict"});
  MarkdownTable t(head);
  int rank = 0;
  for (const auto& law : r.strings("by_distance")) {
    const Record& L = r.at(law);
    const Table& q = L.table("quantities");
    std::vector<std::string> cells{fmt(++rank), code(law), fmt(L.number("distance"), 3)};
    for (std::size_t i = 0; i < scored.size(); ++i) {
      const bool has = q.column("has_value")[i] != 0;
      cells.push_back((has ? (q.column("bound_only")[i] != 0 ? "beyond " : "") + fmt(q.column("model")[i], 3) : "none") +
                      " (" + fmt(q.column("distance")[i], 3) + ")");
    }
    cells.push_back(fmt(L.number("attack_change_deg"), 3));
    cells.push_back(fmt(1000 * L.number("reference_cpu_s"), 3));
    cells.push_back(fmt(1000 * L.number("realtime_cpu_s"), 3));
    cells.push_back(fmt(1e6 * L.number("realtime_cpu_per_step_s"), 3));
    cells.push_back(fmt(1e6 * L.number("reference_cpu_per_rhs_s"), 3));
    cells.push_back(L.at("skips").text("verdict"));
    t.row(cells);
  }
  w.table(t);
  std::string by_cost;
  for (const auto& law : r.strings("by_cost"))
    by_cost += (by_cost.empty() ? "" : " < ") + code(law) + " (" + fmt(1000 * r.at(law).number("realtime_cpu_s"), 3) + " ms)";
  w.text("By real-time cost per throw: " + by_cost + ".");
  for (const auto& law : r.strings("laws")) {
    const Record& L = r.at(law);
    w.verdict(code(law), L.at("skips"));
    const auto& notes = L.strings("notes");
    for (std::size_t i = 0; i < notes.size(); ++i)
      if (!notes[i].empty()) w.bullet(code(law) + ", " + scored.at(i) + ": " + notes[i] + ".");
  }
  w.end_list();

  // The cost of each law per throw.
  MarkdownTable c({"law", "throw", "reference CPU (ms)", "reference RHS evaluations", "real-time CPU (ms)", "real-time steps"});
  for (const auto& law : r.strings("laws")) {
    const Record& L = r.at(law);
    const Table& ct = L.table("cost");
    const auto& names = L.strings("cost_throws");
    for (std::size_t i = 0; i < ct.rows(); ++i)
      c.row({code(law), names.at(i), fmt(1000 * ct.column("reference_cpu_s")[i], 3),
             fmt(ct.column("reference_rhs_evaluations")[i], 8), fmt(1000 * ct.column("realtime_cpu_s")[i], 3),
             fmt(ct.column("realtime_steps")[i], 8)});
  }
  w.table(c);

  // Pitch stability: the attack angle through the held regime, each law.
  {
    const Record& vars = v.at("variants");
    const std::string& regime = r.text("held_regime");
    std::vector<PlotSeries> ps;
    for (const auto& law : r.strings("laws")) {
      const Record& g = vars.at(law + "_reference");
      if (!g.has_child(regime)) continue;
      const Record& h = g.at(regime);
      ps.push_back(attack_angle_series(h, law + " (" + fmt(h.number("bounces")) + " bounces)", "lines"));
    }
    PlotAxes ax;
    ax.x_label = "time (s)";
    ax.y_label = "attack angle (deg)";
    Figure f = line_figure("ranking_held_attitude",
                           "Attack angle at " + fmt(r.number("held_spin_rev_s"), 3) + " rev/s, α = " +
                               fmt(r.number("regime_attack_deg"), 3) + "°, each law (Clanet et al.: held)",
                           ax, ps, "t_s", "attack_deg");
    f.data_path = vars.path();
    w.figure(f);
  }
  w.lead("How to read it.",
         "The distance says how far a law's disk is from Clanet's and Rosellini's disk where both can be measured; the "
         "attitude criterion says whether it keeps flying like their spinning disk. A law can be near in the numbers "
         "and still fail the attitude: the lift of every law here acts on the wetted trailing part of the stone, behind "
         "the centre of mass, so its torque pitches the stone unless the spin's gyroscopic stiffness holds it. No "
         "coefficient was tuned here; whether another coefficient, or a contact model with a cavity, added mass or the "
         "splash, would hold the attitude is not studied.");
  return w.finish();
}

}  // namespace stoneskip
