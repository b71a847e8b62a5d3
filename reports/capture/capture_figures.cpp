// The figures of a capture's section, formatted from its stored record (gnuplot scripts over tables
// taken from the record; nothing here computes a result).
#include "reports/capture/capture_figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>
#include <vector>
#include <sstream>
#include <tuple>

#include "reports/common/markdown.hpp"
#include "reports/common/plot.hpp"
#include "verification/study/stored_values.hpp"

namespace stoneskip {

namespace {

// Colours of the phases, the same in every figure.
constexpr const char* kStill = "#b9e4b9";
constexpr const char* kSwing = "#cfe0f5";
constexpr const char* kClipped = "#f4a6a6";
constexpr const char* kRelease = "#bdbdbd";
// Lines: the three axes, and the two solvers.
constexpr const char* kAxis[3] = {"#1f77b4", "#ff7f0e", "#2ca02c"};
constexpr const char* kRealtime = "#d62728";
constexpr const char* kReference = "#1f1f1f";
constexpr const char* kMember = "#9e9e9e";
// The release velocity is drawn as the distance it carries the stone in this time.
constexpr double kArrow_s = 0.05;
// Stacked panels with their keys outside on the right: the same plot area in every panel.
constexpr const char* kStacked = "set grid\nset key outside right top\nset lmargin at screen 0.08\nset rmargin at screen 0.72\n";

// A number for a gnuplot script, with every digit it needs; gnuplot's NaN where it is not finite
// (printf's `nan` and `inf` are undefined variables to gnuplot, and the figure failed): a
// constant NaN draws nothing.
std::string g(double x) {
  if (!std::isfinite(x)) return "NaN";
  char b[40];
  std::snprintf(b, sizeof b, "%.9g", x);
  return b;
}

// 1-based column of a table in a gnuplot `using` clause.
std::string col(const Table& t, const std::string& name) {
  const auto it = std::find(t.columns.begin(), t.columns.end(), name);
  return std::to_string(1 + (it - t.columns.begin()));
}

Figure make(const std::string& key, const std::string& name, const std::string& title, int w, int h) {
  Figure f;
  f.name = key + "_" + name;
  f.title = title;
  f.width_px = w;
  f.height_px = h;
  return f;
}

std::string dat(const Figure& f, const std::string& part) { return "'" + f.name + "_" + part + ".dat'"; }
void add(Figure& f, const std::string& part, Table t) { f.tables.emplace_back(f.name + "_" + part, std::move(t)); }
// A figure table that is the named columns of table `table` of r, every row (checked by the figure test).
void add_copy(Figure& f, const std::string& part, const Record& r, const std::string& table, const std::vector<std::string>& columns) {
  add_stored_table(f, f.name + "_" + part, r, table, columns);
}
// A figure table of stored estimates, a row each: its position, then the estimate's nominal, low
// and high values (the records' paths go to the figure's .sources).
void add_estimates(Figure& f, const std::string& part, const std::vector<std::pair<double, const Record*>>& rows) {
  Table t{{"position", "nominal", "low", "high"}, {}};
  TableCopy where;
  for (const auto& [x, v] : rows) {
    t.add_row({x, v->number("nominal"), v->number("low"), v->number("high")});
    where.estimates.push_back(v->path());
  }
  add(f, part, t);
  f.copies.emplace_back(f.name + "_" + part, where);
}

std::string rect(double t0, double t1, const char* colour, double opacity) {
  return "set object rect from " + g(t0) + ", graph 0 to " + g(t1) + ", graph 1 fc rgb '" + colour +
         "' fs transparent solid " + g(opacity) + " noborder behind\n";
}
std::string entry(const char* colour, double opacity, const std::string& title) {
  return "keyentry with boxes fc rgb '" + std::string(colour) + "' fs transparent solid " + g(opacity) + " noborder title " +
         gnuplot_quote(title);
}

// The phases as shaded spans (set before the plots, so every panel has them) and their legend
// entries (for one panel's plot command).
struct Phases {
  std::string objects, entries;
};
Phases phases(const Record& c) {
  const Record& m = c.at("motion");
  const Record& still = m.at("still");
  const Record& rel = m.at("release");
  const double period = c.at("timing").number("period_s");
  const double half = 0.5 * (period > 0 ? period : 0.01);
  Phases p;
  std::vector<std::string> entries;
  if (still.flag("found")) {
    p.objects += rect(still.number("t0_s"), still.number("t1_s"), kStill, 0.55);
    entries.push_back(entry(kStill, 0.55, "still part"));
    if (rel.flag("found")) {
      p.objects += rect(still.number("t1_s"), rel.number("t_s"), kSwing, 0.55);
      entries.push_back(entry(kSwing, 0.55, "swing"));
    }
  }
  const Table& spans = m.at("saturation").table("spans");
  for (std::size_t i = 0; i < spans.rows(); ++i)
    p.objects += rect(spans.column("t0_s")[i] - half, spans.column("t1_s")[i] + half, kClipped, 0.6);
  if (spans.rows() > 0) entries.push_back(entry(kClipped, 0.6, "accelerometer clipped"));
  if (rel.flag("found")) {
    p.objects += rect(rel.number("t_low_s"), rel.number("t_high_s"), kRelease, 0.7);
    p.objects += "set arrow from " + g(rel.number("t_s")) + ", graph 0 to " + g(rel.number("t_s")) +
                 ", graph 1 nohead lw 2 lc rgb '#000000' dt 2 front\n";
    entries.push_back(entry(kRelease, 0.7, "release interval (dashed: release)"));
  }
  for (const auto& e : entries) p.entries += ", " + e;
  return p;
}

std::string axis_plot(const Figure& f, const std::string& part, int first_column, const char* const names[3],
                      const std::string& style) {
  std::string s;
  for (int i = 0; i < 3; ++i)
    s += std::string(i ? ", " : "") + (i ? "''" : dat(f, part)) + " u 1:" + std::to_string(first_column + i) + " w " +
         style + " lc rgb '" + kAxis[i] + "' t '" + names[i] + "'";  // enhanced text: a_x is a subscript
  return s;
}

const char* const kAccelNames[3] = {"a_x", "a_y", "a_z"};
const char* const kRateNames[3] = {"pitch rate (about x)", "roll rate (about y)", "yaw rate (about z)"};

std::string rate_label(const Record& c) {
  return c.at("motion").flag("bias_removed") ? "angular rate, bias removed (deg/s)" : "angular rate as read (deg/s)";
}

// Thinning a long table for drawing: runs of k rows; of each, the rows that hold some column's
// least or largest value in the run, in order (at most 2 × columns a run): every peak and trough
// is drawn where it was. k is chosen so that at most about kMaxPlotRows rows are kept.
constexpr std::size_t kMaxPlotRows = 4000;
std::size_t extreme_run_length(std::size_t rows, std::size_t columns) {
  return std::max<std::size_t>(1, (rows * 2 * columns + kMaxPlotRows - 1) / kMaxPlotRows);
}
std::vector<std::size_t> extreme_rows(const std::vector<std::vector<double>>& columns, std::size_t k) {
  std::vector<std::size_t> out;
  const std::size_t n = columns.empty() ? 0 : columns[0].size();
  for (std::size_t a = 0; a < n; a += k) {
    const std::size_t b = std::min(n, a + k);
    std::vector<std::size_t> keep;
    for (const auto& v : columns) {
      keep.push_back(std::size_t(std::min_element(v.begin() + a, v.begin() + b) - v.begin()));
      keep.push_back(std::size_t(std::max_element(v.begin() + a, v.begin() + b) - v.begin()));
    }
    std::sort(keep.begin(), keep.end());
    keep.erase(std::unique(keep.begin(), keep.end()), keep.end());
    out.insert(out.end(), keep.begin(), keep.end());
  }
  return out;
}

// One table with the acceleration and the rate, for both motion figures: every stored sample,
// or for a long capture (more than kMaxPlotRows samples: a 10-minute one drew a 43 MB SVG) the
// samples thinned so that every extreme is kept; with a window, only the samples inside it.
void add_motion_table(Figure& f, const Record& c, std::optional<std::pair<double, double>> window = std::nullopt) {
  const std::vector<std::string> names{"t_s",      "ax_g",     "ay_g",           "az_g",           "wx_deg_s",
                                       "wy_deg_s", "wz_deg_s", "stone_speed_m_s", "lever_speed_m_s"};
  const Table& stored = c.at("motion").table("samples");
  const std::size_t n = stored.rows();
  if (!window && n <= kMaxPlotRows) {
    add_copy(f, "samples", c.at("motion"), "samples", names);
    return;
  }
  std::vector<std::vector<double>> col;
  for (const auto& name : names) col.push_back(stored.column(name));
  Table t{names, {}};
  auto row = [&](std::size_t k) {
    std::vector<double> r;
    for (const auto& v : col) r.push_back(v[k]);
    t.add_row(r);
  };
  if (window) {
    // The window's samples and one beyond each end, so the lines run to the plot's edges.
    const auto& t_s = col[0];
    for (std::size_t k = 0; k < n; ++k) {
      const bool inside = t_s[k] >= window->first && t_s[k] <= window->second;
      const bool just_before = t_s[k] < window->first && k + 1 < n && t_s[k + 1] >= window->first;
      const bool just_after = t_s[k] > window->second && k > 0 && t_s[k - 1] <= window->second;
      if (inside || just_before || just_after) row(k);
    }
    add_computed_table(f, f.name + "_samples", t,
                       "the stored samples (" + c.path() + "/motion/samples) from " + g(window->first) + " to " +
                           g(window->second) + " s, the plot's range, every one, and one beyond each end");
    return;
  }
  const std::size_t k = extreme_run_length(n, names.size() - 1);
  for (std::size_t i : extreme_rows(std::vector<std::vector<double>>(col.begin() + 1, col.end()), k)) row(i);
  add_computed_table(f, f.name + "_samples", t,
                     "the stored samples (" + c.path() + "/motion/samples), " + std::to_string(n) +
                         " of them, thinned for drawing: of each run of " + std::to_string(k) +
                         ", the samples holding a column's least or largest value in the run");
}

// The nominal throw's height against distance for each solver that ran, as plot clauses (each
// after ", "), and where each contact began when asked.
enum class ContactMarks { none, where_they_began };
std::string solver_paths(Figure& f, const Record& sim, ContactMarks contacts) {
  std::string s;
  for (const auto& [solver, colour, title] : {std::tuple{"realtime", kRealtime, "real-time model"},
                                              std::tuple{"reference", kReference, "reference (CVODE)"}}) {
    if (!sim.has_child(solver)) continue;
    const Record& r = sim.at(solver);
    add_copy(f, solver, r, "trajectory", {"x_m", "z_m"});
    s += ", " + dat(f, solver) + " u 1:2 w l " + (solver == std::string("realtime") ? "lw 3" : "lw 1.5 dt 2") +
         " lc rgb '" + colour + "' t " + gnuplot_quote(title);
    if (contacts == ContactMarks::none) continue;
    const std::string part = std::string(solver) + "_contacts";
    add_copy(f, part, r, "contact_list", {"x_m", "start_s"});
    s += ", " + dat(f, part) + " u 1:(0) w p pt 6 ps 1.2 lc rgb '" + colour + "' t " + gnuplot_quote(std::string("contacts, ") + title);
  }
  return s;
}

}  // namespace

Figure capture_motion_figure(const std::string& key, const Record& c) {
  Figure f = make(key, "motion",
                  "Acceleration and angular rate against time as recorded: the still part green, the swing blue, "
                  "clipped spans red, the release interval grey (dashed: the release)",
                  1100, 760);
  add_motion_table(f, c);
  if (c.at("motion").table("samples").rows() > kMaxPlotRows)
    f.title += " (a long capture, drawn from the samples that hold each run's extremes: every peak is drawn)";
  const Phases p = phases(c);
  const double sat = c.at("motion").at("saturation").number("saturation_g");
  std::ostringstream s;
  s << p.objects << "set multiplot layout 2,1\n" << kStacked
    << "set ylabel 'acceleration (g)'\n"
    << "plot " << axis_plot(f, "samples", 2, kAccelNames, "lp pt 7 ps 0.25 lw 1.2") << ", " << g(sat)
    << " w l dt 3 lc rgb '#aa0000' t 'clipping level', " << g(-sat) << " w l dt 3 lc rgb '#aa0000' notitle" << p.entries
    << "\nset xlabel 't (s)'\nset ylabel " << gnuplot_quote(rate_label(c)) << "\n"
    << "plot " << axis_plot(f, "samples", 5, kRateNames, "lp pt 7 ps 0.25 lw 1.2") << "\nunset multiplot\n";
  f.script = s.str();
  return f;
}

std::optional<Figure> capture_swing_figure(const std::string& key, const Record& c) {
  const Record& th = c.at("throw");
  if (!th.flag("computed")) return std::nullopt;
  const Record& still = c.at("motion").at("still");
  const Record& rel = c.at("motion").at("release");
  Figure f = make(key, "swing",
                  "The swing: acceleration, angular rate and the stone's speed from the end of the still part to just "
                  "after the release, with the release estimates and their intervals",
                  1100, 980);
  const double t0 = still.number("t1_s") - 0.1, t1 = rel.number("t_high_s") + 0.1;
  add_motion_table(f, c, std::pair{t0, t1});
  // The estimates at the release: accelerometer, lever arm (a little before and after, to be seen
  // apart) and the one used.
  const double dt = 0.012 * (t1 - t0);  // apart enough to be seen
  const double t = th.number("release_t_s");
  std::vector<std::pair<double, const Record*>> est;
  for (const auto& [name, shift] : std::vector<std::pair<const char*, double>>{
           {"accel_speed_m_s", -dt}, {"lever_speed_m_s", dt}, {"speed_m_s", 0.0}})
    est.emplace_back(t + shift, &th.at("measured").at(name));
  add_estimates(f, "estimates", est);
  const Phases p = phases(c);
  const std::string e = dat(f, "estimates");
  std::ostringstream s;
  s << p.objects << "set multiplot layout 3,1\n" << kStacked
    << "set xrange [" << g(t0) << ":" << g(t1) << "]\n"
    << "set ylabel 'acceleration (g)'\n"
    << "plot " << axis_plot(f, "samples", 2, kAccelNames, "lp pt 7 ps 0.4 lw 1.2") << p.entries << "\n"
    << "set ylabel " << gnuplot_quote(rate_label(c)) << "\n"
    << "plot " << axis_plot(f, "samples", 5, kRateNames, "lp pt 7 ps 0.4 lw 1.2") << "\n"
    << "set xlabel 't (s)'\nset ylabel 'stone speed in the room (m/s)'\n"
    << "plot " << dat(f, "samples") << " u 1:8 w l lw 2 lc rgb '" << kAxis[0]
    << "' t 'accelerometer, integrated" << (th.flag("clipped") ? " (clipped: a lower bound)" : "") << "', '' u 1:9 w l lw 2 lc rgb '"
    << kAxis[1] << "' t '{/Symbol w} × lever arm', " << e << " every ::0::0 u 1:2:3:4 w yerrorbars pt 5 ps 1.2 lw 2 lc rgb '"
    << kAxis[0] << "' t 'release: accelerometer', " << e << " every ::1::1 u 1:2:3:4 w yerrorbars pt 5 ps 1.2 lw 2 lc rgb '"
    << kAxis[1] << "' t 'release: lever arm', " << e
    << " every ::2::2 u 1:2:3:4 w yerrorbars pt 7 ps 1.6 lw 2 lc rgb '#000000' t 'release: the throw (used)'\n"
    << "unset multiplot\n";
  f.script = s.str();
  return f;
}

std::optional<Figure> capture_timing_figure(const std::string& key, const Record& c) {
  const Record& t = c.at("timing");
  if (t.flag("nominal") || !t.flag("ok") || t.table("intervals").rows() == 0) return std::nullopt;
  const bool clock = t.text("clock") == "regular_reports";
  Figure f = make(key, "timing",
                  std::string("Timing: the interval between kept reports against time (gaps red) with the median interval "
                              "and ± one standard deviation (the jitter)") +
                      (clock ? ", each stamp's distance from the fitted regular clock," : ",") +
                      " and the distribution of the intervals",
                  1100, clock ? 980 : 760);
  const std::vector<std::string> names{"t_s", "interval_ms", "lost_reports", "stamp_minus_clock_ms"};
  add_copy(f, "intervals", t, "intervals", names);
  // The histogram counts every interval; the panels against time draw, for a long capture (a
  // 10-minute one drew a 14 MB SVG), the intervals that hold each run's extremes and every gap.
  const Table& stored = t.table("intervals");
  const std::size_t n = stored.rows();
  std::string drawn = "intervals";
  if (n > kMaxPlotRows) {
    std::vector<std::vector<double>> col;
    for (const auto& name : names) col.push_back(stored.column(name));
    const std::size_t k = extreme_run_length(n, 2);
    std::vector<std::size_t> keep = extreme_rows({col[1], col[3]}, k);
    for (std::size_t i = 0; i < n; ++i)
      if (col[2][i] > 0) keep.push_back(i);
    std::sort(keep.begin(), keep.end());
    keep.erase(std::unique(keep.begin(), keep.end()), keep.end());
    Table thin{names, {}};
    for (std::size_t i : keep) thin.add_row({col[0][i], col[1][i], col[2][i], col[3][i]});
    drawn = "drawn";
    add_computed_table(f, f.name + "_drawn", thin,
                       "the stored intervals (" + t.path() + "/intervals), " + std::to_string(n) +
                           " of them, thinned for the panels against time: every gap, and of each run of " +
                           std::to_string(k) + " the intervals holding the run's least or largest interval or stamp "
                           "offset (the histogram counts them all)");
    f.title += " (a long capture: the panels against time draw every gap and each run's extremes; the histogram "
               "counts every interval)";
  }
  // Seconds a capture's timing can hold (capture_timing.cpp refuses a clock beyond 1e12 s); data
  // edited by hand beyond them is refused by name (stored_values.hpp), not drawn as `inf`.
  constexpr double kLongest_s = 1e12;
  const double p = 1e3 * stored_in(t, "period_s", 0, kLongest_s), j = 1e3 * stored_in(t, "jitter_s", 0, kLongest_s);
  const double max_ms = 1e3 * stored_in(t, "max_interval_s", 0, kLongest_s);
  const double bin = p / 20;
  const std::string d = dat(f, drawn), all = dat(f, "intervals");
  std::ostringstream s;
  s << "set multiplot layout " << (clock ? 3 : 2) << ",1\n" << kStacked
    << "set xlabel 't (s)'\nset ylabel 'interval (ms)'\n" << (max_ms > 4 * p ? "set logscale y\n" : "")
    << "plot " << d << " u 1:($3 > 0 ? NaN : $2) w p pt 7 ps 0.4 lc rgb '" << kAxis[0] << "' t 'interval', " << d
    << " u 1:($3 > 0 ? $2 : NaN) w p pt 7 ps 0.8 lc rgb '" << kRealtime << "' t 'gap (reports lost)', " << g(p)
    << " w l lw 1.5 lc rgb '#000000' t 'median interval', " << g(p + j) << " w l dt 2 lc rgb '#555555' t '± jitter (1 σ)', "
    << g(p - j) << " w l dt 2 lc rgb '#555555' notitle\nunset logscale y\n";
  if (clock)
    s << "set ylabel 'stamp − clock (ms)'\nplot " << d << " u 1:4 w p pt 7 ps 0.4 lc rgb '" << kAxis[2]
      << "' t 'host stamp − fitted clock', " << g(p / 2) << " w l dt 2 lc rgb '#555555' t '± half an interval', "
      << g(-p / 2) << " w l dt 2 lc rgb '#555555' notitle\n";
  s << "set xlabel 'interval (ms)'\nset ylabel 'intervals'\nset xrange [0:" << g(std::min(1.05 * max_ms, 6 * p))
    << "]\nset style fill solid 0.6\nset boxwidth " << g(bin) << "\nbin(x) = " << g(bin) << " * floor(x / " << g(bin)
    << ") + " << g(bin / 2) << "\nplot " << all << " u (bin($2)):(1.0) smooth frequency w boxes lc rgb '" << kAxis[0]
    << "' t 'intervals between kept reports'\nunset multiplot\n";
  f.script = s.str();
  return f;
}

std::optional<Figure> capture_release_figure(const std::string& key, const Record& c) {
  const Record& th = c.at("throw");
  if (!th.flag("computed")) return std::nullopt;
  Figure f = make(key, "release_state",
                  "The release state with its intervals (black: the estimate and its interval; grey: the ensemble's "
                  "members), the throw as measured in the room beside the virtual stone it is mapped to",
                  1200, 820);
  const Table& ens = th.table("ensemble");
  add_copy(f, "ensemble", th, "ensemble", {});
  const double n = std::max<double>(1, double(ens.rows()));
  struct Category {
    std::string label;   // x tic label
    std::string column;  // ensemble column
    const Record* value;
  };
  struct Panel {
    std::string name, ylabel;
    std::vector<Category> categories;
  };
  const Record& m = th.at("measured");
  const Record& v = th.at("virtual");
  const std::vector<Panel> panels{
      {"speed", "speed (m/s)",
       {{"room:\\naccel.", "accel_speed_m_s", &m.at("accel_speed_m_s")},
        {"room:\\nlever arm", "lever_speed_m_s", &m.at("lever_speed_m_s")},
        {"room:\\nused", "measured_speed_m_s", &m.at("speed_m_s")},
        {"virtual\\nstone", "speed_m_s", &v.at("speed_m_s")}}},
      {"spin", "spin about the stone's normal (rev/s)",
       {{"room", "measured_spin_rev_s", &m.at("spin_rev_s")}, {"virtual\\nstone", "spin_rev_s", &v.at("spin_rev_s")}}},
      {"height", "height (m)",
       {{"room: rise since\\nthe still part", "rise_m", &m.at("rise_m")},
        {"virtual stone:\\nabove the water", "height_m", &v.at("height_m")}}},
      {"attack", "attack angle (deg)", {{"room = virtual", "attack_angle_deg", &v.at("attack_angle_deg")}}},
      {"path", "path angle (deg)", {{"room = virtual", "path_angle_deg", &v.at("path_angle_deg")}}}};
  std::ostringstream s;
  s << "set multiplot layout 2,3\nset grid y\nset key off\nset bmargin 4\n";
  for (const Panel& p : panels) {
    std::vector<std::pair<double, const Record*>> est;
    std::string tics, plot;
    for (std::size_t i = 0; i < p.categories.size(); ++i) {
      const Category& k = p.categories[i];
      const double x = double(i + 1);
      est.emplace_back(x, k.value);
      tics += std::string(i ? ", " : "") + "\"" + k.label + "\" " + g(x);
      plot += std::string(i ? ", " : "") + dat(f, "ensemble") + " u (" + g(x) + " + 0.5 * (column(0) / " + g(n) +
              " - 0.5)):" + col(ens, k.column) + " w p pt 7 ps 0.5 lc rgb '" + kMember + "'";
    }
    add_estimates(f, p.name, est);
    s << "set xrange [0.4:" << g(double(p.categories.size()) + 0.6) << "]\nset xtics (" << tics << ")\nset ylabel "
      << gnuplot_quote(p.ylabel) << "\nplot " << plot << ", " << dat(f, p.name)
      << " u 1:2:3:4 w yerrorbars pt 7 ps 1.4 lw 2 lc rgb '#000000'\n";
  }
  s << "unset multiplot\n";
  f.script = s.str();
  return f;
}

std::optional<Figure> capture_room_and_water_figure(const std::string& key, const Record& c) {
  const Record& th = c.at("throw");
  if (!th.flag("computed") || th.table("room_path").rows() == 0) return std::nullopt;
  const Record& sim = c.at("simulation");
  Figure f = make(key, "room_and_water",
                  "The throw in the room and over the water: the stone's path in the room from the start of the still "
                  "part to the release (integrated from the accelerometer" +
                      std::string(th.flag("clipped") ? ", which clipped: the path falls short" : "") +
                      "; from above to scale, from the side), and the virtual stone's flight from the height the "
                      "thrower maps it to; arrows: the release velocity used × " +
                      std::to_string(int(1000 * kArrow_s)) + " ms",
                  1400, 760);
  const Table path = th.table("room_path");
  add_copy(f, "room", th, "room_path", {"x_m", "y_m", "z_m"});
  // The release velocities as vectors (so that autoscaling takes in their heads): in the room from
  // the last sample before the release, over the water from the virtual release point.
  const std::size_t last = path.rows() - 1;
  Table arrows{{"x_m", "y_m", "z_m", "dx_m", "dy_m", "dz_m"}, {}};
  arrows.add_row({path.column("x_m")[last], path.column("y_m")[last], path.column("z_m")[last],
                  kArrow_s * th.number("measured_vx_m_s"), kArrow_s * th.number("measured_vy_m_s"),
                  kArrow_s * th.number("measured_vz_m_s")});
  arrows.add_row({0.0, 0.0, th.at("virtual").at("height_m").number("nominal"), kArrow_s * th.number("virtual_vx_m_s"),
                  kArrow_s * th.number("virtual_vy_m_s"), kArrow_s * th.number("virtual_vz_m_s")});
  add_computed_table(f, f.name + "_velocity", arrows,
                     "the release velocities drawn as arrows: each velocity times " + std::to_string(int(1000 * kArrow_s)) + " ms");
  const std::string room = dat(f, "room"), v = dat(f, "velocity");
  const std::string vector_style = " w vectors head filled size screen 0.012,20 lw 2 lc rgb '" + std::string(kRealtime) + "'";
  std::ostringstream s;
  s << "set multiplot\nset grid\nset key below\n"
    << "set origin 0, 0.5\nset size 0.42, 0.5\nset size ratio -1\n"
    << "set title 'in the room, from above'\nset xlabel 'along the throw (m)'\nset ylabel 'to the left (m)'\n"
    << "plot " << room << " u 1:2 w l lw 2 lc rgb '" << kAxis[0] << "' t 'stone centre', " << room
    << " every ::0::0 u 1:2 w p pt 7 ps 1 lc rgb '" << kAxis[2] << "' t 'still part', " << v
    << " every ::0::0 u 1:2:4:5" << vector_style << " t 'release velocity'\n"
    // The panels at the canvas's foot get the room for their axis label and the key below it
    // (gnuplot's own margin put the key over the label there).
    << "set origin 0, 0\nset size 0.42, 0.5\nset size noratio\nset bmargin 6\n"
    << "set title 'in the room, from the side'\nset ylabel 'up, from the still part (m)'\n"
    << "plot " << room << " u 1:3 w l lw 2 lc rgb '" << kAxis[0] << "' t 'stone centre', " << room
    << " every ::0::0 u 1:3 w p pt 7 ps 1 lc rgb '" << kAxis[2] << "' t 'still part', " << v
    << " every ::0::0 u 1:3:4:6" << vector_style << " t 'release velocity'\n"
    << "set origin 0.42, 0\nset size 0.58, 1\nset bmargin 5\nset key below\n"
    << "set title 'the virtual stone over the water'\nset xlabel 'distance (m)'\nset ylabel 'height of the centre (m)'\n"
    << "plot 0 w l lw 1.5 lc rgb '#3060c0' t 'water', " << v << " every ::1::1 u 1:3:4:6" << vector_style
    << " t 'release velocity'";
  s << solver_paths(f, sim, ContactMarks::none) << "\nunset multiplot\n";
  f.script = s.str();
  return f;
}

std::optional<Figure> capture_trajectory_figure(const std::string& key, const Record& c) {
  const Record& sim = c.at("simulation");
  if (!sim.has_child("realtime") && !sim.has_child("reference")) return std::nullopt;
  Figure f = make(key, "trajectory",
                  "Height of the stone's centre against distance for the nominal throw: real-time model and reference "
                  "(CVODE); points on the water: where each contact began",
                  1100, 480);
  std::ostringstream s;
  s << "set grid\nset key below\nset xlabel 'distance (m)'\nset ylabel 'height of the centre (m)'\n"
    << "plot 0 w l lw 1.5 lc rgb '#3060c0' t 'water'";
  s << solver_paths(f, sim, ContactMarks::where_they_began) << "\n";
  f.script = s.str();
  return f;
}

std::optional<Figure> capture_bounce_figure(const std::string& key, const Record& c) {
  const Record& sim = c.at("simulation");
  if (!sim.has_child("ensemble")) return std::nullopt;
  const Record& e = sim.at("ensemble");
  Figure f = make(key, "bounce_distribution",
                  std::string("Bounce counts of the capture's ensemble (real-time model), with the nominal throw's counts") +
                      (e.has_table("bound_corners")
                           ? " and those of the nominal throw at the corners of the speed and height intervals (clipped: the accelerometer's bounds joined with the members)"
                           : ""),
                  900, 560);
  const Table& h = e.table("histogram");
  add_copy(f, "histogram", e, "histogram", {});
  const auto counts = h.column("bounces");
  double lo = counts.empty() ? 0 : *std::min_element(counts.begin(), counts.end());
  double hi = counts.empty() ? 0 : *std::max_element(counts.begin(), counts.end());
  // The nominal throw's counts as lines beside the bar of their count (real-time left, reference right).
  std::string marks, arrows;
  double marks_hi = lo;  // the largest count marked
  for (const auto& [solver, colour, title, shift] :
       {std::tuple{"realtime", kRealtime, "nominal throw, real-time model", -0.15},
        std::tuple{"reference", kReference, "nominal throw, reference (CVODE)", 0.15}}) {
    if (!sim.has_child(solver)) continue;
    const double b = sim.at(solver).number("bounces");
    lo = std::min(lo, b);
    hi = std::max(hi, b);
    marks_hi = std::max(marks_hi, b);
    arrows += "set arrow from " + g(b + shift) + ", graph 0 to " + g(b + shift) + ", graph 0.85 nohead lw 3 dt 2 lc rgb '" +
              colour + "' front\n";
    marks += ", keyentry w l lw 3 dt 2 lc rgb '" + std::string(colour) + "' t " + gnuplot_quote(title);
  }
  // Clipped: the nominal throw at the corners of the accelerometer's bounds (each distinct count once).
  if (e.has_table("bound_corners")) {
    std::vector<double> seen;
    for (const double b : e.table("bound_corners").column("bounces_realtime")) {
      if (!std::isfinite(b) || std::find(seen.begin(), seen.end(), b) != seen.end()) continue;
      seen.push_back(b);
      lo = std::min(lo, b);
      hi = std::max(hi, b);
      marks_hi = std::max(marks_hi, b);
      arrows += "set arrow from " + g(b) + ", graph 0 to " + g(b) + ", graph 0.6 nohead lw 3 dt 3 lc rgb '" + kAxis[1] + "' front\n";
    }
    if (!seen.empty())
      marks += ", keyentry w l lw 3 dt 3 lc rgb '" + std::string(kAxis[1]) + "' t 'nominal throw at the corners of the speed and height intervals'";
  }
  // A few far members (a paper-convention member can make 100 bounces where the rest make 1 to 30)
  // would squeeze the ensemble and the marks into a corner: the axis then ends past the central
  // 95 % and the marks, and a label says how many members lie beyond, and how far.
  std::string beyond;
  const double central_hi = e.has_number("bounces_high") && std::isfinite(e.number("bounces_high")) ? e.number("bounces_high") : hi;
  const double keep = std::max(central_hi, marks_hi);
  const double counts_hi = counts.empty() ? 0 : *std::max_element(counts.begin(), counts.end());
  if (counts_hi > 2 * keep + 5 && hi == counts_hi) {
    const double axis_hi = std::ceil(1.25 * keep + 2);
    double members = 0;
    const auto per = h.column("members");
    for (std::size_t i = 0; i < counts.size(); ++i)
      if (counts[i] > axis_hi) members += per[i];
    hi = axis_hi;
    beyond = "set label " + gnuplot_quote(fmt(members) + (members == 1 ? " member" : " members") +
                                          " beyond the axis, up to " + fmt(counts_hi) + " bounces") +
             " at graph 0.98, graph 0.95 right front\n";
  }
  std::ostringstream s;
  // A tic per count where they fit; gnuplot's own spacing for a wide spread (a paper-convention
  // member can make 100 bounces, whose 100 labels would overprint).
  s << beyond << "set grid y\nset key below\nset xlabel 'bounces'\nset ylabel 'throws of the ensemble'\nset xtics "
    << (hi - lo > 20 ? "autofreq" : "1") << "\n"
    << "set xrange [" << g(lo - 0.6) << ":" << g(hi + 0.6) << "]\nset yrange [0:*]\nset offsets 0, 0, graph 0.3, 0\n"
    << "set style fill solid 0.6\n"
    << "set boxwidth 0.8\n" << arrows << "plot " << dat(f, "histogram") << " u 1:2 w boxes lc rgb '" << kAxis[0]
    << "' t 'ensemble'" << marks << "\n";
  f.script = s.str();
  return f;
}

std::optional<Figure> capture_scene_stone_figure(const std::string& key, const Record& c) {
  if (!c.has_child("scene")) return std::nullopt;
  const Record& st = c.at("scene").at("stone");
  Figure f = make(key, "scene_stone",
                  "The throw through the coupled scene: height of the stone's centre against distance for the scene's "
                  "stone (real-time model on the live water), the same model on still water and the reference (CVODE, "
                  "still water); points on the water: where each contact ended",
                  1100, 480);
  std::ostringstream s;
  s << "set grid\nset key below\nset xlabel 'distance (m)'\nset ylabel 'height of the centre (m)'\n"
    << "plot 0 w l lw 1.5 lc rgb '#3060c0' t 'still water level'";
  for (const auto& [part, colour, style, title] :
       {std::tuple{"scene_path", kRealtime, "lw 3", "scene (real-time model, live water)"},
        std::tuple{"still_path", kAxis[0], "lw 1.5", "real-time model, still water"},
        std::tuple{"reference_path", kReference, "lw 1.5 dt 2", "reference (CVODE, still water)"}}) {
    add_copy(f, part, st, part, {"x_m", "z_m"});
    s << ", " << dat(f, part) << " u 1:2 w l " << style << " lc rgb '" << colour << "' t " << gnuplot_quote(title);
  }
  add_copy(f, "contacts", st, "contacts", {"scene_exit_x_m", "reference_exit_x_m"});
  s << ", " << dat(f, "contacts") << " u 1:(0) w p pt 6 ps 1.4 lc rgb '" << kRealtime << "' t 'contact ends (scene)', "
    << dat(f, "contacts") << " u 2:(0) w p pt 2 ps 1.4 lc rgb '" << kReference << "' t 'contact ends (CVODE)'\n";
  f.script = s.str();
  return f;
}

WaveForcingWords wave_forcing_words(const Record& s) {
  const std::string forcing = s.has_text("forcing") ? s.text("forcing") : "";
  const std::string samples = s.has_number("draught_samples") ? fmt(s.number("draught_samples")) : "?";
  if (forcing == "pressure")
    return {"the pressure head", "pressure head",
            "the head of the stone's own loads against the moving surface, gathered at its steps",
            "the pressure head gathered with the leapfrog's hat weights"};
  if (forcing == "displacement")
    return {"the draught", "draught", "b against the moving surface, sampled at the stone's steps",
            samples + " draught samples per water step"};
  return {"the forcing head", "forcing head", "the head against the moving surface, gathered at the stone's steps",
          "a forcing this record does not name"};
}

std::optional<Figure> capture_scene_wave_figure(const std::string& key, const Record& c) {
  if (!c.has_child("scene") || !c.at("scene").at("waves").flag("compared")) return std::nullopt;
  const Record& w = c.at("scene").at("waves");
  const WaveForcingWords head = wave_forcing_words(c.at("scene").at("settings"));
  // Data written before the row of the largest difference was stored has the first contact's row only.
  const bool worst = w.has_table("worst_profile");
  Figure f = make(key, "scene_waves",
                  std::string("The waves the stone made at the scene's last frame, along the grid row through its first contact") +
                      (worst ? " (top) and along the row holding the largest difference between the scene and the continuum "
                               "reference (bottom)"
                             : "") +
                      ": the scene, the forced leapfrog driven by the reference's " + head.short_name + ", and the forced spectral reference "
                      "(the stencil's exact semi-discrete solution, and the continuum one)",
                  1100, worst ? 860 : 520);
  auto panel = [&](std::ostringstream& s, const char* table, const std::string& title) {
    add_copy(f, table, w, table, {});
    const std::string d = dat(f, table);
    s << "set title " << gnuplot_quote(title) << "\n"
      << "plot " << d << " u 1:($2*1e3) w l lw 3 lc rgb '" << kRealtime << "' t 'scene (two-way)', " << d
      << " u 1:($3*1e3) w l lw 2 lc rgb '" << kAxis[0] << "' t " << gnuplot_quote("leapfrog, reference " + head.short_name) << ", " << d
      << " u 1:($4*1e3) w l lw 1.5 dt 2 lc rgb '" << kAxis[2] << "' t 'semi-discrete reference', " << d
      << " u 1:($5*1e3) w l lw 1.5 dt 3 lc rgb '" << kReference << "' t 'continuum reference'\n";
  };
  std::ostringstream s;
  s << "set grid\nset key outside right top\nset xlabel 'x (m)'\nset ylabel 'surface height (mm)'\n";
  if (worst) s << "set multiplot layout 2,1\n";
  panel(s, "profile", "row y = " + fmt(w.number("row_y_m"), 3) + " m, through the first contact");
  if (worst) {
    panel(s, "worst_profile", "row y = " + fmt(w.number("worst_row_y_m"), 3) + " m, holding the largest |scene − continuum| (at x = " +
                                  fmt(w.number("worst_x_m"), 3) + " m)");
    s << "unset multiplot\n";
  }
  f.script = s.str();
  return f;
}

}  // namespace stoneskip
