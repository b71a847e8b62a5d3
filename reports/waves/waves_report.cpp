#include "reports/waves/waves_report.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

#include "reports/common/markdown.hpp"
#include "reports/waves/kd_label.hpp"
#include "reports/waves/waves_figures.hpp"
#include "verification/convergence/order_fit.hpp"

namespace stoneskip {

namespace {

std::string list_text(const std::vector<double>& v, int significant = 3, const std::string& sep = ", ") {
  std::string s;
  for (double x : v) s += (s.empty() ? "" : sep) + fmt(x, significant);
  return s.empty() ? "–" : s;
}

std::string grids_text(const Table& t) {
  const auto v = t.column("value");
  return v.empty() ? "–" : fmt(v.front()) + "² … " + fmt(v.back()) + "²";
}

// ---- findings at the top ----------------------------------------------------------------------

std::string findings_summary(const Record& secs) {
  const Record& cons = secs.at("consistency");
  const Record& conv = secs.at("convergence");
  const Record& iso = secs.at("isotropy");
  const Record& stab = secs.at("stability");
  std::ostringstream m;
  m << "## Findings\n\n";
  for (const auto& name : cons.strings("stencils")) {
    const Record& c = cons.at(name);
    m << "* " << code(name) << ": **" << c.at("verdict").text("verdict") << "**";
    if (conv.has_child(name)) {
      const Record& s = conv.at(name);
      m << "; space order " << order_interval(s.at("space").at("fit")) << " (" << s.at("space").at("fit").at("verdict").text("verdict")
        << "), time order " << order_interval(s.at("time").at("fit")) << " (" << s.at("time").at("fit").at("verdict").text("verdict") << ")";
      // The walled squares' space–time orders (stored since 7 December).
      if (conv.has("walls") && !conv.strings("walls").empty()) {
        m << "; in the walled square";
        for (const auto& b : conv.strings("walls")) {
          const Record& f = s.at("walls_" + b).at("fit");
          m << ", " << b << " " << order_interval(f) << " (" << f.at("verdict").text("verdict") << ")";
        }
      }
    }
    if (iso.has_child(name))
      m << "; phase-speed spread over direction at kd = " << pi_fraction(iso.number("table_kd")) << ": "
        << fmt(iso.at(name).number("spread_at_table_kd"), 3);
    if (stab.has_child(name)) {
      const Record& s = stab.at(name);
      m << "; stable for σ ≤ " << fmt(s.number("limit_at_zero_damping"), 6) << " at μΔt = 0, "
        << s.at("damping").text("verdict");
    }
    m << ".\n";
  }
  if (iso.has_child("roundest"))
    m << "* Roundest waves: " << code(iso.at("roundest").text("stencil")) << " — " << iso.at("roundest").text("why") << ".\n";
  m << "* Lengyel's damping-dependent bound: " << verdict_markdown(stab.at("lengyel").at("verdict")) << ".\n";
  m << "* Speed against error: " << verdict_markdown(secs.at("speed").at("answer")) << ".\n\n";
  return m.str();
}

// ---- 1. consistency ---------------------------------------------------------------------------

SectionOutput consistency_section(const Record& c) {
  SectionWriter w(c, "1. Consistency: does each stencil approximate the Laplacian?");
  w.text("A stencil is consistent with ∇² when, applied to a smooth surface, it gives ∇²z plus an error that vanishes as "
         "the cell size d → 0. In Fourier terms: applied to the wave e^{i k·x} it multiplies it by its *symbol*, which must "
         "behave like −|k|² at small kd. The framework fits the symbol along each direction θ by a polynomial in (kd)² on "
         "kd ≤ " + fmt(c.number("max_kd"), 3) + " (" + fmt(c.number("samples"), 3) + " samples per direction): the constant "
         "term is the response to a uniformly raised surface (it must be 0 — equal to the sum of the weights), the (kd)² "
         "coefficient must be −1, and the (kd)⁴ coefficient s₂(θ) is the leading error (s₂ d² ∂⁴ in the operator). A stencil "
         "is called consistent when both hold to " + fmt(c.number("tolerance"), 2) + ".");
  MarkdownTable t({"stencil", "weights (centre, edge, corner) × 1/d²", "weights sum", "constant term of symbol",
                   "Laplacian coefficient", "leading error s₂(θ), min … max", "verdict"});
  const Table& s = c.table("summary");
  const auto names = c.strings("stencils");
  for (std::size_t i = 0; i < names.size(); ++i) {
    auto col = [&](const char* k) { return s.column(k)[i]; };
    const bool ok = col("consistent") != 0;
    t.row({code(names[i]), fmt(col("centre")) + ", " + fmt(col("orth")) + ", " + fmt(col("diag")), fmt(col("weight_sum"), 6),
           fmt(col("constant_term"), 6), fmt(col("laplacian_coefficient"), 6),
           ok ? fmt(col("leading_error_min"), 4) + " … " + fmt(col("leading_error_max"), 4) : "–",
           c.at(names[i]).at("verdict").text("verdict")});
  }
  w.table(t);
  for (const auto& n : names) w.verdict(code(n), c.at(n).at("verdict"));
  w.end_list();
  w.lead("How to read it.", "An inconsistent stencil's extra term is a restoring force proportional to the height, with a "
                            "coefficient that grows like 1/d²: refining the grid makes it worse, not better (section 2 "
                            "shows what that does to convergence). For the consistent stencils the leading error depends on "
                            "the direction unless s₂(θ) is flat; the figure shows it for each.");
  w.figure(consistency_figure(c));
  return w.finish();
}

// ---- 2. convergence ---------------------------------------------------------------------------

// The page states each sequence's errors, its fit and its verdict from three stored copies: the
// points, the fit, and the verdict's own inputs (which `report render` re-judges). They must be
// one story: the fit is recomputed here from the stored errors (fit_order over the finest
// fit_points, as the study fits them; equal to round-off, 1e-12 relative, as the same code on the
// same doubles), and the verdict's inputs must be the fit's and the section's settings. Anything
// else is data edited by hand or from another run: RecordError, refused by `report render`.
void require_one_story(const Record& c, const std::string& name, const Record& q) {
  const auto same = [](double a, double b) {
    return a == b || (std::isnan(a) && std::isnan(b)) || std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b));
  };
  const auto fail = [&](const std::string& what, double stored, double expected) {
    std::ostringstream m;
    m.precision(17);
    m << q.path() << ": " << what << " is " << stored << " but " << expected << " follows from the stored data";
    throw RecordError(m.str());
  };
  const Table& pts = q.table("points");
  const auto& h_all = pts.column("h");
  const auto& e_all = pts.column("l2_error_m");
  const double fp = c.number("fit_points");
  const std::size_t first = fp > 0 && pts.rows() > static_cast<std::size_t>(fp) ? pts.rows() - static_cast<std::size_t>(fp) : 0;
  const OrderFit fit = fit_order(std::vector<double>(h_all.begin() + static_cast<long>(first), h_all.end()),
                                 std::vector<double>(e_all.begin() + static_cast<long>(first), e_all.end()));
  const Record& f = q.at("fit");
  const Record& v = f.at("verdict");
  if (fit.valid) {
    for (const auto& [key, x] : {std::pair<const char*, double>{"order", fit.order}, {"order_low", fit.order_low},
                                 {"order_high", fit.order_high}}) {
      if (!same(f.number(key), x)) fail(name + " fit " + key, f.number(key), x);
      if (!same(v.number(key), x)) fail(name + " verdict's " + key, v.number(key), x);
    }
    // The refinements at which the error grew, an input of the verdict (order_record.cpp).
    if (v.has_number("refinements")) {
      const double grew = fit.growing_refinements();
      if (!same(v.number("refinements"), double(fit.pairwise.size())))
        fail(name + " verdict's refinements", v.number("refinements"), double(fit.pairwise.size()));
      if (!same(v.number("growing_refinements"), grew)) fail(name + " verdict's growing_refinements", v.number("growing_refinements"), grew);
    }
  }
  for (const char* key : {"tolerance", "minimum_order", "expected_order"})
    if (!same(v.number(key), c.number(key))) fail(name + " verdict's " + key, v.number(key), c.number(key));
}

std::string lower_first(std::string s) {
  if (!s.empty() && s[0] == 'A') s[0] = 'a';
  return s;
}

// The initial surface as stored (verification/waves/wave_studies.cpp store_problem). Reports
// written before its centre, radius, direction and wavelength were stored said "a <kind> bump
// (amplitude, width) in the middle" whatever the kind: they keep that wording.
std::string initial_text(const Record& p) {
  const std::string kind = p.text("initial"), amp = fmt(p.number("amplitude_m") * 100, 3) + " cm";
  if (!p.has_number("x_m"))
    return "A " + kind + " bump (amplitude " + amp + ", width " + fmt(p.number("width_m"), 3) + " m) in the middle";
  const std::string at = " centred at (" + fmt(p.number("x_m"), 4) + ", " + fmt(p.number("y_m"), 4) + ") m";
  if (kind == "plane_wave")
    return "A standing plane wave (amplitude " + amp + ", wavelength " + fmt(p.number("wavelength_m"), 4) + " m, k at " +
           fmt(p.number("angle_deg"), 4) + "° from x)";
  if (kind == "ring")
    return "A ring (amplitude " + amp + ", radius " + fmt(p.number("radius_m"), 4) + " m, half-width " +
           fmt(p.number("width_m"), 3) + " m)" + at;
  if (kind == "gaussian")
    return "A Gaussian bump (amplitude " + amp + ", e-folding radius " + fmt(p.number("width_m"), 3) + " m)" + at;
  return "A " + kind + " disturbance (amplitude " + amp + ")" + at;
}

// The walled squares (reports written before 7 December have none): the "both" sequence again with
// the square's edges made walls, against the walled references (solvers/spectral/walled_wave.hpp).
void walls_subsection(SectionWriter& w, const Record& c) {
  if (!c.has("walls") || c.strings("walls").empty()) return;
  const auto walls = c.strings("walls");
  const Record& p = c.at("problem");
  std::string named;
  for (const auto& b : walls) named += (named.empty() ? "" : ", ") + b;
  const double travel = p.number("wave_speed_m_s") * c.number("walls_t_end_s");
  w.lead("Walled squares.",
         "The scene's pond has walls, not the periodic square's wrap-around. So the *both* sequence is run again with the "
         "square's edges made walls (" + named + "), the same stencils, grids " + grids_text(c.table("both_grids")) +
             " and σ = " + fmt(c.number("both_sigma")) + ", to t = " + fmt(c.number("walls_t_end_s")) +
             " s, in which a wave travels " + fmt(travel, 3) + " m, " + fmt(travel / p.number("length_m"), 3) +
             " times the square's side. A reflecting wall is made by ghost cells "
             "that mirror the edge cells, which puts it half a cell beyond the edge points: the grid's points stand at the "
             "cell centres, (i + ½)L/n, so that the walls are at 0 and L on every grid. A fixed rim is made by ghost cells "
             "that hold 0, one cell beyond the edge points: the n − 1 points stand at (i + 1)L/n. The exact solution is a "
             "cosine series (reflecting) or a sine series (fixed) of the initial surface, each mode advanced exactly in time "
             "as above (FFTW's REDFT10/REDFT01 and RODFT00 transforms). A wall in another place, or a corner treated "
             "otherwise, would leave an error that falls at first order or not at all; the verdicts below are judged as "
             "those above.");
  MarkdownTable t({"stencil", "walls", "finest d", "RMS error at finest (m)", "max error at finest (m)", "order (95 % interval)",
                   "pairwise orders", "verdict", "CPU of the runs (s)"});
  for (const auto& n : c.strings("stencils"))
    for (const auto& b : walls) {
      const std::string kind = "walls_" + b;
      const Record& q = c.at(n).at(kind);
      require_one_story(c, n + " " + kind, q);
      const Table& pts = q.table("points");
      const std::size_t last = pts.rows() - 1;
      t.row({code(n), b, fmt(pts.column("h")[last], 3) + " m", fmt(pts.column("l2_error_m")[last], 3),
             fmt(pts.column("max_error_m")[last], 3), order_interval(q.at("fit")), list_text(q.table("pairwise_all").column("order")),
             q.at("fit").at("verdict").text("verdict"), fmt(q.number("cpu_s"), 3)});
    }
  w.table(t);
  for (const auto& b : walls) w.figure(convergence_figure(c, "walls_" + b));
}

SectionOutput convergence_section(const Record& c) {
  const Record& p = c.at("problem");
  SectionWriter w(c, "2. Convergence against the exact solution");
  std::ostringstream m;
  m << initial_text(p) << " at rest on a periodic " << fmt(p.number("length_m")) << " m × "
    << fmt(p.number("length_m")) << " m square, wave speed c = " << fmt(p.number("wave_speed_m_s")) << " m/s, damping μ = "
    << fmt(p.number("damping_per_s")) << " /s; the surface is compared at t = " << fmt(p.number("t_end_s")) << " s. "
    << "The exact solution comes from the spectral reference: every Fourier mode of the initial surface is advanced "
       "exactly in time (a damped oscillator per mode) and transformed back with FFTW. Using the continuum symbol "
       "c²|k|² gives the exact solution of the wave equation (spectrally accurate on the grid); using the stencil's own "
       "symbol gives the exact solution of the *semi-discrete* system — the stencil with no time-stepping error. "
       "That lets the error be taken apart:";
  w.lead("The problem.", m.str());
  w.bullet("**space alone**: semi-discrete exact minus continuum exact, on grids of " + grids_text(c.table("space_grids")) + " cells;");
  w.bullet("**time alone**: the leapfrog minus the semi-discrete exact solution on a " + fmt(c.number("time_grid")) +
           "² grid, with " + list_text(c.table("time_steps").column("value"), 5) + " steps;");
  w.bullet("**both**: the leapfrog minus the continuum exact solution, grid and step refined together at σ = cΔt/d = " +
           fmt(c.number("both_sigma")) + ", grids " + grids_text(c.table("both_grids")) + ".");
  w.end_list();
  const double fp = c.number("fit_points");
  w.text("Errors are RMS over the domain (m). The observed order is the slope of a least-squares fit of log(error) "
         "against log(h) over " + (fp > 0 ? "the finest " + fmt(fp) + " points" : std::string("every point")) +
         ", with its 95 % confidence interval (Student t); the pairwise orders use every pair of neighbouring grids. "
         "The verdict asks for the whole interval within " + fmt(c.number("tolerance")) + " of " +
         fmt(c.number("expected_order")) + "; an interval too wide to decide (or a fit on fewer than 3 points), a run without a finite error, "
         "or a local order that drifts across the grids by more than twice that tolerance (the bend of log error "
         "against log h significant by an F test) says *order not established*, and *does not converge* needs the "
         "whole interval at or below " +
         fmt(c.number("minimum_order")) + ".");
  MarkdownTable t({"stencil", "sequence", "finest h", "RMS error at finest (m)", "max error at finest (m)",
                   "order (95 % interval)", "pairwise orders", "verdict", "CPU of the runs (s)"});
  const auto names = c.strings("stencils");
  for (const auto& n : names)
    for (const char* kind : {"space", "time", "both"}) {
      const Record& q = c.at(n).at(kind);
      require_one_story(c, n + " " + kind, q);
      const Table& pts = q.table("points");
      const std::size_t last = pts.rows() - 1;
      const bool time = std::string(kind) == "time";
      t.row({code(n), kind, fmt(pts.column("h")[last], 3) + (time ? " s" : " m"), fmt(pts.column("l2_error_m")[last], 3),
             fmt(pts.column("max_error_m")[last], 3), order_interval(q.at("fit")),
             list_text(q.table("pairwise_all").column("order")), q.at("fit").at("verdict").text("verdict"),
             std::string(kind) == "space" ? "– (FFT only)" : fmt(q.number("cpu_s"), 3)});
    }
  w.table(t);
  for (const auto& n : names)
    if (c.at(n).has_child("diagnosis")) w.verdict(code(n), c.at(n).at("diagnosis"));
  w.end_list();
  for (const char* k : {"space", "time", "both"}) w.figure(convergence_figure(c, k));

  w.lead("Grid Convergence Index.",
         "Celik et al. (2008) estimate the discretisation uncertainty of a quantity from three grids, without knowing the "
         "exact answer. Here the quantity is the height at (¾, ½) L at t = " + fmt(p.number("t_end_s")) +
             " s from the three finest *both* runs; because the exact value is known, the table also says whether the "
             "GCI band actually contains it.");
  MarkdownTable g({"stencil", "classification", "apparent order p", "φ fine (m)", "φ extrapolated (m)", "exact (m)",
                   "GCI_fine", "actual |exact − φ fine| / |φ fine|", "verdict"});
  for (const auto& n : names) {
    const Record& b = c.at(n).at("both");
    if (!b.has_child("gci")) continue;
    const Record& gc = b.at("gci");
    // Divergent or at round-off: no order or GCI is defined (stored as 0; "0 %" read as "no error
    // left"), and a divergent sequence has no extrapolated value.
    const bool defined = gc.text("kind") != "divergent" && gc.text("kind") != "converged to round-off";
    g.row({code(n), gc.text("kind"), defined ? fmt(gc.number("order"), 3) : "–", fmt(gc.number("point_fine_m"), 5),
           gc.text("kind") != "divergent" ? fmt(gc.number("extrapolated_m"), 5) : "–", fmt(gc.number("point_exact_m"), 5),
           defined ? fmt(100 * gc.number("gci_fine"), 3) + " %" +
                         (gc.has("reverted") && gc.flag("reverted")
                              ? " (p not reasonable: " + fmt(gc.number("order_used"), 3) + " and Fs = " +
                                    fmt(gc.number("safety_factor"), 3) + " used)"
                              : "")
                   : "none",
           fmt(100 * gc.number("actual_relative_error"), 3) + " %", gc.at("verdict").text("verdict")});
  }
  w.table(g);
  w.lead("How to read it.",
         "On log-log axes an order-p method is a line of slope p (the dotted guide has slope 2). The GCI only means "
         "something in the asymptotic range, which it cannot check from three values alone: a non-converging sequence "
         "can look \"monotone\" by chance, which is why a GCI row is called *misleading* where the order test of the whole "
         "error field says the sequence does not converge.");
  walls_subsection(w, c);
  return w.finish();
}

// ---- 3. isotropy ------------------------------------------------------------------------------

SectionOutput isotropy_section(const Record& c) {
  SectionWriter w(c, "3. Isotropy: do waves travel at the same speed in every direction?");
  w.text("Lee & Baek (2013) chose an 8-neighbour stencil to make waves rounder. The phase speed of a plane wave with "
         "wave number k at angle θ on the grid is c_h = c·√(−symbol)/kd; its relative error (c_h − c)/c depends on kd "
         "(how many cells per wavelength: 2π/kd) and, for an anisotropic stencil, on θ. The polar plots show c_h/c "
         "around the circle (the dotted circle is exact; the radial scale is magnified). Only consistent stencils have a "
         "phase speed to speak of.");
  const auto skipped = c.strings("skipped_inconsistent");
  if (!skipped.empty()) {
    std::string s;
    for (const auto& n : skipped) s += (s.empty() ? "" : ", ") + code(n);
    w.text("Left out as inconsistent (section 1): " + s + ".");
  }
  w.figure(isotropy_polar_figure(c));
  const auto kds = c.table("polar_kd").column("kd");
  std::vector<std::string> headers{"stencil"};
  for (double kd : kds) headers.push_back("spread over θ at kd = " + pi_fraction(kd));
  headers.push_back("mean error at kd = " + pi_fraction(c.number("table_kd")));
  headers.push_back("spread ratio to " + c.text("baseline_stencil") + " at " + pi_fraction(c.number("table_kd")));
  MarkdownTable t(headers);
  for (const auto& n : c.strings("stencils")) {
    const Record& s = c.at(n);
    std::vector<std::string> row{code(n)};
    for (double sp : s.table("spread_at_polar_kd").column("spread")) row.push_back(fmt(sp, 3));
    row.push_back(fmt(s.number("mean_error_at_table_kd"), 3));
    row.push_back(fmt(s.number("spread_ratio_to_baseline"), 3));
    t.row(row);
  }
  w.table(t);
  if (c.has_child("roundest"))
    w.text("Roundest waves: " + code(c.at("roundest").text("stencil")) + " — " + c.at("roundest").text("why") + ".");
  w.text("The spread is the difference between the fastest and slowest direction. How it shrinks with kd tells the "
         "order of the anisotropy: slope 2 on the log-log plot means the leading error itself depends on direction, "
         "slope 4 means only the next term does.");
  w.figure(isotropy_spread_figure(c));
  w.lead("Measured from simulations.",
         "The prediction above uses only the stencil's weights. To check it against the actual code, a single Fourier mode "
         "is run with the leapfrog at σ = " + fmt(c.number("measured_sigma")) + " on a " + fmt(c.number("measured_grid")) +
             "² periodic grid for " + fmt(c.number("measured_steps"), 6) +
             " steps, and its frequency is estimated from the time series of its amplitude (Prony's linear prediction). "
             "The wave vector is the grid wave vector nearest the wanted kd and angle, so its kd differs by a few per cent "
             "from the target; the figure divides every error by the run's own (kd)², which removes that difference to "
             "leading order. Largest difference between measured and symbol-predicted (semi-discrete) relative speed: " +
             fmt(c.number("worst_measured_vs_semi_discrete"), 3) +
             " (this includes the leapfrog's own contribution at this σ); against the fully discrete dispersion relation, "
             "which includes the leapfrog: " + fmt(c.number("worst_measured_vs_fully_discrete"), 3) + ".");
  w.figure(isotropy_measured_figure(c));
  w.lead("Ring test.", "A narrow Gaussian bump (width " + fmt(c.number("ring_width_m"), 3) + " m on a " +
                           fmt(c.number("ring_n")) + "² grid of the unit square, σ = " + fmt(c.number("ring_sigma"), 3) +
                           ") spreads as a ring; after " + fmt(c.number("ring_t_s"), 3) +
                           " s the radius of the outgoing wavefront is measured along rays: the mean radius weighted by z² "
                           "over an annulus around ct (bilinear sampling every quarter cell). The same measurement on the "
                           "exact continuum solution gives the reference. An isotropic scheme gives the same radius in every "
                           "direction; a lag behind the reference means the scheme's waves are slow.");
  MarkdownTable r({"stencil", "wavefront radius: range over θ (cells)", "mean lag behind the exact wavefront (cells)", "CPU (s)"});
  for (const auto& n : c.strings("stencils")) {
    const Record& s = c.at(n);
    r.row({code(n), fmt(s.number("ring_spread_cells"), 3), fmt(s.number("ring_mean_lag_cells"), 3), fmt(s.number("ring_cpu_s"), 3)});
  }
  w.table(r);
  w.figure(ring_figure(c));
  return w.finish();
}

// ---- 4. stability -----------------------------------------------------------------------------

SectionOutput stability_section(const Record& c) {
  SectionWriter w(c, "4. Stability: how large may the time step be?");
  const double f = c.number("check_factor");
  w.text("Each Fourier mode of the leapfrog is multiplied every step by a root g of (2 + μΔt)g² − (4 + 2σ²·symbol)g + "
         "(2 − μΔt) = 0. The scheme is stable when |g| ≤ 1 for every mode; the framework evaluates |g| on a " +
         fmt(c.number("wavenumbers")) + " × " + fmt(c.number("wavenumbers")) +
         " grid of wave numbers (which includes the checkerboard) and finds the largest stable σ = cΔt/d by bisection, "
         "for μΔt from 0 to " + fmt(c.number("mu_dt_max"), 3) + ". The limit is then *measured*: runs from random noise at " +
         fmt(100 * f, 2) + " % below and above it, and a bisection on σ using runs alone (16² grid, " +
         fmt(c.number("measured_steps"), 6) + " steps, to a relative width of " + fmt(c.number("measured_tolerance"), 2) +
         "; a run is unstable when it blows up, or when the rise of its log RMS over the latter half of the steps (the "
         "fitted slope times that window) exceeds the scatter of log RMS about the fitted line plus a round-off floor, "
         "verification/waves/stability.hpp: an undamped run, whose RMS only oscillates, can measure a growth per step a "
         "little above 1 without being called unstable).");
  w.figure(stability_figure(c));
  MarkdownTable t({"stencil", "μΔt", "computed σ limit", "measured σ limit", "Lengyel's bound",
                   "RMS ratio at " + fmt(1 - f, 3) + " × limit", "RMS ratio at " + fmt(1 + f, 3) + " × limit",
                   "growth/step at " + fmt(1 + f, 3) + " ×: measured (predicted)"});
  for (const auto& n : c.strings("stencils")) {
    const Table& k = c.at(n).table("checks");
    for (std::size_t i = 0; i < k.rows(); ++i) {
      auto col = [&](const char* name) { return k.column(name)[i]; };
      t.row({code(n), fmt(col("mu_dt")), fmt(col("computed_limit"), 6), fmt(col("measured_limit"), 5),
             fmt(col("lengyel_bound"), 4), fmt(col("ratio_below"), 3), fmt(col("ratio_above"), 3),
             fmt(col("growth_above"), 5) + " (" + fmt(col("predicted_growth_above"), 5) + ")"});
    }
  }
  w.table(t);
  for (const auto& n : c.strings("stencils")) w.verdict(code(n) + ", dependence on damping", c.at(n).at("damping"));
  w.end_list();
  const Record& l = c.at("lengyel");
  w.lead("Lengyel's bound",
         "c < (d/2Δt)√(μΔt + 2), i.e. σ < ½√(μΔt + 2), grows with the damping. Its test: " +
             verdict_markdown(l.at("verdict")) + " (RMS up " + fmt(l.number("norm_ratio"), 3) + "× in " +
             // The steps taken: the run stops once its RMS passes 1e100 (reports before steps_run
             // was stored ran every step asked for or said the asked-for count).
             fmt(l.number(l.has_number("steps_run") ? "steps_run" : "steps"), 6) +
             " steps). Try it: `stoneskip wave cases/wave_lengyel_counterexample.toml`.");
  w.lead("How to read it.",
         "Damping shrinks the oscillating stable modes (complex roots, |g| = √((2 − μΔt)/(2 + μΔt)) for them; the "
         "slowest modes are overdamped, their roots real, and decay more slowly than that) but cannot rescue the "
         "checkerboard, whose root becomes real and leaves the unit circle; the verdicts above say whether the "
         "computed limits move with μΔt.");
  return w.finish();
}

// ---- 5. speed against error -------------------------------------------------------------------

SectionOutput speed_section(const Record& c) {
  const Record& p = c.at("problem");
  SectionWriter w(c, "5. Speed against error: does the 8-neighbour stencil reach a given error for less work?");
  w.text(std::string("The paper argues that its 8-neighbour stencil lets a sparser grid do the same job. Here one physical problem — ") +
         lower_first(initial_text(p)) + " followed to t = " +
         fmt(p.number("t_end_s"), 3) + " s on the periodic " + fmt(p.number("length_m")) +
         " m square — is solved by each stencil on grids of " + grids_text(c.table("grids")) + " cells at σ = " +
         list_text(c.table("sigma_fractions").column("value"), 2) +
         " × the stencil's own stability limit (so stencils that allow larger steps use them), and the RMS error against "
         "the exact continuum solution is set against the cost of the run (" + c.text("clock") + "; runs shorter than " +
         fmt(c.number("min_cpu_s"), 2) + " s are repeated and averaged; the machine may be shared, so times carry noise). "
         "The lines join the best error reached for a given time.");
  w.figure(work_precision_figure(c));
  const auto targets = c.table("targets_m").column("target_m");
  std::vector<std::string> headers{"stencil", "σ limit used"};
  for (double e : targets) headers.push_back("CPU s to reach " + fmt(e, 1) + " m RMS");
  headers.push_back("smallest error reached (m)");
  headers.push_back("cell updates per CPU second (largest grid)");
  MarkdownTable t(headers);
  const auto names = c.strings("stencils");
  for (const auto& n : names) {
    const Record& s = c.at(n);
    std::vector<std::string> row{code(n), fmt(s.number("sigma_limit"), 4)};
    for (double v : s.table("cpu_to_reach").column("cpu_s")) row.push_back(fmt(v, 3));
    row.push_back(fmt(s.number("best_error_m"), 3));
    row.push_back(fmt(s.number("cell_updates_per_cpu_s_largest_grid"), 3));
    t.row(row);
  }
  w.table(t);
  const Table& win = c.table("winners");
  for (std::size_t i = 0; i < win.rows(); ++i) {
    const int k = static_cast<int>(win.column("winner_index")[i]);
    const double base = win.column("baseline_cpu_s")[i], best = win.column("winner_cpu_s")[i];
    if (k < 0) {
      w.bullet(fmt(win.column("target_m")[i], 1) + " m: no run reached it.");
      continue;
    }
    std::string line = fmt(win.column("target_m")[i], 1) + " m: fastest is " + code(names[k]) + " (" + fmt(best, 3) + " s";
    if (names[k] != c.text("baseline_stencil"))
      line += std::isnan(base) ? ", " + c.text("baseline_stencil") + " never reached it"
                               : ", " + c.text("baseline_stencil") + " " + fmt(base, 3) + " s";
    w.bullet(line + ").");
  }
  w.verdict("**Answer**", c.at("answer"));
  w.end_list();
  w.lead("How to read it.",
         "A stencil's larger stable step buys speed only if the error at a given grid does not grow with it; the space "
         "error of section 2 and the cost of reading 8 neighbours instead of 4 decide the rest. An inconsistent stencil "
         "appears for completeness: its error does not fall with the work.");
  return w.finish();
}

}  // namespace

RenderedReport render_waves_report(const StoredReport& s) {
  const Record& secs = s.sections;
  RenderedReport out;
  const Record& settings = secs.at("settings");
  std::ostringstream md;
  md << "# Water surface verification: the stencils against the exact solution\n\n"
        "This report checks the height-field water of Lee & Baek (2013), *z_tt = c²∇²z − μz_t* stepped with a damped "
        "leapfrog, with 3 × 3 Laplacian stencils: the 5-point stencil (`five_point`, the paper's Figure 4a), the "
        "8-neighbour family member with γ = ½ (`nine_point_half`, the paper's Eq. 10 halved), the isotropic "
        "\"Mehrstellen\" member γ = ⅓ (`nine_point_isotropic`, Patra & Karttunen 2006), and the paper's Eq. 11 exactly "
        "as printed (`paper_eq11`). It answers, with numbers: is each stencil consistent, at what order does it "
        "converge, how round are its waves, how large may its time step be, and what does a given accuracy cost?\n\n"
     << "Settings: the `" << settings.text("preset") << "` preset (stored in `data.h5`)."
     << (settings.text("preset") != "full" ? " **This is a reduced run: grids and sequences are shorter than in the full report.**" : "")
     << "\n\n";
  md << findings_summary(secs);
  out.markdown = md.str();
  append(out, consistency_section(secs.at("consistency")));
  append(out, convergence_section(secs.at("convergence")));
  append(out, isotropy_section(secs.at("isotropy")));
  append(out, stability_section(secs.at("stability")));
  append(out, speed_section(secs.at("speed")));
  out.markdown +=
      "## How this was computed\n\n"
      "* Height field: `model/water/height_field.cpp` (leapfrog, ghost-layer boundaries), stencils as data in "
      "`model/water/stencil.cpp`.\n"
      "* Exact reference: `solvers/spectral/spectral_wave.cpp` (FFTW r2c/c2r, one damped oscillator per mode, "
      "`damped_mode.cpp` for every damping regime).\n"
      "* Studies and verdicts: `verification/waves/wave_studies.cpp` (from the settings in `cases/studies/`), order fits "
      "and GCI in `verification/convergence/`; this page is formatted by `reports/waves/` from `data.h5` alone.\n"
      "* Single runs of any case: `stoneskip wave cases/wave_gaussian_five_point.toml [--set water.stencil=...] [--json]`.\n\n";
  out.markdown += provenance_markdown(s);
  return out;
}

}  // namespace stoneskip
