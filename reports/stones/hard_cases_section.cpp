// Section 4 of the stones report: throws chosen to break a solver, and the largest stable step —
// formatted from the stored record.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include "reports/common/markdown.hpp"
#include "reports/common/plot.hpp"
#include "reports/stones/report_sections.hpp"

namespace stoneskip {

namespace {

std::string code_list(const std::vector<std::string>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + code(v[i]);
  return v.empty() ? std::string("none") : s;
}

}  // namespace

SectionOutput hard_cases_section(const Record& c) {
  SectionWriter w(c, "4. Hard cases");
  const auto steps = c.table("single_steps_s").column("dt_s");
  w.lead("What is measured.",
         "Throws chosen to break a solver (`cases/hard/`). Each is solved by CVODE (rtol " + fmt(c.number("reference_rtol"), 2) +
             ") and by the real-time stepper, first with the case's own settings (the adaptive `bs32` at the default "
             "tolerance unless the case names a scheme) and then with `" + c.text("single_step_scheme") +
             "` at one fixed step h for flight and contact alike, growing from " + (steps.empty() ? std::string("–") : fmt(steps.front(), 2)) + " s to " +
             (steps.empty() ? std::string("–") : fmt(steps.back(), 2)) +
             " s. For each run: does the state stay finite; does the stepper miss a contact the reference has (it stepped "
             "over it: tunnelling) or report one the reference does not have; is the bounce count the same; and does the "
             "stone gain energy over a contact (more than " + fmt(c.number("energy_tolerance_fraction"), 2) +
             " of its release kinetic energy). In the `physical` convention the water and the air can only take energy "
             "out (model/README.md §1.6), so a gain there is a numerical artefact; in the `paper` convention the model itself can "
             "create energy.");
  MarkdownTable summary({"case", "reference (CVODE)", "real-time, case settings", "real-time, largest single step that is ok",
                         "first thing to go wrong as h grows"});
  for (const auto& key : c.strings("cases")) {
    const Record& h = c.at(key);
    const double ok = h.number("largest_ok_single_step_s");
    summary.row({h.text("title") + " (" + code(h.text("file")) + ")", h.text("reference_verdict"), h.strings("verdicts").front(),
                 ok > 0 ? fmt(ok, 3) + " s" : "none of the steps tried", h.text("first_departure")});
  }
  w.table(summary);
  w.lead("What it finds.", "The reference fails on " + code_list(c.strings("reference_failed")) +
                               "; the real-time stepper with the case's own settings departs from the reference on " +
                               code_list(c.strings("case_settings_depart")) +
                               "; in the physical convention the stepper creates energy over a contact on " +
                               code_list(c.strings("energy_created_physical")) +
                               ". The first departure from the reference as the single step grows, over all cases:");
  {
    const Table& f = c.table("first_departure_counts");
    const auto& names = c.strings("departure_names");
    for (std::size_t i = 0; i < f.rows(); ++i)
      if (f.column("cases")[i] > 0)
        w.bullet(names.at(static_cast<std::size_t>(f.column("departure")[i])) + ": " + fmt(f.column("cases")[i]) + " case(s)");
    w.end_list();
  }
  w.text("Every run, with what went wrong:");
  for (const auto& key : c.strings("cases")) {
    const Record& h = c.at(key);
    w.text("**" + h.text("title") + "** (" + code(h.text("file")) + ", " + h.text("convention") + " convention; reference: " +
           h.text("reference_verdict") + ")");
    MarkdownTable t({"real-time setting", "bounces", "contacts", "max energy gain (J)", "CPU (s)", "verdict"});
    const Table& runs = h.table("runs");
    const auto& settings = h.strings("settings");
    const auto& verdicts = h.strings("verdicts");
    for (std::size_t i = 0; i < runs.rows(); ++i) {
      auto col = [&](const char* k) { return runs.column(k)[i]; };
      t.row({settings[i], col("finite") != 0 ? fmt(col("bounces")) : "–", fmt(col("contacts")), fmt(col("max_energy_gain_J"), 3),
             fmt(col("cpu_s"), 3), verdicts[i]});
    }
    w.table(t);
  }

  const Record& s = c.at("largest_stable_step");
  w.subheading("Largest stable step against throw speed");
  const auto hs = s.has_table("steps_s") ? s.table("steps_s").column("dt_s") : std::vector<double>{};
  w.text("One fixed step h (flight = contact) of " + s.text("scheme") + ", h = " +
         (hs.empty() ? std::string("–") : fmt(hs.front(), 2) + " … " + fmt(hs.back(), 2)) +
         " s; for each speed the largest h such that every smaller h tried is also (a) finite (the run neither "
         "became NaN nor, in the physical convention, ran away past 10³ × (its release energy + 1 J), where the "
         "stepper stops it), (b) finite and without energy gain, (c) all that and with the reference's contact and "
         "bounce count.");
  MarkdownTable mt({"speed (m/s)", "reference bounces / contacts", "(a) finite up to h (s)", "(b) no energy gain up to h (s)",
                    "(c) same contacts up to h (s)"});
  const Table& rows = s.table("rows");
  // A criterion met by every step tried has its limit beyond the largest: "≥", not a limit.
  const double largest_tried = hs.empty() ? 0 : hs.back();
  auto h_text = [&](double v) {
    if (!(v > 0)) return std::string("< smallest");
    return largest_tried > 0 && v >= largest_tried ? "≥ " + fmt(v, 3) + " (all tried)" : fmt(v, 3);
  };
  for (std::size_t i = 0; i < rows.rows(); ++i) {
    auto col = [&](const char* k) { return rows.column(k)[i]; };
    mt.row({fmt(col("speed_m_s"), 3), fmt(col("reference_bounces")) + " / " + fmt(col("reference_contacts")),
            h_text(col("largest_finite_s")), h_text(col("largest_no_energy_gain_s")), h_text(col("largest_same_contacts_s"))});
  }
  w.table(mt);
  // Where no step tried keeps the reference's contacts, (a) and (b) judge runs that miss contacts.
  std::vector<std::string> missing;
  for (std::size_t i = 0; i < rows.rows(); ++i)
    if (!(rows.column("largest_same_contacts_s")[i] > 0) && rows.column("largest_no_energy_gain_s")[i] > 0)
      missing.push_back(fmt(rows.column("speed_m_s")[i], 3) + " m/s");
  std::string note;
  if (largest_tried > 0)
    note = "A point at " + fmt(largest_tried, 3) + " s (\"≥ … (all tried)\" in the table) is the largest step tried: every "
           "step tried met that criterion, and its limit lies beyond.";
  const std::string speeds = and_list(missing);
  if (!missing.empty())
    note += std::string(note.empty() ? "" : " ") + "At " + speeds +
            " not even the smallest step tried makes the reference's contacts, so there (a) and (b) judge runs that "
            "miss contacts, not the stepper on the throw.";
  if (!note.empty()) w.text(note);
  {
    // A step that was never stable is stored as 0 (or less): not drawn on the log axis.
    using Rows = TableSource::Rows;
    const PlotSeries a = table_series("(a) finite", s, "rows", "speed_m_s", "largest_finite_s", "linespoints", Rows::y_positive);
    const PlotSeries b = table_series("(b) no energy gain", s, "rows", "speed_m_s", "largest_no_energy_gain_s", "linespoints", Rows::y_positive);
    const PlotSeries d =
        table_series("(c) same contacts as the reference", s, "rows", "speed_m_s", "largest_same_contacts_s", "linespoints", Rows::y_positive);
    std::vector<PlotSeries> series{a, b, d};
    // A speed at which even the smallest step tried fails a criterion ("< smallest" in the table):
    // a marker at the smallest step, so that the figure shows it too.
    if (!hs.empty()) {
      const std::pair<const char*, const char*> criteria[] = {{"largest_finite_s", "(a)"},
                                                              {"largest_no_energy_gain_s", "(b)"},
                                                              {"largest_same_contacts_s", "(c)"}};
      for (const auto& [column, label] : criteria) {
        const auto v = rows.column(column);
        if (std::none_of(v.begin(), v.end(), [](double h) { return h <= 0; })) continue;
        series.push_back(table_series(std::string(label) + " not met even at the smallest step tried", s, "rows", "speed_m_s",
                                      column, "points pt 11 ps 2", Rows::y_nonpositive, hs.front()));
      }
    }
    PlotAxes ax;
    ax.x_label = "throw speed (m/s)";
    ax.y_label = "largest step h (s)";
    ax.log_x = ax.log_y = true;
    Figure f = line_figure("largest_stable_step", "Largest stable single step of the real-time stepper against throw speed",
                           ax, series, "speed_m_s", "h_s");
    f.data_path = s.path();
    w.figure(f);
  }
  return w.finish();
}

}  // namespace stoneskip
