#include "verification/scene/scene_step_findings.hpp"

#include <algorithm>
#include <cmath>

#include "verification/convergence/order_fit.hpp"
#include "verification/scene/scene_findings_support.hpp"
#include "verification/study/verdict_rules.hpp"
#include "verification/study/words.hpp"

namespace stoneskip::scene_findings {

namespace {

// Each a column of the step tables; its error's column is error_<key>, its local order's local_order_<key>.
constexpr SectionQuantity kStepQuantities[] = {{"first_start_s", "the first touch", 1e6, "µs"},
                                            {"first_duration_s", "the first contact's duration", 1e6, "µs"},
                                            {"first_exit_m_s", "the first contact's exit speed", 1, "m/s"}};

Table step_table() {
  // error_*: |value − the reference's|; local_order_*: log(e_{i−1}/e_i)/log(Δt_{i−1}/Δt_i) against
  // the row before (NaN on the first row, or where an error is 0).
  Table t = table({"reading", "step_fraction", "water_dt_s", "first_start_s", "first_duration_s", "first_exit_m_s", "contacts",
                   "error_first_start_s", "error_first_duration_s", "error_first_exit_m_s", "local_order_first_start_s",
                   "local_order_first_duration_s", "local_order_first_exit_m_s", "wall_s"});
  t.units = {"1", "1", "s", "s", "s", "m/s", "1", "s", "s", "m/s", "1", "1", "1", "s"};
  return t;
}

}  // namespace

void water_step_study(const SceneOptions& base, const SceneStudyCase& c, const ContactRecord& touch, double end_s,
                      const SceneGridOptions& g, const ProgressFactory& progress, Record& out) {
  out.set("reference_step_fraction", g.reference_step_fraction);
  const double cell = base.water->field.cell_m, dt = base.water->field.dt_s;
  // One run: the first contact's start, duration and exit speed, and the contacts until end_s.
  auto run = [&](LevelInTime reading, double fraction) {
    SceneOptions s = base;
    s.duration_s = end_s;
    s.level_in_time = reading;
    place_on_pond(s, c, touch.first_touch_m, g.pond_m, cell, dt * fraction);
    const SceneSummary r = run_scene(s);
    const ContactRecord* first = r.stone.contacts.empty() ? nullptr : &r.stone.contacts.front();
    return std::vector<double>{double(reading == LevelInTime::extrapolated), fraction, dt * fraction,
                               first ? first->start_s : kNaN, first ? first->duration_s() : kNaN, first ? first->exit_speed_m_s : kNaN,
                               double(r.stone.contacts.size()), kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, r.wall_s};
  };
  auto ticker = start_progress(progress, "scene: water steps", 2 * g.step_fractions.size() + 2);
  Table reference = step_table();
  for (LevelInTime reading : {LevelInTime::extrapolated, LevelInTime::held}) {
    reference.add_row(run(reading, g.reference_step_fraction));
    ticker->tick();
  }
  const auto ref_of = [&](const char* key, std::size_t row) { return reference.column(key)[row]; };
  Record in;
  double closer = 0, farther = 0, unresolved = 0, missing = 0, finest_closer = 0, finest_farther = 0;
  std::vector<std::string> resolved_words;
  std::vector<Table> tables;
  for (LevelInTime reading : {LevelInTime::held, LevelInTime::extrapolated}) {
    Table t = step_table();
    std::vector<double> before;
    for (double f : g.step_fractions) {
      std::vector<double> row = run(reading, f);
      for (std::size_t q = 0; q < 3; ++q) {
        row[7 + q] = std::abs(row[3 + q] - ref_of(kStepQuantities[q].key, 0));
        if (!before.empty() && before[7 + q] > 0 && row[7 + q] > 0)
          row[10 + q] = std::log(before[7 + q] / row[7 + q]) / std::log(before[2] / row[2]);
      }
      t.add_row(row);
      before = row;
      ticker->tick();
    }
    tables.push_back(t);
  }
  // Each quantity: the two readings' errors step by step. The reference's own error is unknown;
  // the gap between its two readings stands for it (the held one's first-order error dominates
  // it), so a comparison is resolved only where the two errors differ by more than twice the gap.
  for (std::size_t q = 0; q < 3; ++q) {
    const SectionQuantity& sq = kStepQuantities[q];
    const std::string err = std::string("error_") + sq.key;
    const double gap = std::abs(ref_of(sq.key, 0) - ref_of(sq.key, 1));
    in.set(std::string("reference_gap_") + sq.key, gap);
    const auto held = tables[0].column(err), ex = tables[1].column(err);
    int q_closer = 0, q_farther = 0, q_unresolved = 0;
    std::vector<std::string> held_wins;
    const auto dts = tables[0].column("water_dt_s");
    for (std::size_t i = 0; i < held.size(); ++i) {
      const double h = std::abs(held[i]), e = std::abs(ex[i]);
      if (!std::isfinite(h) || !std::isfinite(e)) {
        ++missing;
        continue;
      }
      const bool finest = i + 1 == held.size();
      if (std::abs(h - e) <= 2 * gap) {
        ++q_unresolved;
      } else if (e < h) {
        ++q_closer;
        finest_closer += finest;
      } else {
        ++q_farther;
        finest_farther += finest;
        held_wins.push_back(num(1e3 * dts[i], 3) + " ms");
      }
    }
    closer += q_closer;
    farther += q_farther;
    unresolved += q_unresolved;
    const bool same_everywhere = gap == 0 && std::all_of(held.begin(), held.end(), [](double e) { return e == 0; }) &&
                                 std::all_of(ex.begin(), ex.end(), [](double e) { return e == 0; });
    if (same_everywhere) {  // e.g. the first touch on water that is still until the stone reaches it
      resolved_words.push_back(std::string(sq.words) + ": the same in every run, the reference's included");
      continue;  // no order to fit
    }
    resolved_words.push_back(std::string(sq.words) + ": extrapolated closer at " + std::to_string(q_closer) + ", held at " +
                             std::to_string(q_farther) + ", within the reference's gap (" + num(sq.scale * gap, 2) + " " + sq.unit +
                             ") at " + std::to_string(q_unresolved) +
                             (held_wins.empty() ? std::string() : " (held closer at steps of " + joined(held_wins, ", ") + ")"));
    // The observed order of each reading's error against the step (95 % interval), from the
    // errors the reference resolves (above its gap).
    for (std::size_t k = 0; k < 2; ++k) {
      std::vector<double> h_used, e_used;
      const auto col = tables[k].column(err), steps = tables[k].column("water_dt_s");
      for (std::size_t i = 0; i < col.size(); ++i)
        if (std::isfinite(col[i]) && std::abs(col[i]) > 2 * gap) {
          h_used.push_back(steps[i]);
          e_used.push_back(std::abs(col[i]));
        }
      const OrderFit fit = fit_order(h_used, e_used);
      const std::string prefix = std::string(k == 0 ? "held" : "extrapolated") + ".";
      out.set(prefix + "order_" + sq.key, fit.valid ? fit.order : kNaN);
      out.set(prefix + "order_low_" + sq.key, fit.valid ? fit.order_low : kNaN);
      out.set(prefix + "order_high_" + sq.key, fit.valid ? fit.order_high : kNaN);
      out.set(prefix + "order_points_" + sq.key, double(fit.valid ? fit.points : 0));
    }
  }
  out.set_table("reference", reference);
  out.set_table("held", tables[0]);
  out.set_table("extrapolated", tables[1]);
  in.set("closer", closer).set("farther", farther).set("unresolved", unresolved).set("missing", missing);
  in.set("finest_closer", finest_closer).set("finest_farther", finest_farther);
  // The contacts up to the runs' end against the reference's (a rebounding surface can touch a
  // leaving stone again: a bounce, model/README.md §1.8).
  for (std::size_t k = 0; k < 2; ++k) {
    double same = 0;
    for (double n : tables[k].column("contacts")) same += n == ref_of("contacts", 0);
    out.set(std::string(k == 0 ? "held" : "extrapolated") + ".contacts_as_reference", same);
  }
  std::string reason = joined(resolved_words, "; ");
  if (missing > 0) reason = std::to_string(int(missing)) + " comparison(s) with a run that made no contact; " + reason;
  decide_verdict(out, "verdict", "level_in_time", in, reason);
}

}  // namespace stoneskip::scene_findings
