#include "reports/waves/waves_figures.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "reports/common/plot.hpp"
#include "reports/waves/kd_label.hpp"

namespace stoneskip {

namespace {

// One line style per stencil, the same in every figure.
std::string style(const std::string& stencil) {
  if (stencil == "five_point") return "lc rgb '#1f77b4' pt 7";
  if (stencil == "nine_point_half") return "lc rgb '#ff7f0e' pt 5";
  if (stencil == "nine_point_isotropic") return "lc rgb '#2ca02c' pt 9";
  if (stencil == "paper_eq11") return "lc rgb '#d62728' pt 11 dt 2";
  return "lc rgb '#7f7f7f' pt 13";
}

std::string title_of(const std::string& stencil) {
  std::string t = stencil;
  std::replace(t.begin(), t.end(), '_', ' ');
  return t;
}

// A stencil's clause in the plot command (comma-separated), for its table `name`.
void add_stencil_clause(std::ostringstream& p, bool& first, const std::string& name, const std::string& stencil,
                        const char* with, const char* columns = "1:2") {
  p << (first ? "" : ", ") << "'" << name << ".dat' u " << columns << " w " << with << " lw 2 " << style(stencil)
    << " t '" << title_of(stencil) << "'";
  first = false;
}

// Adds a stencil's curve: table `table` of r as stored, and its clause in the plot command.
void add_stencil_curve(Figure& f, std::ostringstream& p, bool& first, const std::string& name, const Record& r,
                       const std::string& table, const std::string& stencil, const char* with, const char* columns = "1:2") {
  add_stored_table(f, name, r, table);
  add_stencil_clause(p, first, name, stencil, with, columns);
}

const char* kLogLog = "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\nset grid\nset key outside right\n";

}  // namespace

Figure consistency_figure(const Record& c) {
  Figure f;
  f.name = "consistency_leading_error";
  f.title = "Leading truncation error coefficient of each consistent stencil against the direction of the wave";
  std::ostringstream p;
  p << "set xlabel 'direction θ of the wave vector (degrees)'\nset ylabel 'leading error coefficient s_2(θ)  (× d^2 ∂^4)'\n"
       "set grid\nset key outside right\nset xrange [0:90]\nset xtics 15\nplot ";
  bool first = true;
  for (const auto& name : c.strings("stencils")) {
    const Record& s = c.at(name);
    if (s.at("verdict").text("verdict") != "consistent") continue;
    add_stencil_curve(f, p, first, f.name + "_" + name, s, "leading_error", name, "l");
  }
  f.script = p.str();
  return f;
}

Figure convergence_figure(const Record& c, const std::string& kind) {
  Figure f;
  f.name = "convergence_" + kind;
  const bool time = kind == "time";
  std::ostringstream title;
  if (kind == "space")
    title << "Space error alone: exact semi-discrete solution of each stencil against the exact continuum solution (RMS over the domain)";
  else if (time)
    title << "Time error alone: leapfrog against the stencil's exact semi-discrete solution on a " << c.number("time_grid")
          << " × " << c.number("time_grid") << " grid (RMS)";
  else if (kind.rfind("walls_", 0) == 0)
    title << "The square walled in (" << (kind == "walls_reflecting" ? "reflecting walls" : "fixed rims")
          << "), both refined together at σ = " << c.number("both_sigma") << " to t = " << c.number("walls_t_end_s")
          << " s: leapfrog against the exact walled solution (RMS)";
  else
    title << "Both refined together at σ = cΔt/d = " << c.number("both_sigma")
          << ": leapfrog against the exact continuum solution (RMS)";
  f.title = title.str();
  std::ostringstream p;
  p << kLogLog << "set xlabel '" << (time ? "time step Δt (s)" : "cell size d (m)") << "'\nset ylabel 'RMS error (m)'\nplot ";
  double anchor_h = 0, anchor_e = 0, hmin = 1e300, hmax = 0;
  bool first = true;
  const auto names = c.strings("stencils");
  for (const auto& name : names) {
    const Table& pts = c.at(name).at(kind).table("points");
    const auto h = pts.column("h"), e = pts.column("l2_error_m"), m = pts.column("max_error_m");
    Table t{{time ? "dt_s" : "cell_m", "l2_error_m", "max_error_m"}, {}};
    for (std::size_t i = 0; i < h.size(); ++i) {
      t.add_row({h[i], e[i], m[i]});
      hmin = std::min(hmin, h[i]);
      hmax = std::max(hmax, h[i]);
    }
    if (name == names.front() && !h.empty()) {
      anchor_h = h.back();
      anchor_e = e.back();
    }
    f.tables.emplace_back(f.name + "_" + name, t);  // its source: below
    add_stencil_clause(p, first, f.name + "_" + name, name, "lp");
    const std::string stored = c.at(name).at(kind).path() + "/points";  // columns 1:2 are h, l2_error_m as stored
    TableSource src;
    src.table = stored;
    src.x_column = "h";
    src.y_column = "l2_error_m";
    f.sources.push_back({f.name + "_" + name, {src}});
  }
  if (anchor_h > 0) {  // a slope-2 guide through the first stencil's finest point, shifted down
    Table g{{"h", "guide"}, {}};
    for (double h : {hmin, hmax}) g.add_row({h, 0.3 * anchor_e * (h / anchor_h) * (h / anchor_h)});
    f.tables.emplace_back(f.name + "_slope2", g);
    f.sources.push_back({f.name + "_slope2", {}});  // a guide, computed here: y ∝ h²
    DerivedSeries guide;
    guide.kind = DerivedSeries::Kind::power_law;
    guide.exponent = 2;
    f.derived.push_back({f.name + "_slope2", guide});
    p << ", '" << f.name << "_slope2.dat' u 1:2 w l lc rgb 'black' dt 3 t 'slope 2'";
  }
  f.script = p.str();
  return f;
}

Figure isotropy_polar_figure(const Record& iso) {
  Figure f;
  f.name = "isotropy_polar";
  const auto kds = iso.table("polar_kd").column("kd");
  std::string at;
  for (std::size_t k = 0; k < kds.size(); ++k) at += (k ? ", " : "") + pi_fraction(kds[k]);
  f.title = "Phase speed c_h/c of a plane wave against its direction, from each stencil's symbol, at kd = " + at +
            " (radius: c_h/c; a perfect scheme is the circle of radius 1)";
  f.width_px = 500 * static_cast<int>(std::max<std::size_t>(kds.size(), 1));
  f.height_px = 560;
  std::ostringstream p;
  p << "set multiplot layout 1," << kds.size()
    << "\nset polar\nset angles degrees\nset size ratio -1\nunset border\nunset xtics\nunset ytics\n"
       "set grid polar 45\nset key outside bottom center horizontal\nset rtics format '%g' scale 0.3 offset 0,0.8\n";
  const auto names = iso.strings("stencils");
  for (std::size_t k = 0; k < kds.size(); ++k) {
    double lo = 1e300, hi = -1e300;
    for (const auto& name : names)
      for (double v : iso.at(name).table("polar_" + std::to_string(k)).column("speed_ratio"))
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    hi = std::max(hi, 1.0);
    const double span = std::max(hi - lo, 1e-12);
    // Tics at round values (1, 2 or 5 × 10^n apart, about half the curves' spread), not at the range's
    // odd start: labels such as 0.995 and 1, which a reader can place.
    const double raw = span / 2, decade = std::pow(10.0, std::floor(std::log10(raw)));
    const double step = decade * (raw / decade < 1.5 ? 1 : raw / decade < 3.5 ? 2 : raw / decade < 7.5 ? 5 : 10);
    const double r0 = lo - 0.6 * span;
    p << "set title 'kd = " << pi_fraction(kds[k]) << "'\nset rrange [" << r0 << ":" << hi + 0.05 * span
      << "]\nset rtics " << std::ceil(r0 / step) * step << ", " << step << "\nset trange [0:360]\nplot ";
    bool first = true;
    for (const auto& name : names)
      add_stencil_curve(f, p, first, f.name + "_" + name + "_" + std::to_string(k), iso.at(name), "polar_" + std::to_string(k),
                        name, "l");
    p << ", 1 w l lc rgb 'black' dt 3 t 'exact'\n";
  }
  p << "unset multiplot\n";
  f.script = p.str();
  return f;
}

Figure isotropy_spread_figure(const Record& iso) {
  Figure f;
  f.name = "isotropy_spread";
  f.title = "Spread over direction (max − min) of the relative phase-speed error, against kd (from the symbols)";
  const double kd = iso.number("table_kd");
  std::ostringstream p;
  p << kLogLog << "set xlabel 'kd (radians per cell; π/kd cells per half wavelength)'\nset ylabel 'spread of (c_h − c)/c over θ'\n"
    << "set arrow from first " << kd << ", graph 0 to first " << kd << ", graph 1 nohead dt 3 lc rgb 'gray'\n"
    << "set label 'kd = " << pi_fraction(kd) << "' at first " << kd << ", graph 0.95 offset 0.5,0\nplot ";
  bool first = true;
  for (const auto& name : iso.strings("stencils")) {
    Table t = iso.at(name).table("spread");
    for (std::size_t r = 0; r < t.rows(); ++r) t.values[2 * r + 1] = std::max(t.values[2 * r + 1], 1e-17);  // log axis
    add_computed_table(f, f.name + "_" + name, t, iso.at(name).path() + "/spread with each spread raised to at least 1e-17 for the log axis");
    add_stencil_clause(p, first, f.name + "_" + name, name, "l");
  }
  f.script = p.str();
  return f;
}

Figure isotropy_measured_figure(const Record& iso) {
  Figure f;
  f.name = "isotropy_measured";
  const auto kds = iso.table("measured_kd").column("kd");
  f.title = "Relative phase-speed error divided by (kd)², against direction: measured from simulations of single "
            "Fourier modes (points) and predicted by the symbol (lines)";
  f.width_px = 650 * static_cast<int>(std::max<std::size_t>(kds.size(), 1));
  f.height_px = 620;
  std::ostringstream p;
  p << "set multiplot layout 1," << kds.size() << "\nset grid\nset key below maxrows 3\nset xlabel 'direction θ (degrees)'\n"
       "set ylabel '(c_h − c)/c  ÷ (kd)^2'\nset xrange [0:45]\n";
  for (std::size_t k = 0; k < kds.size(); ++k) {
    p << "set title 'kd ≈ " << pi_fraction(kds[k]) << ", σ = " << iso.number("measured_sigma") << ", "
      << iso.number("measured_grid") << "^2 grid'\nplot ";
    bool first = true;
    for (const auto& name : iso.strings("stencils")) {
      const Record& s = iso.at(name);
      const Table& m = s.table("measured");
      Table pts{{"theta_deg", "measured_error_per_kd2", "semi_discrete_error_per_kd2", "fully_discrete_error_per_kd2", "kd"}, {}};
      const auto target = m.column("kd_target"), kd = m.column("kd"), th = m.column("theta_deg"),
                 me = m.column("measured_error"), se = m.column("semi_discrete_error"), fe = m.column("fully_discrete_error");
      for (std::size_t i = 0; i < target.size(); ++i)
        if (target[i] == kds[k])
          pts.add_row({th[i], me[i] / (kd[i] * kd[i]), se[i] / (kd[i] * kd[i]), fe[i] / (kd[i] * kd[i]), kd[i]});
      const std::string tn = f.name + "_" + name + "_" + std::to_string(k);
      add_computed_table(f, tn, pts, s.path() + "/measured: the rows at this kd, each error divided by kd²");
      add_stored_table(f, tn + "_symbol", s, "symbol_line_" + std::to_string(k));
      p << (first ? "" : ", ") << "'" << tn << "_symbol.dat' u 1:2 w l lw 2 " << style(name) << " t '" << title_of(name)
        << " (symbol)', '" << tn << ".dat' u 1:2 w p ps 1.3 " << style(name) << " t '" << title_of(name)
        << " (simulation)'";
      first = false;
    }
    p << "\n";
  }
  p << "unset multiplot\n";
  f.script = p.str();
  return f;
}

Figure ring_figure(const Record& iso) {
  Figure f;
  f.name = "ring_radius";
  f.title = "Ring test: radius of the outgoing wavefront of a spreading bump against direction, minus the exact "
            "(continuum) wavefront radius, in cells";
  std::ostringstream p;
  p << "set grid\nset key outside right\nset xlabel 'direction θ (degrees)'\nset ylabel 'wavefront radius − exact (cells)'\n"
       "set xrange [0:90]\nset xtics 15\nplot ";
  bool first = true;
  for (const auto& name : iso.strings("stencils"))
    add_stencil_curve(f, p, first, f.name + "_" + name, iso.at(name), "ring", name, "lp", "1:4");
  f.script = p.str();
  return f;
}

Figure stability_figure(const Record& st) {
  Figure f;
  f.name = "stability_limits";
  f.title = "Largest stable Courant number σ = cΔt/d against μΔt: computed from the amplification factors (lines), "
            "measured by running (points), and Lengyel's printed bound (black dashes)";
  std::ostringstream p;
  p << "set grid\nset key outside right\nset xlabel 'μΔt'\nset ylabel 'largest stable σ = cΔt/d'\nset yrange [0.5:1.2]\nplot ";
  bool first = true;
  for (const auto& name : st.strings("stencils")) {
    const Record& s = st.at(name);
    add_stencil_curve(f, p, first, f.name + "_" + name, s, "limit_curve", name, "l");
    const std::string mn = f.name + "_" + name + "_measured";
    add_stored_table(f, mn, s, "checks");
    p << ", '" << mn << ".dat' u 1:3 w p ps 1.5 " << style(name) << " notitle";
  }
  const Record& l = st.at("lengyel");
  add_stored_table(f, f.name + "_lengyel", l, "bound_curve");
  Table ce{{"mu_dt", "sigma"}, {}};
  ce.add_row({l.number("mu_dt"), l.number("sigma")});
  add_computed_table(f, f.name + "_counterexample", ce, l.path() + ": the point (mu_dt, sigma) of the counter-example");
  std::ostringstream growth;
  growth.precision(3);
  growth << l.number("measured_growth_per_step");
  p << ", '" << f.name << "_lengyel.dat' u 1:2 w l lw 2 lc rgb 'black' dt 2 t 'Lengyel bound ½√(μΔt+2)', '" << f.name
    << "_counterexample.dat' u 1:2 w p pt 3 ps 2.5 lc rgb 'black' t 'counter-example (grows ×" << growth.str() << "/step)'";
  f.script = p.str();
  return f;
}

Figure work_precision_figure(const Record& sp) {
  Figure f;
  f.name = "work_precision";
  f.title = "Speed against error on the same physical problem: RMS error against CPU time of the leapfrog run, every "
            "grid and Courant number (points) and the best error for the time (lines)";
  std::ostringstream p;
  p << kLogLog << "set xlabel 'CPU time of the run (s, thread CPU)'\nset ylabel 'RMS error against the exact solution (m)'\nplot ";
  bool first = true;
  for (const auto& name : sp.strings("stencils")) {
    const Table& pts = sp.at(name).table("points");
    const auto cpu = pts.column("cpu_s"), l2 = pts.column("l2_error_m");
    std::vector<std::size_t> order(cpu.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return cpu[a] < cpu[b]; });
    Table all{{"cpu_s", "l2_error_m"}, {}}, front{{"cpu_s", "l2_error_m"}, {}};
    double best = 1e300;
    for (std::size_t i : order) {
      all.add_row({std::max(cpu[i], 1e-6), l2[i]});
      if (l2[i] < best) {
        best = l2[i];
        front.add_row({std::max(cpu[i], 1e-6), l2[i]});
      }
    }
    const std::string tn = f.name + "_" + name;
    add_computed_table(f, tn, all, sp.at(name).path() + "/points: (cpu_s, l2_error_m), CPU raised to at least 1 µs for the log axis");
    add_computed_table(f, tn + "_front", front, sp.at(name).path() + "/points: the runs more accurate than every cheaper one (the Pareto front)");
    p << (first ? "" : ", ") << "'" << tn << ".dat' u 1:2 w p " << style(name) << " notitle, '" << tn
      << "_front.dat' u 1:2 w l lw 2 " << style(name) << " t '" << title_of(name) << "'";
    first = false;
  }
  f.script = p.str();
  return f;
}

}  // namespace stoneskip
