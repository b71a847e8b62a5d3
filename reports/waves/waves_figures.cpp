#include "reports/waves/waves_figures.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace stoneskip {

namespace {

constexpr double kDeg = 180 / M_PI;

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

Table table(std::vector<std::string> columns) { return Table{std::move(columns), {}}; }

// Adds a stencil's curve: its table, and its clause in the plot command (comma-separated).
void add_stencil_curve(Figure& f, std::ostringstream& p, bool& first, const std::string& name, Table t,
                       const std::string& stencil, const char* with) {
  f.tables.emplace_back(name, std::move(t));
  p << (first ? "" : ", ") << "'" << name << ".dat' u 1:2 w " << with << " lw 2 " << style(stencil) << " t '"
    << title_of(stencil) << "'";
  first = false;
}

// The distinct values of a list, in order of first appearance.
std::vector<double> distinct(const std::vector<double>& values) {
  std::vector<double> out;
  for (double v : values)
    if (std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
  return out;
}

const char* kLogLog = "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\nset grid\nset key outside right\n";

}  // namespace

Figure consistency_figure(const WaveStudies& s) {
  Figure f;
  f.name = "consistency_leading_error";
  f.title = "Leading truncation error coefficient of each consistent stencil against the direction of the wave";
  std::ostringstream p;
  p << "set xlabel 'direction θ of the wave vector (degrees)'\nset ylabel 'leading error coefficient s_2(θ)  (× d^2 ∂^4)'\n"
       "set grid\nset key outside right\nset xrange [0:90]\nset xtics 15\nplot ";
  bool first = true;
  for (const auto& c : s.consistency) {
    if (!c.consistent) continue;
    Table t = table({"theta_deg", "leading_error"});
    for (std::size_t i = 0; i < c.theta_rad.size(); ++i) t.add_row({c.theta_rad[i] * kDeg, c.leading_error[i]});
    add_stencil_curve(f, p, first, f.name + "_" + c.stencil, std::move(t), c.stencil, "l");
  }
  f.script = p.str();
  return f;
}

Figure convergence_figure(const WaveStudies& s, const std::string& kind) {
  Figure f;
  f.name = "convergence_" + kind;
  const bool time = kind == "time";
  if (kind == "space")
    f.title = "Space error alone: exact semi-discrete solution of each stencil against the exact continuum solution (RMS over the domain)";
  else if (time)
    f.title = "Time error alone: leapfrog against the stencil's exact semi-discrete solution on a 64 × 64 grid (RMS)";
  else
    f.title = "Both refined together at σ = cΔt/d = 0.5: leapfrog against the exact continuum solution (RMS)";
  std::ostringstream p;
  p << kLogLog << "set xlabel '" << (time ? "time step Δt (s)" : "cell size d (m)") << "'\nset ylabel 'RMS error (m)'\nplot ";
  double anchor_h = 0, anchor_e = 0, hmin = 1e300, hmax = 0;
  bool first = true;
  for (const auto& c : s.convergence) {
    const ConvergenceSequence& seq = kind == "space" ? c.space : time ? c.time : c.both;
    Table t = table({time ? "dt_s" : "cell_m", "l2_error_m", "max_error_m"});
    for (const auto& pt : seq.points) {
      t.add_row({pt.h, pt.l2_m, pt.max_m});
      hmin = std::min(hmin, pt.h);
      hmax = std::max(hmax, pt.h);
    }
    if (c.stencil == "five_point" && !seq.points.empty()) {
      anchor_h = seq.points.back().h;
      anchor_e = seq.points.back().l2_m;
    }
    add_stencil_curve(f, p, first, f.name + "_" + c.stencil, std::move(t), c.stencil, "lp");
  }
  if (anchor_h > 0) {  // a slope-2 guide through the five-point stencil's finest point, shifted down
    Table g = table({"h", "guide"});
    for (double h : {hmin, hmax}) g.add_row({h, 0.3 * anchor_e * (h / anchor_h) * (h / anchor_h)});
    f.tables.emplace_back(f.name + "_slope2", g);
    p << ", '" << f.name << "_slope2.dat' u 1:2 w l lc rgb 'black' dt 3 t 'slope 2'";
  }
  f.script = p.str();
  return f;
}

Figure isotropy_polar_figure(const WaveStudies& s) {
  Figure f;
  f.name = "isotropy_polar";
  f.title = "Phase speed c_h/c of a plane wave against its direction, from each stencil's symbol, at kd = π/8, π/4, π/2 "
            "(radius: c_h/c; a perfect scheme is the circle of radius 1)";
  f.width_px = 1500;
  f.height_px = 560;
  std::ostringstream p;
  p << "set multiplot layout 1,3\nset polar\nset angles degrees\nset size ratio -1\nunset border\nunset xtics\nunset ytics\n"
       "set grid polar 45\nset key bottom center horizontal\nset rtics format '%.3f' scale 0.3\n";
  std::vector<double> all_kd;
  for (const auto& c : s.isotropy_curves) all_kd.push_back(c.kd);
  const std::vector<double> kds = distinct(all_kd);
  for (std::size_t k = 0; k < kds.size(); ++k) {
    double lo = 1e300, hi = -1e300;
    for (const auto& c : s.isotropy_curves)
      if (c.kd == kds[k])
        for (double e : c.error) lo = std::min(lo, 1 + e), hi = std::max(hi, 1 + e);
    hi = std::max(hi, 1.0);
    const double span = hi - lo;
    const double rmin = lo - 0.6 * span, rmax = hi + 0.05 * span;
    const int denom = static_cast<int>(std::lround(M_PI / kds[k]));
    p << "set title 'kd = π/" << denom << "'\nset rrange [" << rmin << ":" << rmax << "]\nset rtics " << span / 2
      << "\nset trange [0:360]\nplot ";
    bool first = true;
    for (const auto& c : s.isotropy_curves) {
      if (c.kd != kds[k]) continue;
      Table t = table({"theta_deg", "speed_ratio"});
      for (std::size_t i = 0; i < c.theta_rad.size(); ++i) t.add_row({c.theta_rad[i] * kDeg, 1 + c.error[i]});
      add_stencil_curve(f, p, first, f.name + "_" + c.stencil + "_" + std::to_string(k), std::move(t), c.stencil, "l");
    }
    p << ", 1 w l lc rgb 'black' dt 3 t 'exact'\n";
  }
  p << "unset multiplot\n";
  f.script = p.str();
  return f;
}

Figure isotropy_spread_figure(const WaveStudies& s) {
  Figure f;
  f.name = "isotropy_spread";
  f.title = "Spread over direction (max − min) of the relative phase-speed error, against kd (from the symbols)";
  std::ostringstream p;
  p << kLogLog << "set xlabel 'kd (radians per cell; π/kd cells per half wavelength)'\nset ylabel 'spread of (c_h − c)/c over θ'\n"
       "set arrow from first pi/8, graph 0 to first pi/8, graph 1 nohead dt 3 lc rgb 'gray'\nset label 'kd = π/8' at first pi/8, graph 0.95 offset 0.5,0\nplot ";
  bool first = true;
  for (const auto& c : s.spread_curves) {
    Table t = table({"kd", "spread"});
    for (std::size_t i = 0; i < c.kd.size(); ++i) t.add_row({c.kd[i], std::max(c.spread[i], 1e-17)});
    add_stencil_curve(f, p, first, f.name + "_" + c.stencil, std::move(t), c.stencil, "l");
  }
  f.script = p.str();
  return f;
}

Figure isotropy_measured_figure(const WaveStudies& s) {
  Figure f;
  f.name = "isotropy_measured";
  f.title = "Relative phase-speed error divided by (kd)², against direction: measured from simulations of single "
            "Fourier modes (points) and predicted by the symbol (lines), at kd ≈ π/8 (left) and π/4 (right)";
  f.width_px = 1300;
  f.height_px = 620;
  std::ostringstream p;
  p << "set multiplot layout 1,2\nset grid\nset key below maxrows 3\nset xlabel 'direction θ (degrees)'\n"
       "set ylabel '(c_h − c)/c  ÷ (kd)^2'\nset xrange [0:45]\n";
  std::vector<double> all_kd;
  for (const auto& m : s.measured_isotropy) all_kd.push_back(m.kd_target);
  const std::vector<double> kds = distinct(all_kd);
  for (std::size_t k = 0; k < kds.size(); ++k) {
    const int denom = static_cast<int>(std::lround(M_PI / kds[k]));
    p << "set title 'kd ≈ π/" << denom << ", σ = " << s.measured_sigma << ", " << s.measured_grid << "^2 grid'\nplot ";
    bool first = true;
    for (const auto& m : s.measured_isotropy) {
      if (m.kd_target != kds[k]) continue;
      Table pts = table({"theta_deg", "measured_error_per_kd2", "semi_discrete_error_per_kd2", "fully_discrete_error_per_kd2", "kd"});
      for (const auto& q : m.points)
        pts.add_row({q.theta_rad * kDeg, q.measured_error / (q.kd * q.kd), q.semi_discrete_error / (q.kd * q.kd),
                     q.fully_discrete_error / (q.kd * q.kd), q.kd});
      Table line = table({"theta_deg", "symbol_error_per_kd2"});
      for (int a = 0; a <= 90; ++a) {
        const double th = M_PI / 4 * a / 90;
        for (const auto& st : s.stencils)
          if (st.name == m.stencil) line.add_row({th * kDeg, phase_speed_error(st, kds[k], th) / (kds[k] * kds[k])});
      }
      const std::string name = f.name + "_" + m.stencil + "_" + std::to_string(k);
      f.tables.emplace_back(name, pts);
      f.tables.emplace_back(name + "_symbol", line);
      p << (first ? "" : ", ") << "'" << name << "_symbol.dat' u 1:2 w l lw 2 " << style(m.stencil) << " t '"
        << title_of(m.stencil) << " (symbol)', '" << name << ".dat' u 1:2 w p ps 1.3 " << style(m.stencil) << " t '"
        << title_of(m.stencil) << " (simulation)'";
      first = false;
    }
    p << "\n";
  }
  p << "unset multiplot\n";
  f.script = p.str();
  return f;
}

Figure ring_figure(const WaveStudies& s) {
  Figure f;
  f.name = "ring_radius";
  f.title = "Ring test: radius of the outgoing wavefront of a spreading bump against direction, minus the exact "
            "(continuum) wavefront radius, in cells";
  std::ostringstream p;
  p << "set grid\nset key outside right\nset xlabel 'direction θ (degrees)'\nset ylabel 'wavefront radius − exact (cells)'\n"
       "set xrange [0:90]\nset xtics 15\nplot ";
  bool first = true;
  for (const auto& [name, r] : s.rings) {
    Table t = table({"theta_deg", "front_radius_m", "reference_front_radius_m", "difference_cells"});
    for (std::size_t i = 0; i < r.theta_rad.size(); ++i)
      t.add_row({r.theta_rad[i] * kDeg, r.front_radius_m[i], r.reference_front_radius_m[i],
                 (r.front_radius_m[i] - r.reference_front_radius_m[i]) / r.cell_m});
    const std::string tn = f.name + "_" + name;
    f.tables.emplace_back(tn, t);
    p << (first ? "" : ", ") << "'" << tn << ".dat' u 1:4 w lp lw 2 " << style(name) << " t '" << title_of(name) << "'";
    first = false;
  }
  f.script = p.str();
  return f;
}

Figure stability_figure(const WaveStudies& s) {
  Figure f;
  f.name = "stability_limits";
  f.title = "Largest stable Courant number σ = cΔt/d against μΔt: computed from the amplification factors (lines), "
            "measured by running (points), and Lengyel's printed bound (black dashes)";
  std::ostringstream p;
  p << "set grid\nset key outside right\nset xlabel 'μΔt'\nset ylabel 'largest stable σ = cΔt/d'\nset yrange [0.5:1.2]\nplot ";
  bool first = true;
  for (const auto& c : s.stability_curves) {
    Table t = table({"mu_dt", "sigma_limit"});
    for (std::size_t i = 0; i < c.mu_dt.size(); ++i) t.add_row({c.mu_dt[i], c.limit[i]});
    const std::string name = f.name + "_" + c.stencil;
    f.tables.emplace_back(name, t);
    Table m = table({"mu_dt", "measured_sigma_limit"});
    for (const auto& k : s.stability_checks)
      if (k.stencil == c.stencil) m.add_row({k.mu_dt, k.measured_limit});
    f.tables.emplace_back(name + "_measured", m);
    p << (first ? "" : ", ") << "'" << name << ".dat' u 1:2 w l lw 2 " << style(c.stencil) << " t '" << title_of(c.stencil)
      << "', '" << name << "_measured.dat' u 1:2 w p ps 1.5 " << style(c.stencil) << " notitle";
    first = false;
  }
  Table l = table({"mu_dt", "lengyel_bound"});
  for (int i = 0; i <= 38; ++i) l.add_row({0.05 * i, lengyel_bound(0.05 * i)});
  f.tables.emplace_back(f.name + "_lengyel", l);
  Table ce = table({"mu_dt", "sigma"});
  ce.add_row({0.5, 0.75});
  f.tables.emplace_back(f.name + "_counterexample", ce);
  p << ", '" << f.name << "_lengyel.dat' u 1:2 w l lw 2 lc rgb 'black' dt 2 t 'Lengyel bound ½√(μΔt+2)', '" << f.name
    << "_counterexample.dat' u 1:2 w p pt 3 ps 2.5 lc rgb 'black' t 'counter-example (grows ×"
    << std::lround(100 * s.lengyel_counterexample.growth_per_step) / 100.0 << "/step)'";
  f.script = p.str();
  return f;
}

Figure work_precision_figure(const WaveStudies& s) {
  Figure f;
  f.name = "work_precision";
  f.title = "Speed against error on the same physical problem: RMS error against CPU time of the leapfrog run, every "
            "grid and Courant number (points) and the best error for the time (lines)";
  std::ostringstream p;
  p << kLogLog << "set xlabel 'CPU time of the run (s)'\nset ylabel 'RMS error against the exact solution (m)'\nplot ";
  bool first = true;
  for (const auto& [name, pts] : s.work) {
    Table t = table({"cpu_s", "l2_error_m", "max_error_m", "n", "sigma", "steps"});
    std::vector<WorkPoint> sorted = pts;
    std::sort(sorted.begin(), sorted.end(), [](const WorkPoint& a, const WorkPoint& b) { return a.cpu_s < b.cpu_s; });
    Table front = table({"cpu_s", "l2_error_m"});
    double best = 1e300;
    for (const auto& w : sorted) {
      t.add_row({std::max(w.cpu_s, 1e-6), w.l2_m, w.max_m, static_cast<double>(w.n), w.sigma, static_cast<double>(w.steps)});
      if (w.l2_m < best) {
        best = w.l2_m;
        front.add_row({std::max(w.cpu_s, 1e-6), w.l2_m});
      }
    }
    const std::string tn = f.name + "_" + name;
    f.tables.emplace_back(tn, t);
    f.tables.emplace_back(tn + "_front", front);
    p << (first ? "" : ", ") << "'" << tn << ".dat' u 1:2 w p " << style(name) << " notitle, '" << tn
      << "_front.dat' u 1:2 w l lw 2 " << style(name) << " t '" << title_of(name) << "'";
    first = false;
  }
  f.script = p.str();
  return f;
}

}  // namespace stoneskip
