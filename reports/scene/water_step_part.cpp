#include "reports/scene/water_step_part.hpp"

#include <cmath>
#include <string>

#include "reports/common/markdown.hpp"
#include "reports/common/plot.hpp"

namespace stoneskip {

namespace {

struct Quantity {
  const char* key;    // the stored column; its error is error_<key>
  const char* words;  // as the page names it
  double scale;       // to the unit its figure's axis is in
};
constexpr Quantity kQuantities[] = {{"first_start_s", "first touch", 1e3}, {"first_duration_s", "first contact", 1e3}, {"first_exit_m_s", "exit speed", 1}};

// "p = 1.9 [1.2, 2.6] (4 points)", or why there is none.
std::string order_words(const Record& ws, const std::string& reading, const char* key) {
  const std::string k = reading + ".order_" + key;
  const double points = ws.number(reading + ".order_points_" + key);
  if (!(points >= 2) || std::isnan(ws.number(k))) return "no order: fewer than two errors above the reference's gap";
  std::string s = "p = " + fmt(ws.number(k), 2);
  if (points > 2) s += " [" + fmt(ws.number(reading + ".order_low_" + key), 2) + ", " + fmt(ws.number(reading + ".order_high_" + key), 2) + "]";
  return s + " (" + fmt(points) + " points)";
}

// One error against the water step, a line for each reading.
Figure error_figure(const Record& ws, const std::string& name, const std::string& title, const Quantity& q, const std::string& label) {
  const std::string err = std::string("error_") + q.key;
  TableSource how;
  how.x_column = "water_dt_s";
  how.y_column = err;
  how.rows = TableSource::Rows::y_positive;  // an error of 0 is a gap on the log axis
  how.y_scale = q.scale;
  std::vector<PlotSeries> series{table_series("held over each step", ws, "held", how, "linespoints pt 7"),
                                 table_series("extrapolated from the last two", ws, "extrapolated", how, "linespoints pt 5")};
  // Guides of slope 1 and 2 through each reading's error at the finest step (where it is > 0).
  for (int k = 0; k < 2; ++k) {
    const PlotSeries& s = series[static_cast<std::size_t>(k)];
    if (s.x.empty() || !(s.y.back() > 0)) continue;
    std::vector<double> xs;
    for (double x : s.x)
      if (std::isfinite(x)) xs.push_back(x);
    series.push_back(power_law_guide(k == 0 ? "slope 1" : "slope 2", xs, s.x.back(), s.y.back(), k + 1,
                                     std::string("lines lc rgb '#888888' dt ") + (k == 0 ? "2" : "4")));
  }
  const PlotAxes ax{"water step (s)", label, true, true, "set key bottom right"};
  return line_figure(name, title, ax, series, "water_dt_s", err);
}

}  // namespace

void water_step_part(SectionWriter& w, const Record& ws) {
  const Table ref = ws.table("reference");
  const Table held = ws.table("held"), ex = ws.table("extrapolated");
  auto r = [&](const char* k, std::size_t row) { return ref.column(k)[row]; };
  w.text("**The level between water steps.** The stone steps on its own clock and the water on its own; between two water "
         "steps the stone reads the surface either *held* (the last level, until the next: the real-time loop's way, first order "
         "in the water step) or *extrapolated* (the line through the last two levels: second order, and causal). `level_in_time` "
         "in a scene's `[water]` chooses (model/README.md §2.4). Here the scene's first contact on its own cell, with the water "
         "step refined alone (the same pond as above), is run both ways against the same scene on a step " +
         fmt(1 / ws.number("reference_step_fraction"), 3) + " times finer, extrapolated (first touch " + fmt(1e3 * r("first_start_s", 0), 7) +
         " ms, first contact " + fmt(1e3 * r("first_duration_s", 0), 5) + " ms, exit speed " + fmt(r("first_exit_m_s", 0), 5) + " m/s, " +
         fmt(r("contacts", 0)) + " contact(s)); held there it gives " + fmt(1e3 * r("first_start_s", 1), 7) + " ms, " +
         fmt(1e3 * r("first_duration_s", 1), 5) + " ms, " + fmt(r("first_exit_m_s", 1), 5) + " m/s and " + fmt(r("contacts", 1)) +
         " contact(s). That gap stands for the reference's own error: a difference between the two readings' errors no larger "
         "than twice it is not counted for either.");
  // The first touch moves only where the water moves before the stone reaches it (still water
  // until the stone's first touch: the same in every run).
  bool touch_moves = false;
  for (const Table* t : {&held, &ex})
    for (double e : t->column("error_first_start_s")) touch_moves = touch_moves || e > 0;
  std::vector<std::string> head{"water step (ms)", "level"};
  if (touch_moves) head.insert(head.end(), {"first touch (ms)", "its error (µs)", "order"});
  head.insert(head.end(), {"first contact (ms)", "its error (µs)", "order", "exit speed (m/s)", "its error (m/s)", "order", "contacts",
                           "wall (s)"});
  MarkdownTable m(head);
  auto order = [](double p) { return std::isnan(p) ? std::string("–") : fmt(p, 2); };
  for (std::size_t i = 0; i < held.rows(); ++i)
    for (const Table* t : {&held, &ex}) {
      auto v = [&](const char* k) { return t->column(k)[i]; };
      std::vector<std::string> row{fmt(1e3 * v("water_dt_s"), 3), t == &held ? "held" : "extrapolated"};
      if (touch_moves)
        row.insert(row.end(), {fmt(1e3 * v("first_start_s"), 7), fmt(1e6 * v("error_first_start_s"), 2), order(v("local_order_first_start_s"))});
      row.insert(row.end(), {fmt(1e3 * v("first_duration_s"), 5), fmt(1e6 * v("error_first_duration_s"), 2),
                             order(v("local_order_first_duration_s")), fmt(v("first_exit_m_s"), 5), fmt(v("error_first_exit_m_s"), 2),
                             order(v("local_order_first_exit_m_s")), fmt(v("contacts")), fmt(v("wall_s"), 2)});
      m.row(row);
    }
  w.table(m);
  w.text("An \"order\" is the local one, log(e′/e)/log(Δt′/Δt) against the row of the same level one step coarser: about 1 for an "
         "error first order in the step, 2 for second order, once the step is fine enough for the leading term to dominate." +
         std::string(touch_moves ? "" : " The first touch is the same in every run, " + fmt(1e3 * r("first_start_s", 0), 7) +
                                            " ms: the water is still until the stone first reaches it, so no reading moves it.") +
         " Contacts as many as the reference's " + fmt(r("contacts", 0)) + ": held at " + fmt(ws.number("held.contacts_as_reference")) +
         " of " + fmt(double(held.rows())) + " steps, extrapolated at " + fmt(ws.number("extrapolated.contacts_as_reference")) + " (a surface "
         "rising under a leaving stone can touch it again: each such touch is a contact, model/README.md §1.8).");
  std::string orders;
  for (std::size_t q = touch_moves ? 0 : 1; q < 3; ++q)
    orders += std::string(orders.empty() ? "" : "; ") + kQuantities[q].words + ": held " + order_words(ws, "held", kQuantities[q].key) +
              ", extrapolated " + order_words(ws, "extrapolated", kQuantities[q].key);
  w.text("Observed orders over all the steps (least squares on log–log, 95 % interval; errors within twice the reference's gap left "
         "out): " + orders + ".");
  w.verdict("The level between water steps", ws.at("verdict"));
  w.end_list();
  if (touch_moves)
    w.figure(error_figure(ws, "water_step_first_touch", "The first touch's error against the water step, the level held or extrapolated",
                          kQuantities[0], "|first touch − reference| (ms)"));
  w.figure(error_figure(ws, "water_step_duration", "The first contact's duration error against the water step, the level held or extrapolated",
                        kQuantities[1], "|duration − reference| (ms)"));
  w.figure(error_figure(ws, "water_step_exit_speed", "The first contact's exit speed error against the water step, the level held or extrapolated",
                        kQuantities[2], "|exit speed − reference| (m/s)"));
}

}  // namespace stoneskip
