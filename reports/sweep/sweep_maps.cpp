#include "reports/sweep/sweep_maps.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

#include "tools/io/column_units.hpp"
#include "tools/io/input_error.hpp"

namespace stoneskip {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Gnuplot text: single quotes doubled; labels are set `noenhanced` so keys keep their underscores.
std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string num(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

const char* kCountPalette =
    "set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', 4 '#fde725')\n";
const char* kDivergingPalette = "set palette defined (-1 '#2166ac', 0 '#f7f7f7', 1 '#b2182b')\n";
const char* kLevelColours[] = {"#000000", "#ffffff", "#e41a1c", "#ff7f00", "#f781bf", "#a65628"};

// The end of every figure's script: the plot command's newline, the script, the size.
Figure& finish(Figure& f, std::ostringstream& script, int width_px, int height_px) {
  script << "\n";
  f.script = script.str();
  f.width_px = width_px;
  f.height_px = height_px;
  return f;
}

struct Axis {
  std::string key;
  bool log = false;
};

std::string axes_script(const Axis& x, const Axis& y, const std::string& title) {
  std::ostringstream s;
  s << "set title " << quoted(title) << " noenhanced\n";
  s << "set xlabel " << quoted(x.key) << " noenhanced\nset ylabel " << quoted(y.key) << " noenhanced\n";
  if (x.log) s << "set logscale x\n";
  if (y.log) s << "set logscale y\n";
  return s.str();
}

// A tick step of 1, 2 or 5 times a power of ten that puts at most kMaxColourTicks ticks on a span
// of whole counts (54 ticks of one count each cannot be read).
constexpr int kMaxColourTicks = 10;
int count_tick_step(double span) {
  for (int decade = 1;; decade *= 10)
    for (int m : {1, 2, 5})
      if (span / (m * decade) + 1 <= kMaxColourTicks) return m * decade;
}

// The colour scale of bounce counts lo..hi: one colour per count, ticks at whole counts.
std::string count_scale(double lo, double hi, const std::string& label) {
  hi = std::max(hi, lo + 1);  // gnuplot needs two colours at least
  const int step = count_tick_step(hi - lo);
  std::ostringstream s;
  s << kCountPalette << "set palette maxcolors " << static_cast<int>(hi - lo + 1) << "\nset cbrange [" << lo - 0.5 << ":"
    << hi + 0.5 << "]\nset cbtics " << step * std::floor(lo / step) << ", " << step << "\nset cblabel " << quoted(label)
    << " noenhanced offset 1.5,0\n";
  return s.str();
}

std::string continuous_scale(double lo, double hi, const std::string& label) {
  std::ostringstream s;
  // No offset: gnuplot sets the label beyond the tick labels, which are wider here than whole
  // counts ("0.8"), and an offset of 1.5 put it past the picture's right edge.
  s << kCountPalette << "set cbrange [" << num(lo) << ":" << num(hi > lo ? hi : lo + 1) << "]\nset cblabel " << quoted(label)
    << " noenhanced\n";
  return s.str();
}

std::string diverging_scale(double span, const std::string& label) {
  const double m = std::max(1.0, span);
  std::ostringstream s;
  s << kDivergingPalette << "set palette maxcolors " << static_cast<int>(2 * m + 1) << "\nset cbrange [" << -m - 0.5
    << ":" << m + 0.5 << "]\nset cblabel " << quoted(label) << " noenhanced offset 1.5,0\n";
  return s.str();
}

std::pair<double, double> finite_range(const std::vector<double>& v) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double x : v)
    if (std::isfinite(x)) {
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  if (lo > hi) lo = hi = 0;
  return {lo, hi};
}

// Bounce thresholds k + ½ across the count's range, at most `max_levels`, spread evenly.
std::vector<int> threshold_counts(double lo, double hi, std::size_t max_levels) {
  std::vector<int> ks;
  const int a = static_cast<int>(std::floor(lo)), b = static_cast<int>(std::ceil(hi));
  if (b <= a || max_levels == 0) return ks;
  const int step = std::max(1, static_cast<int>(std::ceil(double(b - a) / double(max_levels))));
  for (int k = a; k < b; k += step) ks.push_back(k);
  return ks;
}

// Tics of a heat-map axis drawn in cell-index space (cell i at i): round values placed where
// they fall between the grid values, which are equally spaced in x (linear) or ln x (log).
std::string index_tics(const char* axis, const std::vector<double>& values, bool log_scale) {
  const std::size_t n = values.size();
  std::ostringstream s;
  s << "set " << axis << "tics (";
  if (n == 1) return s.str() + quoted(num(values[0])) + " 0)\n";
  auto f = [&](double v) { return log_scale ? std::log(v) : v; };
  const double a = f(values.front()), b = f(values.back());
  auto pos = [&](double v) { return (f(v) - a) / (b - a) * static_cast<double>(n - 1); };
  std::vector<double> ticks;
  const double lo = values.front(), hi = values.back();
  if (log_scale) {
    const int d0 = static_cast<int>(std::floor(std::log10(lo))), d1 = static_cast<int>(std::ceil(std::log10(hi)));
    const std::vector<double> mantissas = d1 - d0 <= 2 ? std::vector<double>{1, 2, 5} : std::vector<double>{1};
    for (int d = d0; d <= d1; ++d)
      for (double m : mantissas) ticks.push_back(m * std::pow(10.0, d));
  } else {
    const double raw = (hi - lo) / 5, mag = std::pow(10.0, std::floor(std::log10(raw)));
    double step = 10 * mag;
    for (double m : {1.0, 2.0, 2.5, 5.0})
      if (m * mag >= raw) {
        step = m * mag;
        break;
      }
    // The multiples of step in [lo, hi], by index: summing step from lo never ended where step is
    // below lo's resolution (an axis from 0.1 to 0.1 + 1 ulp hung sweep-plot).
    const double k0 = std::ceil(lo / step), k1 = std::floor(hi / step + 1e-9);
    for (int i = 0; std::isfinite(k0) && k0 + i <= k1 && i <= 10; ++i) {
      const double t = (k0 + i) * step;
      if (ticks.empty() || t > ticks.back()) ticks.push_back(std::abs(t) < 1e-12 * step ? 0 : t);
    }
  }
  bool first = true;
  for (double t : ticks) {
    if (t < lo * (1 - 1e-12) - 1e-300 || t > hi * (1 + 1e-12) + 1e-300) continue;
    s << (first ? "" : ", ") << quoted(num(t)) << " " << num(pos(t));
    first = false;
  }
  return s.str() + ")\n";
}

struct Contour {
  GridMap field;      // drawn where this field passes the level
  double level;
  std::string label;
};

// A heat map of a grid map (one cell per grid point, drawn as an image in cell-index space so
// that neighbouring cells meet without seams; tics carry the values) with contours over it.
Figure heat_map(const std::string& name, const std::string& title, const GridMap& map, const Axis& x, const Axis& y,
                const std::string& value_unit, const std::string& scale, const std::vector<Contour>& contours) {
  Figure f;
  f.name = name;
  f.title = title;
  const std::size_t nx = map.x_values.size(), ny = map.y_values.size();
  // An image needs a value in every cell: a cell without one is drawn with the lowest value
  // ("shown") and covered by a grey box.
  const double lowest = finite_range(map.value).first;
  Table cells, empty;
  cells.columns = {"ix", "iy", "x", "y", "value", "shown"};
  cells.units = {"1", "1", column_unit(x.key), column_unit(y.key), value_unit, value_unit};
  empty.columns = {"ix", "iy"};
  for (std::size_t iy = 0; iy < ny; ++iy)
    for (std::size_t ix = 0; ix < nx; ++ix) {
      const double v = map.at(ix, iy);
      cells.add_row({double(ix), double(iy), map.x_values[ix], map.y_values[iy], v, std::isfinite(v) ? v : lowest});
      if (!std::isfinite(v)) empty.add_row({double(ix), double(iy)});
    }
  f.tables.emplace_back(name + "_cells", cells);
  std::ostringstream s;
  s << "set title " << quoted(title) << " noenhanced\n";
  s << "set xlabel " << quoted(x.key + (x.log ? " (log scale)" : "")) << " noenhanced\nset ylabel "
    << quoted(y.key + (y.log ? " (log scale)" : "")) << " noenhanced\n";
  s << index_tics("x", map.x_values, x.log) << index_tics("y", map.y_values, y.log) << scale;
  s << "set xrange [-0.5:" << nx - 0.5 << "]\nset yrange [-0.5:" << ny - 0.5 << "]\nset tics out\n";
  // gnuplot draws nothing `with image` under 2 × 2 cells ("Image grid must be at least 4 points"):
  // a grid with one value on an axis is drawn as filled boxes, one per cell, instead.
  std::ostringstream plot;
  bool titled = false;  // a series in the key (without one, the key's box was a stray line)
  if (nx >= 2 && ny >= 2)
    plot << "plot '" << name << "_cells.dat' using 1:2:6 with image notitle";
  else
    plot << "plot '" << name << "_cells.dat' using 1:2:($1-0.5):($1+0.5):($2-0.5):($2+0.5):6 with boxxyerror "
         << "fs solid 1.0 noborder fc palette notitle";
  if (empty.rows() > 0) {
    f.tables.emplace_back(name + "_empty", empty);
    plot << ", \\\n     '" << name << "_empty.dat' using 1:2:($1-0.5):($1+0.5):($2-0.5):($2+0.5) with boxxyerror "
         << "fs solid 1.0 noborder fc rgb '#bdbdbd' title 'no result (failed or not run)'";
    titled = true;
  }
  for (std::size_t l = 0; l < contours.size(); ++l) {
    GridMap index = contours[l].field;  // the same field on cell indices
    for (std::size_t i = 0; i < nx; ++i) index.x_values[i] = double(i);
    for (std::size_t i = 0; i < ny; ++i) index.y_values[i] = double(i);
    Table seg;
    seg.columns = {"ix0", "iy0", "ix1", "iy1"};  // cell indices: unit "1" from the names
    for (const auto& e : threshold_edges(index, contours[l].level, false, false)) seg.add_row({e.x0, e.y0, e.x1, e.y1});
    if (seg.rows() == 0) continue;
    const std::string t = name + "_level" + std::to_string(l);
    f.tables.emplace_back(t, seg);
    plot << ", \\\n     '" << t << ".dat' using 1:2:($3-$1):($4-$2) with vectors nohead lw 2.5 lc rgb '"
         << kLevelColours[l % std::size(kLevelColours)] << "' title " << quoted(contours[l].label);
    titled = true;
  }
  // The key on grey: the second contour's colour is white (seen on the map's dark end), which a
  // white key hid.
  s << (titled ? "set key outside below box opaque fc rgb '#9e9e9e'\n" : "unset key\n") << plot.str();
  return finish(f, s, 900, 760);
}

Figure scatter(const std::string& name, const std::string& title, const std::vector<double>& xs,
               const std::vector<double>& ys, const std::vector<double>& v, const Axis& x, const Axis& y,
               const std::string& value_unit, const std::string& scale) {
  Figure f;
  f.name = name;
  f.title = title;
  Table t;
  t.columns = {"x", "y", "value"};
  t.units = {column_unit(x.key), column_unit(y.key), value_unit};
  for (std::size_t i = 0; i < v.size(); ++i)
    if (std::isfinite(v[i])) t.add_row({xs[i], ys[i], v[i]});
  if (t.rows() == 0) t.add_row({kNaN, kNaN, kNaN});
  f.tables.emplace_back(name + "_points", t);
  const double size = v.size() > 5000 ? 0.35 : v.size() > 500 ? 0.6 : 1.0;
  f.script = axes_script(x, y, title) + scale + "plot '" + name + "_points.dat' using 1:2:3 with points pt 7 ps " +
             num(size) + " lc palette notitle\n";
  f.width_px = 900;
  f.height_px = 720;
  return f;
}

// Histogram of integer values, one series per (label, values); bars side by side.
Figure histogram(const std::string& name, const std::string& title, const std::string& x_label,
                 const std::vector<std::pair<std::string, std::vector<double>>>& series) {
  Figure f;
  f.name = name;
  f.title = title;
  std::ostringstream s;
  s << "set title " << quoted(title) << " noenhanced\nset xlabel " << quoted(x_label)
    << " noenhanced\nset ylabel 'throws'\nset grid ytics\nset style fill solid 0.7 border -1\nset xtics 1\n"
       "set key below\nset yrange [0:*]\n";
  const double width = 0.8 / static_cast<double>(std::max<std::size_t>(1, series.size()));
  s << "set boxwidth " << num(width) << "\nplot ";
  for (std::size_t k = 0; k < series.size(); ++k) {
    std::map<long long, double> counts;
    for (double v : series[k].second)
      if (std::isfinite(v)) counts[std::llround(v)] += 1;
    Table t;
    t.columns = {"value", "throws"};
    t.units = {"1", "1"};  // a count, and the throws holding it
    for (const auto& [value, n] : counts) t.add_row({static_cast<double>(value), n});
    if (t.rows() == 0) t.add_row({kNaN, kNaN});
    const std::string tn = name + "_" + std::to_string(k);
    f.tables.emplace_back(tn, t);
    const double offset = (static_cast<double>(k) - 0.5 * static_cast<double>(series.size() - 1)) * width;
    s << (k ? ", \\\n     " : "") << "'" << tn << ".dat' using ($1+" << num(offset) << "):2 with boxes title "
      << quoted(series[k].first);
  }
  return finish(f, s, 900, 520);
}

// One solver's bounce counts along a one-axis grid: NaN where the run has no count, failed marking
// the runs that failed (the others without a count were not run).
struct CountSeries {
  std::string label;
  std::vector<double> x, count;
  std::vector<char> failed;
};

// The convention of reports/README.md for bounce counts: each count held to halfway to its
// neighbours (a step outline: a change is drawn at the middle of its bracket, and the last value
// shows over the last half spacing; halfway in ln x on a log axis), the outline broken at a run
// without a count, never bridged; the runs as dots; a failed run a cross on a row of its own at −1.
// Until December 5 the counts were joined by sloping lines and a failed run left a silent gap.
Figure count_curve(const std::string& name, const std::string& title, const Axis& x, const std::vector<CountSeries>& series) {
  Figure f;
  f.name = name;
  f.title = title;
  const std::string xu = column_unit(x.key);
  auto halfway = [&](double a, double b) { return x.log ? std::sqrt(a * b) : 0.5 * (a + b); };
  std::ostringstream s;
  s << "set title " << quoted(title) << " noenhanced\nset xlabel " << quoted(x.key + (x.log ? " (log scale)" : ""))
    << " noenhanced\nset ylabel 'bounces (−1: the solve failed)'\nset grid\nset yrange [-1.5:*]\nset key below\n";
  if (x.log) s << "set logscale x\n";
  double most = 0;  // whole counts: a tic per count where they are few
  for (const CountSeries& c : series)
    for (double v : c.count)
      if (std::isfinite(v)) most = std::max(most, v);
  if (most <= 20) s << "set ytics 1\n";
  s << "plot ";
  const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c"};
  // The later series (the reference) drawn first and wider, beneath: where the two agree a border of
  // its colour shows around the real-time line (the stones report's convention).
  bool first = true;
  for (std::size_t k = series.size(); k-- > 0;) {
    const bool wide = series.size() > 1 && k + 1 == series.size();
    CountSeries c = series[k];  // in the order of x (a table's rows need not be)
    std::vector<std::size_t> order(c.x.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return series[k].x[a] < series[k].x[b]; });
    for (std::size_t i = 0; i < order.size(); ++i) {
      c.x[i] = series[k].x[order[i]];
      c.count[i] = series[k].count[order[i]];
      c.failed[i] = series[k].failed[order[i]];
    }
    const std::string colour = std::string(" lc rgb '") + colours[k % 3] + "'";
    Table dots, outline, failed;
    dots.columns = outline.columns = {"x", "bounces"};
    failed.columns = {"x", "drawn_at"};
    dots.units = outline.units = failed.units = {xu, "1"};
    const std::size_t n = c.x.size();
    auto has = [&](std::size_t i) { return i < n && std::isfinite(c.count[i]); };
    for (std::size_t i = 0; i < n; ++i) {
      if (has(i)) {
        dots.add_row({c.x[i], c.count[i]});
        const double left = i > 0 && has(i - 1) ? halfway(c.x[i - 1], c.x[i]) : c.x[i];
        const double right = has(i + 1) ? halfway(c.x[i], c.x[i + 1]) : c.x[i];
        outline.add_row({left, c.count[i]});
        outline.add_row({right, c.count[i]});
        if (!has(i + 1)) outline.add_row({kNaN, kNaN});  // a break (a blank line in the .dat)
      } else if (c.failed[i]) {
        failed.add_row({c.x[i], -1});
      }
    }
    const std::string tn = name + "_" + std::to_string(k);
    const bool any_failed = failed.rows() > 0;
    for (Table* t : {&dots, &outline})
      if (t->rows() == 0) t->add_row({kNaN, kNaN});
    f.tables.emplace_back(tn, dots);
    f.tables.emplace_back(tn + "_outline", outline);
    s << (first ? "" : ", \\\n     ") << "'" << tn << "_outline.dat' using 1:2 with lines lw " << (wide ? "5" : "1.5")
      << colour << " title "
      << quoted(c.label) << ", \\\n     '" << tn << ".dat' using 1:2 with points pt 7 ps 0.6" << colour << " notitle";
    if (any_failed) {
      f.tables.emplace_back(tn + "_failed", failed);
      s << ", \\\n     '" << tn << "_failed.dat' using 1:2 with points pt 2 ps " << (wide ? "2.6 lw 3" : "1.4 lw 2")
        << colour << " title " << quoted(c.label + ": solve failed");
    }
    first = false;
  }
  return finish(f, s, 900, 520);
}

std::string word(const std::string& solver) { return solver == "realtime" ? "real-time" : "reference"; }

}  // namespace

std::vector<double> cell_edges(const std::vector<double>& values, bool log_scale) {
  std::vector<double> e;
  const std::size_t n = values.size();
  if (n == 0) return e;
  auto to = [&](double v) { return log_scale ? std::log(v) : v; };
  auto from = [&](double u) { return log_scale ? std::exp(u) : u; };
  if (n == 1) {
    const double u = to(values[0]), half = log_scale ? 0.1 : (values[0] == 0 ? 0.5 : 0.05 * std::abs(values[0]));
    return {from(u - half), from(u + half)};
  }
  e.push_back(from(to(values[0]) - 0.5 * (to(values[1]) - to(values[0]))));
  for (std::size_t i = 0; i + 1 < n; ++i) e.push_back(from(0.5 * (to(values[i]) + to(values[i + 1]))));
  e.push_back(from(to(values[n - 1]) + 0.5 * (to(values[n - 1]) - to(values[n - 2]))));
  return e;
}

std::vector<Segment> threshold_edges(const GridMap& map, double level, bool log_x, bool log_y) {
  std::vector<Segment> out;
  const std::size_t nx = map.x_values.size(), ny = map.y_values.size();
  const std::vector<double> ex = cell_edges(map.x_values, log_x), ey = cell_edges(map.y_values, log_y);
  auto crosses = [&](double a, double b) {
    return std::isfinite(a) && std::isfinite(b) && ((a <= level) != (b <= level));
  };
  for (std::size_t iy = 0; iy < ny; ++iy)
    for (std::size_t ix = 0; ix < nx; ++ix) {
      if (ix + 1 < nx && crosses(map.at(ix, iy), map.at(ix + 1, iy)))
        out.push_back({ex[ix + 1], ey[iy], ex[ix + 1], ey[iy + 1]});  // the edge between two x-neighbours
      if (iy + 1 < ny && crosses(map.at(ix, iy), map.at(ix, iy + 1)))
        out.push_back({ex[ix], ey[iy + 1], ex[ix + 1], ey[iy + 1]});
    }
  return out;
}

GridMap grid_mean(const SweepData& d, const std::vector<double>& column, std::size_t ax, std::size_t ay) {
  GridMap m;
  m.x_values = d.design.grid_values(ax);
  m.y_values = d.design.grid_values(ay);
  const std::size_t nx = m.x_values.size(), ny = m.y_values.size();
  std::vector<double> sum(nx * ny, 0), n(nx * ny, 0);
  const auto& axes = d.design.axes;
  std::vector<std::size_t> stride(axes.size(), 1);
  for (std::size_t k = axes.size() - 1; k-- > 0;) stride[k] = stride[k + 1] * static_cast<std::size_t>(axes[k + 1].count);
  const std::vector<double> index = d.throws.column("throw");
  for (std::size_t r = 0; r < column.size(); ++r) {
    if (!std::isfinite(column[r])) continue;
    const auto t = static_cast<std::size_t>(index[r]);
    const std::size_t ix = t / stride[ax] % static_cast<std::size_t>(axes[ax].count);
    const std::size_t iy = t / stride[ay] % static_cast<std::size_t>(axes[ay].count);
    sum[iy * nx + ix] += column[r];
    n[iy * nx + ix] += 1;
  }
  m.value.resize(nx * ny);
  for (std::size_t c = 0; c < nx * ny; ++c) m.value[c] = n[c] > 0 ? sum[c] / n[c] : kNaN;
  return m;
}

std::vector<double> usable_counts(const SweepData& d, const std::string& solver) {
  std::vector<double> b = d.throws.column(solver + "_bounces");
  const std::vector<double> o = d.throws.column(solver + "_outcome");
  for (std::size_t i = 0; i < b.size(); ++i)
    if (o[i] == kOutcomeFailed || o[i] == kOutcomeNotRun) b[i] = kNaN;
  return b;
}

std::vector<Figure> sweep_map_figures(const SweepData& d, const SweepMapOptions& o) {
  std::vector<Figure> figs;
  const auto& axes = d.design.axes;
  const std::size_t n = axes.size();
  const bool grid = d.design.kind == DesignKind::grid;
  const std::vector<std::string> solvers = solver_names(d.solvers);
  std::vector<std::pair<std::string, std::vector<double>>> counts;
  for (const auto& s : solvers) counts.emplace_back(s, usable_counts(d, s));
  std::vector<double> diff;
  if (solvers.size() == 2) {
    diff.resize(counts[0].second.size());
    for (std::size_t i = 0; i < diff.size(); ++i) diff[i] = counts[0].second[i] - counts[1].second[i];
  }
  auto axis = [&](std::size_t k) { return Axis{axes[k].key, axes[k].scale == AxisScale::log}; };
  auto other_keys = [&](std::size_t i, std::size_t j) {
    std::string s;
    for (std::size_t k = 0; k < n; ++k)
      if (k != i && k != j) s += (s.empty() ? "" : ", ") + axes[k].key;
    return s;
  };
  auto others = [&](std::size_t i, std::size_t j) {
    const std::string s = other_keys(i, j);
    return s.empty() ? std::string() : " (mean over " + s + ")";
  };
  const std::string pre = o.prefix + "_";

  if (n == 1) {
    std::vector<CountSeries> series;
    for (const auto& [s, c] : counts) {
      CountSeries cs{word(s), d.throws.column(axes[0].key), c, {}};
      for (const double outcome : d.throws.column(s + "_outcome")) cs.failed.push_back(outcome == kOutcomeFailed ? 1 : 0);
      series.push_back(std::move(cs));
    }
    if (grid) {
      figs.push_back(count_curve(pre + "bounces", "Bounce count against " + axes[0].key, axis(0), series));
    } else {
      for (const auto& [s, c] : counts) {
        const std::vector<double> zero(c.size(), 0.0);
        const auto [lo, hi] = finite_range(c);
        figs.push_back(scatter(pre + "bounces_" + s, "Bounce count (" + word(s) + ") against " + axes[0].key,
                               d.throws.column(axes[0].key), c, c, axis(0), Axis{"bounces", false}, "1",
                               count_scale(lo, hi, "bounces")));
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const std::string pair = "_" + std::to_string(i) + "_" + std::to_string(j);
      for (const auto& [s, c] : counts) {
        const std::string title = "Bounce count, " + word(s) + ": " + axes[j].key + " against " + axes[i].key + others(i, j);
        const auto [lo, hi] = finite_range(c);
        if (grid) {
          const GridMap m = grid_mean(d, c, i, j);
          std::vector<Contour> levels;
          for (int k : threshold_counts(lo, hi, o.max_contour_levels))
            levels.push_back({m, k + 0.5, std::to_string(k) + " | " + std::to_string(k + 1) + " bounces"});
          figs.push_back(heat_map(pre + "bounces_" + s + pair, title, m, axis(i), axis(j), "1", count_scale(lo, hi, "bounces"),
                                  levels));
        } else {
          figs.push_back(scatter(pre + "bounces_" + s + pair, title, d.throws.column(axes[i].key),
                                 d.throws.column(axes[j].key), c, axis(i), axis(j), "1", count_scale(lo, hi, "bounces")));
        }
      }
      if (!diff.empty()) {
        const auto [lo, hi] = finite_range(diff);
        const double span = std::max(std::abs(lo), std::abs(hi));
        const std::string title = "Real-time minus reference bounce count: " + axes[j].key + " against " + axes[i].key + others(i, j);
        if (grid && n == 2) {
          std::vector<double> absolute(diff.size());
          for (std::size_t k = 0; k < diff.size(); ++k) absolute[k] = std::abs(diff[k]);
          // The edge of agreement: where the |difference| passes ½.
          figs.push_back(heat_map(pre + "disagreement" + pair, title, grid_mean(d, diff, i, j), axis(i), axis(j), "1",
                                  diverging_scale(span, "real-time − reference bounces"),
                                  {{grid_mean(d, absolute, i, j), 0.5, "edge of agreement"}}));
        } else if (grid) {
          // Over the other axes a mean of signed differences cancels (+1 and −1 average to an
          // agreeing 0): the map is the share of those throws whose two counts differ, and its
          // contour the edge of agreement, between the cells where every throw agrees and the
          // rest (a share is 0 or at least one over the other axes' throws, far above 1e-9).
          std::vector<double> differs(diff.size());
          for (std::size_t k = 0; k < diff.size(); ++k) differs[k] = std::isfinite(diff[k]) ? (diff[k] != 0 ? 1.0 : 0.0) : kNaN;
          const GridMap share = grid_mean(d, differs, i, j);
          figs.push_back(heat_map(pre + "disagreement" + pair,
                                  "Share of throws with differing counts: " + axes[j].key + " against " + axes[i].key +
                                      " (over " + other_keys(i, j) + ")",
                                  share, axis(i), axis(j), "1", continuous_scale(0, 1, "share differing"),
                                  {{share, 1e-9, "all agree | some differ"}}));
        } else {
          figs.push_back(scatter(pre + "disagreement" + pair, title, d.throws.column(axes[i].key),
                                 d.throws.column(axes[j].key), diff, axis(i), axis(j), "1",
                                 diverging_scale(span, "real-time − reference bounces")));
        }
      }
    }
  for (auto c = o.columns.begin(); c != o.columns.end(); ++c) {
    const std::string& column = *c;
    if (!d.throws.has_column(column))
      throw_input_error(column, 0, "", "no such column in the sweep's table (the columns are listed in its /throws)");
    // A column mapped twice would write its figures twice under the same names.
    if (std::find(o.columns.begin(), c, column) != c)
      throw_input_error("--map " + column, 0, "", "given more than once (each column is mapped once)");
    const std::vector<double> v = d.throws.column(column);
    const auto [lo, hi] = finite_range(v);
    std::string stem = pre;
    for (char ch : column) stem += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
    if (n == 1)
      figs.push_back(scatter(stem, column + " against " + axes[0].key, d.throws.column(axes[0].key), v, v, axis(0),
                             Axis{column, false}, column_unit(column), continuous_scale(lo, hi, column)));
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        const std::string title = column + ": " + axes[j].key + " against " + axes[i].key + (grid ? others(i, j) : "");
        const std::string name = stem + "_" + std::to_string(i) + "_" + std::to_string(j);
        if (grid)
          figs.push_back(heat_map(name, title, grid_mean(d, v, i, j), axis(i), axis(j), column_unit(column),
                                  continuous_scale(lo, hi, column), {}));
        else
          figs.push_back(scatter(name, title, d.throws.column(axes[i].key), d.throws.column(axes[j].key), v, axis(i), axis(j),
                                 column_unit(column), continuous_scale(lo, hi, column)));
      }
  }
  if (!grid) {
    figs.push_back(histogram(pre + "bounce_histogram", "Bounce counts over the " + std::to_string(d.throws.rows()) + " throws",
                             "bounces", [&] {
                               std::vector<std::pair<std::string, std::vector<double>>> s;
                               for (const auto& [name, c] : counts) s.emplace_back(word(name), c);
                               return s;
                             }()));
    if (!diff.empty())
      figs.push_back(histogram(pre + "disagreement_histogram", "Real-time minus reference bounce count, per throw",
                               "real-time − reference bounces", {{"throws", diff}}));
  }
  return figs;
}

}  // namespace stoneskip
