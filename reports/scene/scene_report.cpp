#include "reports/scene/scene_report.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "reports/common/colour_scale.hpp"
#include "reports/common/markdown.hpp"
#include "reports/common/plot.hpp"
#include "reports/scene/frame_plot.hpp"
#include "reports/scene/water_step_part.hpp"
#include "verification/study/stored_values.hpp"

namespace stoneskip {

namespace {

// An ensemble member's count, or "failed" (NaN: the run failed and has no count).
std::string count_or_failed(double c) { return std::isnan(c) ? std::string("failed") : fmt(c); }

std::string us(double s) { return fmt(1e6 * s, 3) + " µs"; }
std::string ms(double s) { return fmt(1e3 * s, 3) + " ms"; }
std::string duration(double s) { return std::abs(s) >= 0.1 ? fmt(s, 3) + " s" : std::abs(s) >= 1e-3 ? ms(s) : us(s); }

const std::string& verdict_of(const Record& r, const std::string& key = "verdict") { return r.at(key).text("verdict"); }

// A target's verdict beside the figure the table shows: the figure and the verdict's input are
// stored apart, and must be the same number, or the page would set a verdict beside a value it was
// not decided on (data edited by hand: RecordError, refused by `report render`).
const std::string& target_verdict(const Record& s, const std::string& key, const std::string& figure) {
  const double shown = s.number(figure), decided = s.at(key).number("value");
  if (!(shown == decided || (std::isnan(shown) && std::isnan(decided)))) {
    std::ostringstream m;
    m.precision(17);
    m << s.path() << ": " << figure << " is " << shown << " but its verdict " << key << " was decided on " << decided;
    throw RecordError(m.str());
  }
  return verdict_of(s, key);
}

// ---- findings at the top ----------------------------------------------------------------------

std::string findings(const Record& secs) {
  std::ostringstream m;
  m << "## Findings\n\n";
  const Record& cp = secs.at("coupling");
  for (const auto& name : cp.strings("cases")) {
    const Record& c = cp.at(name);
    m << "* " << code(name) << ", two-way against one-way: " << verdict_markdown(c.at("verdict")) << ".\n";
  }
  m << "* The coupled stability limit (" << code(secs.at("stability").text("stencil")) << "): "
    << verdict_markdown(secs.at("stability").at("verdict")) << ".\n";
  const Record& cv = secs.at("convergence");
  m << "* The forced leapfrog against the forced spectral reference:";
  for (const auto& name : cv.strings("stencils")) {
    const Record& s = cv.at(name);
    m << " " << code(name) << " space " << order_interval(s.at("space").at("fit")) << " (" << verdict_of(s.at("space").at("fit")) << "), time "
      << order_interval(s.at("time").at("fit")) << ", both " << order_interval(s.at("both").at("fit")) << " (" << verdict_of(s.at("both").at("fit"))
      << ");";
  }
  m << "\n* The rings: " << verdict_markdown(secs.at("rings").at("verdict")) << ".\n";
  if (secs.has_child("grid")) {
    const Record& g = secs.at("grid");
    m << "* The coupled scene as the grid is refined: " << verdict_markdown(g.at("verdict"));
    if (g.has_child("fixed_width"))
      for (const auto& key : g.at("fixed_width").child_names()) {
        const Record& fw = g.at("fixed_width").at(key);
        m << "; with the head " << fmt(100 * fw.number("head_width_m"), 3) << " cm wide: " << verdict_markdown(fw.at("verdict"));
      }
    m << ".\n";
  }
  const Record& sp = secs.at("speed");
  for (const char* k : {"scene_target", "bandwidth_target", "per_cell_target", "sweep_target"})
    m << "* Speed: " << verdict_markdown(sp.at(k)) << ".\n";
  m << "\n";
  return m.str();
}

// ---- 1. coupling ------------------------------------------------------------------------------

SectionOutput coupling_section(const Record& c) {
  SectionWriter w(c, "1. What the stone's waves change: two-way against one-way against still water");
  w.text("Each shipped scene is run three times with the same stone, throw and frames: **two-way** (the stone forces the water, "
         "with its pressure or its draught as the case says, model/README.md §2.4), **one-way** (the stone is clipped against the field, which it does not disturb: on a "
         "still pond the field stays flat) and **still water** (no field at all). The contacts are compared in order (a "
         "contact is a maximal interval with some triangle wet, model/README.md §1.8). The bounce counts are compared on ensembles of "
         "perturbed throws (a bounce count can change under a nudge of the speed far below any measurement's precision, so one run "
         "against one says nothing; each case's perturbations are given with its ensemble below); a change "
         "of the first contact's times beyond " + us(c.number("time_tolerance_s")) + " counts as visible.");
  for (const auto& name : c.strings("cases")) {
    const Record& r = c.at(name);
    const Record& s = r.at("settings");
    const std::string forcing = s.has_text("scene_forcing") ? s.text("scene_forcing")
                                : r.has_child("forcing") && r.at("forcing").has_text("scene_forcing")
                                    ? r.at("forcing").text("scene_forcing")
                                    : std::string();
    w.subheading(code(name) + ": " + s.text("title"));
    w.text(s.text("convention") + " convention, " + fmt(s.number("speed_m_s"), 3) + " m/s, " + s.text("stone") + "; pond " +
           fmt(s.number("nx")) + " × " + fmt(s.number("ny")) + " cells of " + fmt(100 * s.number("cell_m"), 3) + " cm, c = " +
           fmt(s.number("wave_speed_m_s"), 3) + " m/s, μ = " + fmt(s.number("damping_per_s"), 3) + " /s, " + s.text("stencil") +
           ", water step " + ms(s.number("water_dt_s")) + " (σ = " + fmt(s.number("courant"), 3) + ", coupled limit " +
           fmt(s.number("coupled_limit"), 4) + "), " +
           // The forcing as stored with the settings, or (reports before that) with the two-way
           // run's forcing record; neither: the old wording.
           (forcing.empty() ? fmt(s.number("draught_samples")) + " draught samples per step; "
            : forcing == "displacement"
                ? "displacement forcing, " + fmt(s.number("draught_samples")) + " draught samples per water step; "
                : forcing + " forcing (a head per stone step); ") +
           fmt(s.number("duration_s"), 3) + " s simulated.");
    w.verdict("Two-way against one-way", r.at("verdict"));
    w.bullet("Why: " + r.text("why") + ".");
    w.bullet(std::string("One-way on the still pond against no field at all: ") +
             (r.flag("one_way_equals_still") ? "the same throw bit for bit (the field stays flat)." : "**different** — a defect."));
    w.bullet("Water volume change over the two-way scene: " + fmt(r.number("water_volume_change_m3"), 2) + " m³ (the stone adds and removes no water).");
    const Table& a = r.at("two_way").table("contacts");
    const Table& b = r.at("one_way").table("contacts");
    const Table& n = r.at("none").table("contacts");
    MarkdownTable t({"contact", "two-way start … end (s)", "two-way first touch (x, y) m", "one-way start … end (s)",
                     "one-way first touch (x, y) m", "still water start … end (s)", "two-way − one-way, start"});
    const std::size_t rows = std::max({a.rows(), b.rows(), n.rows()});
    auto span = [](const Table& x, std::size_t k) {
      return k < x.rows() ? fmt(x.column("start_s")[k], 6) + " … " + fmt(x.column("end_s")[k], 6) : std::string("–");
    };
    auto touch = [](const Table& x, std::size_t k) {
      return k < x.rows() ? "(" + fmt(x.column("touch_x_m")[k], 4) + ", " + fmt(x.column("touch_y_m")[k], 3) + ")" : std::string("–");
    };
    for (std::size_t k = 0; k < rows && k < 20; ++k)
      t.row({fmt(double(k + 1)), span(a, k), touch(a, k), span(b, k), touch(b, k), span(n, k),
             k < a.rows() && k < b.rows() ? duration(a.column("start_s")[k] - b.column("start_s")[k]) : "–"});
    w.table(t);
    if (rows > 20) w.text("(" + fmt(double(rows)) + " contacts in all; the first 20 shown, every one in data.h5.)");
    w.text("Contacts: two-way " + fmt(r.at("two_way").number("contact_count")) + " (" + fmt(r.at("two_way").number("bounces")) + " bounces, " +
           r.at("two_way").text("outcome") + " at " + fmt(r.at("two_way").number("end_time_s"), 4) + " s), one-way " +
           fmt(r.at("one_way").number("contact_count")) + " (" + fmt(r.at("one_way").number("bounces")) + ", " + r.at("one_way").text("outcome") +
           " at " + fmt(r.at("one_way").number("end_time_s"), 4) + " s), still water " + fmt(r.at("none").number("contact_count")) + " (" +
           fmt(r.at("none").number("bounces")) + ").");
    if (s.has_number("origin_x_m")) {  // where the pond ends: beyond it the stone makes no waves
      const double d = s.number("cell_m"), x0 = s.number("origin_x_m") - 0.5 * d, y0 = s.number("origin_y_m") - 0.5 * d;
      const double x1 = x0 + s.number("nx") * d, y1 = y0 + s.number("ny") * d;
      const auto tx = a.column("touch_x_m"), ty = a.column("touch_y_m");
      long outside = 0;
      double first_outside = 0;
      for (std::size_t k = 0; k < tx.size(); ++k)
        if (tx[k] < x0 || tx[k] > x1 || ty[k] < y0 || ty[k] > y1) {
          if (outside++ == 0) first_outside = double(k + 1);
        }
      w.text("The pond spans x = " + fmt(x0, 3) + " … " + fmt(x1, 3) + " m, y = " + fmt(y0, 3) + " … " + fmt(y1, 3) + " m. " +
             (outside == 0 ? std::string("Every two-way contact is inside it.")
                           : "**" + fmt(double(outside)) + " of the " + fmt(double(tx.size())) +
                                 " two-way contacts are outside it** (from contact " + fmt(first_outside) +
                                 " on): there the stone's draught is ignored (model/water/draught_patch.hpp) and the surface "
                                 "it meets is the height at the pond's nearest edge, so those contacts make no rings and feel no "
                                 "waves of their own; the movie ends when the stone leaves the pond."));
    }
    {
      const Record& e = r.at("ensemble");
      const Table& m = e.table("members");
      w.text("The bounce counts on ensembles of " + fmt(e.number("members_per_setting")) + " throws per setting, speed × (1 ± ε), ε from " +
             fmt(e.number("perturbation_smallest"), 2) + " to " + fmt(e.number("perturbation_largest"), 2) + ": two-way " +
             fmt(e.number("mean_two_way"), 3) + " ± " + fmt(e.number("sd_two_way"), 2) + ", one-way " + fmt(e.number("mean_one_way"), 3) + " ± " +
             fmt(e.number("sd_one_way"), 2) + " (mean ± sd); difference " + fmt(e.number("difference"), 3) + ", 95 % interval [" +
             fmt(e.number("difference_low"), 3) + ", " + fmt(e.number("difference_high"), 3) + "] (Welch)" +
             (e.has_number("failed_two_way") && e.number("failed_two_way") + e.number("failed_one_way") > 0
                  ? "; " + fmt(e.number("failed_two_way")) + " two-way and " + fmt(e.number("failed_one_way")) +
                        " one-way runs failed and have no count, so nothing is decided on these ensembles."
                  : "."));
      MarkdownTable et({"speed factor − 1", "two-way bounces", "one-way bounces"});
      for (std::size_t k = 0; k < m.rows(); ++k)
        et.row({fmt(m.column("speed_factor")[k] - 1, 2), count_or_failed(m.column("two_way_bounces")[k]),
                count_or_failed(m.column("one_way_bounces")[k])});
      w.table(et);
    }
    {
      // The two forcings of two-way coupling (model/README.md §2.4): what the water received against what the stone received.
      const Record& fr = r.at("forcing");
      w.text("What the water receives, by forcing (the scene's own: " + code(fr.text("scene_forcing")) +
             "). The stone's hydrodynamic vertical impulse is its momentum change less gravity's and the air's, step by step "
             "(what its stepper applied); the water's is Σ Δt Σ h̄ ρ g d² over its steps. Pressure forcing scales each stone "
             "step's head to carry that step's impulse. "
             "The energy budget: the waves' energy E (the leapfrog's own, solvers/scene/wave_energy.hpp) gains the pressure's work W "
             "and loses what damping takes, D.");
      MarkdownTable ft({"forcing", "stone impulse (N s)", "water impulse (N s)", "water / stone", "W (J)", "D (J)", "E start … end (J)",
                        "budget residual", "energy at ‖k‖d > π/2"});
      for (const char* key : {"pressure", "displacement"}) {
        const Record& k = fr.at(key);
        ft.row({code(key), fmt(k.number("stone_vertical_impulse_N_s"), 4), fmt(k.number("water_vertical_impulse_N_s"), 4),
                fmt(k.number("impulse_ratio"), 4), fmt(k.number("pressure_work_J"), 3), fmt(k.number("damping_loss_J"), 3),
                fmt(k.number("wave_energy_start_J"), 3) + " … " + fmt(k.number("wave_energy_end_J"), 3),
                fmt(k.number("energy_budget_residual"), 2), pct(k.number("grid_scale_energy_fraction"))});
      }
      w.table(ft);
      // A scene that ends inside a pressing leaves its last pieces' impulse in the windows of water
      // steps past the end (stored since 7 December).
      if (const Record& pr = fr.at("pressure"); pr.has_number("water_impulse_pending_N_s") && pr.number("water_impulse_pending_N_s") != 0)
        w.text("Under pressure forcing the scene ended inside a pressing: " + fmt(pr.number("water_impulse_pending_N_s"), 3) +
               " N s of the stone's impulse was held for water steps past its end, not in the water's column above (the "
               "pressings' water impulses below sum to the two).");
      const Table& ci = fr.at("pressure").table("contact_impulses");
      MarkdownTable ct({"pressing", "start … end (s)", "stone (N s)", "water (N s)", "water / stone − 1"});
      for (std::size_t k = 0; k < ci.rows() && k < 20; ++k) {
        const double st = ci.column("stone_N_s")[k], wa = ci.column("water_N_s")[k];
        ct.row({fmt(double(k + 1)), fmt(ci.column("start_s")[k], 6) + " … " + fmt(ci.column("end_s")[k], 6), fmt(st, 4), fmt(wa, 4),
                st != 0 ? fmt(wa / st - 1, 2) : std::string("–")});
      }
      w.text("Pressure forcing, contact by contact (runs of stone steps with the stone pressing on the water; the water's "
             "column is what the grid keeps of the head, nothing for a pressing beyond the pond's rim, where it reads −1):");
      w.table(ct);
      if (ci.rows() > 20) w.text("(" + fmt(double(ci.rows())) + " in all; the first 20 shown, every one in data.h5.)");
    }
    // One-way as open rings under the two-way dots, so that a contact both runs share shows both.
    std::vector<PlotSeries> series;
    series.push_back(table_series("one-way", r.at("one_way"), "contacts", "touch_x_m", "start_s", "points pt 6 ps 1.6"));
    series.push_back(table_series("two-way", r.at("two_way"), "contacts", "touch_x_m", "start_s", "points pt 7 ps 0.8"));
    PlotAxes ax{"first touch x (m)", "contact start (s)", false, false, ""};
    w.figure(line_figure("coupling_" + name, "Where and when the stone touched the water: " + name, ax, series, "x_m", "t_s"));
  }
  w.lead("How to read it.",
         "The two-way stone meets the water its own draught has pushed down, but only as far as the water has had time to move: "
         "the depression spreads at c, so over a contact much shorter than the time footprint/c the water under the stone barely "
         "answers. How large the change is, scene by scene, is the verdict above with its numbers; a throw that bounces carries "
         "a change at one contact into every later one (in the paper convention, whose contacts can create energy, it can grow).");
  return w.finish();
}

// ---- 2. stability -----------------------------------------------------------------------------

SectionOutput stability_section(const Record& s) {
  SectionWriter w(s, "2. The coupled stability limit, shown on either side");
  w.text("Under a floating stone the draught follows the water with unit gain (b = (z − s)⁺ under a flat bottom at s), so the "
         "forced step acts there like a Laplacian of twice the strength: the Courant number under the footprint is √2 σ, and the "
         "two-way step is stable only for σ ≤ the free limit / √2 (model/README.md §2.4; " + code(s.text("stencil")) + ": free limit " +
         fmt(s.number("free_limit"), 4) + ", coupled " + fmt(s.number("coupled_limit"), 4) + "). A scene above it is **refused** "
         "with a one-line error at `water.dt_s` (the stone cannot be lagged without changing the model's closed forms). Shown "
         "here: an 11-gon stone held on a periodic " + fmt(s.number("n")) + "² pond, started in its closed-form equilibrium plus "
         "round-off noise, the draught recomputed every step; the growth per step of the departure from equilibrium at " +
         pct(1 - s.number("margin")) + " and " + pct(1 + s.number("margin")) + " of the coupled limit, and without the stone.");
  MarkdownTable t({"σ", "with the stone", "growth per step", "steps"});
  t.row({fmt(s.number("sigma_below"), 4), "yes", fmt(s.number("growth_below"), 6), fmt(s.number("steps"))});
  t.row({fmt(s.number("sigma_above"), 4), "yes", fmt(s.number("growth_above"), 6), fmt(s.number("steps_above"))});
  t.row({fmt(s.number("sigma_above"), 4), "no", fmt(s.number("growth_free_above"), 6), fmt(s.number("steps"))});
  w.table(t);
  w.verdict("The limit", s.at("verdict"));
  w.end_list();
  return w.finish();
}

// ---- 3. convergence ---------------------------------------------------------------------------

SectionOutput convergence_section(const Record& c) {
  SectionWriter w(c, "3. The forced leapfrog against the forced spectral reference");
  w.text("A Gaussian draught " + fmt(1e3 * c.number("draught_depth_m"), 3) + " mm deep and " + fmt(c.number("draught_width_m"), 3) +
         " m wide moves at " + fmt(c.number("draught_speed_m_s"), 3) + " m/s under a smooth envelope across a periodic " +
         fmt(c.number("length_m")) + " m square at rest (c = " + fmt(c.number("wave_speed_m_s"), 3) + " m/s, μ = " +
         fmt(c.number("damping_per_s"), 3) + " /s); the surface at t = " + fmt(c.number("t_end_s"), 3) +
         " s is compared with the forced spectral reference (model/README.md §2.5: each Fourier mode exact, the Duhamel integral by "
         "Gauss–Legendre quadrature). As for the free field, the error is split: space (the stencil's exact semi-discrete forced "
         "solution against the continuum's), time (the leapfrog against the semi-discrete solution on a " +
         fmt(c.number("time_grid")) + "² grid) and both (σ = " + fmt(c.number("both_sigma"), 3) + "). An order is granted when its "
         "whole 95 % interval lies within " + fmt(c.number("expected_order")) + " ± " + fmt(c.number("tolerance")) + ".");
  MarkdownTable t({"stencil", "space order", "time order", "both", "verdict (both)", "reference quadrature error (m)", "smallest error measured (m)"});
  std::vector<PlotSeries> series;
  for (const auto& name : c.strings("stencils")) {
    const Record& s = c.at(name);
    t.row({code(name), order_interval(s.at("space").at("fit")), order_interval(s.at("time").at("fit")), order_interval(s.at("both").at("fit")),
           verdict_of(s.at("both").at("fit")), fmt(s.number("reference_quadrature_m"), 2), fmt(s.number("smallest_error_m"), 2)});
    series.push_back(table_series(name, s.at("both"), "points", "h", "l2_error_m"));
  }
  w.table(t);
  for (const auto& name : c.strings("stencils")) {
    const Record& s = c.at(name);
    w.verdict(code(name) + " space", s.at("space").at("fit").at("verdict"));
    w.verdict(code(name) + " time", s.at("time").at("fit").at("verdict"));
    w.verdict(code(name) + " both", s.at("both").at("fit").at("verdict"));
  }
  w.end_list();
  PlotAxes ax{"cell size d (m), Δt = σ d / c", "RMS error at t_end (m)", true, true, ""};
  w.figure(line_figure("forced_convergence", "Forced leapfrog: error against the forced spectral reference, d and Δt refined together", ax,
                       series, "h_m", "error_m"));
  // The walled squares (reports written before 7 December have none).
  if (c.has("walls") && !c.strings("walls").empty()) {
    const auto walls = c.strings("walls");
    std::string named;
    for (const auto& b : walls) named += (named.empty() ? "" : ", ") + b;
    w.lead("Walled squares.",
           "The scene's pond has walls. So *both* is run again with the square's edges made walls (" + named + "), the draught "
           "alone (no periodic images), to t = " + fmt(c.number("walls_t_end_s"), 3) + " s, against the forced walled reference "
           "(model/README.md §2.5: cosine modes between reflecting walls, which the leapfrog's ghost cells put half a cell beyond "
           "the edge points, or sine modes inside fixed rims one cell beyond them; the draught mirrored across a reflecting wall, "
           "as the forced step's ghost cells take it). The cell d = L/n is the periodic square's; a reflecting grid has n points, "
           "a fixed one the n − 1 inside its rims.");
    MarkdownTable wt({"stencil", "walls", "order (95 % interval)", "verdict"});
    std::vector<PlotSeries> walled;
    for (const auto& name : c.strings("stencils"))
      for (const auto& b : walls) {
        const Record& q = c.at(name).at("walls_" + b);
        wt.row({code(name), b, order_interval(q.at("fit")), verdict_of(q.at("fit"))});
        walled.push_back(table_series(name + ", " + b, q, "points", "h", "l2_error_m"));
      }
    w.table(wt);
    for (const auto& name : c.strings("stencils"))
      for (const auto& b : walls) w.verdict(code(name) + " " + b, c.at(name).at("walls_" + b).at("fit").at("verdict"));
    w.end_list();
    w.figure(line_figure("forced_convergence_walls", "Forced leapfrog in the walled square: error against the forced walled reference, d and Δt refined together",
                         ax, walled, "h_m", "error_m"));
  }
  return w.finish();
}

// ---- 4. rings ---------------------------------------------------------------------------------

SectionOutput rings_section(const Record& r) {
  SectionWriter w(r, "4. How fast the rings spread");
  w.text("Scene " + code(r.text("case")) + ", contact " + fmt(r.number("contact")) + ": the ring is measured around the contact's "
         "centre (halfway between the first touch and the exit point), from " + fmt(r.number("start_after_s"), 3) + " s to " +
         fmt(r.number("end_after_s"), 3) + " s after the contact ended, at every frame: the azimuthal RMS of the surface in rings "
         "one cell wide, and the ring's radius taken as its leading edge (where that profile falls to half its maximum beyond " +
         fmt(r.number("min_radius_m"), 3) + " m). A least-squares line gives the speed with its 95 % interval. The scheme carries a "
         "wave of number k at its phase speed ω/k and its energy at its group speed dω/dk (the leapfrog's dispersion relation "
         "cos ωΔt = 1 + σ² s(kd)/2 with " + code(r.text("stencil")) + "'s symbol s, σ = " + fmt(r.number("courant"), 3) +
         ", averaged over directions); the leading edge should move between the group speed of the ring's dominant wave and c.");
  if (r.flag("found")) {
    MarkdownTable t({"quantity", "value"});
    t.row({"measured speed of the leading edge", fmt(r.number("speed_m_s"), 4) + " m/s [" + fmt(r.number("speed_low_m_s"), 4) + ", " +
                                                     fmt(r.number("speed_high_m_s"), 4) + "], R² = " + fmt(r.number("r_squared"), 5)});
    t.row({"c", fmt(r.number("c_m_s"), 4) + " m/s"});
    t.row({"the ring's wavelength (leading crest to trough × 2, at t = " + fmt(r.number("profile_t_s"), 3) + " s)",
           fmt(100 * r.number("wavelength_m"), 3) + " cm = " + fmt(r.number("wavelength_m") / r.number("cell_m"), 3) + " cells (kd = " +
               fmt(r.number("kd"), 3) + ")"});
    t.row({"the scheme's phase speed there", fmt(r.number("phase_speed_m_s"), 4) + " m/s"});
    t.row({"the scheme's group speed there", fmt(r.number("group_speed_m_s"), 4) + " m/s"});
    w.table(t);
  }
  w.verdict("The rings", r.at("verdict"));
  w.end_list();
  if (r.flag("found")) {
    const std::vector<double> t_s = r.table("radius").column("t_s");
    PlotAxes ax{"t (s)", "radius of the leading edge (m)", false, false, ""};
    w.figure(line_figure("ring_radius", "The ring's leading edge against time", ax,
                         {table_series("measured", r, "radius", "t_s", "radius_m", "points pt 7 ps 0.6"),
                          record_line("least-squares line", r, "intercept_m", "speed_m_s", t_s),
                          record_line("speed c from the same start", r, "intercept_m", "c_m_s", t_s, "lines dt 2")},
                         "t_s", "r_m"));
    PlotAxes ap{"distance from the contact's centre (m)", "z (m)", false, false, ""};
    w.figure(line_figure("ring_profile", "The ring at t = " + fmt(r.number("profile_t_s"), 3) + " s: azimuthal mean and RMS", ap,
                         {table_series("mean", r, "profile", "r_m", "mean_m", "lines"), table_series("RMS", r, "profile", "r_m", "rms_m", "lines")},
                         "r_m", "z_m"));
  }
  return w.finish();
}

// ---- 5. shortcuts -----------------------------------------------------------------------------

SectionOutput shortcuts_section(const Record& s) {
  SectionWriter w(s, "5. Computing only what the scene needs: each shortcut's error and saving");
  w.text("Scene " + code(s.text("case")) + ", two-way, against the same scene computed in full (float64, every tile, " +
         "the stated reference): the largest surface difference over frames every " + fmt(s.number("checkpoint_every")) +
         " frames (relative to the largest |z| there), the largest change of a contact's start or end, the contact count, and the "
         "scene's thread CPU time (the least of " + fmt(s.number("repeats")) + " runs each). Within tolerance means a surface "
         "difference ≤ " + fmt(s.number("field_tolerance"), 2) + " of the largest |z|, contacts moved ≤ " + us(s.number("time_tolerance_s")) +
         " and the same count.");
  MarkdownTable t({"shortcut", "surface difference (m, relative)", "contacts moved", "contacts", "CPU (shortcut / reference)", "saved", "verdict"});
  for (const auto& key : s.strings("shortcuts")) {
    const Record& r = s.at(key);
    t.row({r.text("what"), fmt(r.number("field_max_change_m"), 2) + " (" + fmt(r.number("field_relative"), 2) + ")", duration(r.number("start_change_s")),
           fmt(r.number("contacts_shortcut")) + " / " + fmt(r.number("contacts_reference")),
           ms(r.number("shortcut_cpu_s")) + " / " + ms(r.number("reference_cpu_s")), pct(r.number("saving")), verdict_of(r)});
  }
  w.table(t);
  for (const auto& key : s.strings("shortcuts")) w.verdict(s.at(key).text("what"), s.at(key).at("verdict"));
  w.end_list();
  w.lead("How to read it.",
         "A negative saving is a cost. ε = 0 steps only tiles that hold anything, which is exact (model/README.md §2.6) but pays the tiles' "
         "bookkeeping; ε > 0 drops what the quiet tiles held. Leaving the field out entirely is exact only for a case that asks "
         "for bounces on still water.");
  return w.finish();
}

// ---- 6. grid ----------------------------------------------------------------------------------

// A sequence's table (verification/scene/scene_grid_findings.cpp).
MarkdownTable grid_table_markdown(const Record& seq) {
  const Table t = seq.table("grids");
  // How the first contact ends (stored since 7 December): "bounce", or "under" (it sank, or the run ended in it).
  auto ends = [](const Table& x, std::size_t i) -> std::string {
    if (!x.has_column("first_bounced")) return "";
    const double b = x.column("first_bounced")[i];
    return std::isnan(b) ? "" : b > 0 ? ", bounce" : ", under";
  };
  MarkdownTable m({"cell (cm)", "grid", "water step (ms)", "cells across the stone", "smoothing passes", "pressure work W (J)",
                   t.has_column("first_bounced") ? "first contact (ms), how it ends" : "first contact (ms)", "its exit speed (m/s)",
                   "contacts", "wall (s)"});
  for (std::size_t i = 0; i < t.rows(); ++i) {
    auto v = [&](const char* k) { return t.column(k)[i]; };
    m.row({fmt(100 * v("cell_m"), 3), fmt(v("n")) + "²", fmt(1e3 * v("water_dt_s"), 3), fmt(v("cells_across_stone"), 3),
           t.has_column("smoothing_passes") ? fmt(v("smoothing_passes")) : std::string("–"), fmt(v("pressure_work_J"), 4),
           fmt(1e3 * v("first_duration_s"), 5) + ends(t, i), fmt(v("first_exit_m_s"), 4), fmt(v("contacts")), fmt(v("wall_s"), 2)});
  }
  // The finest grid again with the water step halved (stored since 7 December).
  if (seq.has_table("half_step") && seq.table("half_step").rows() > 0) {
    const Table h = seq.table("half_step");
    auto v = [&](const char* k) { return h.column(k)[0]; };
    m.row({fmt(100 * v("cell_m"), 3) + ", step ½", fmt(v("n")) + "²", fmt(1e3 * v("water_dt_s"), 3), fmt(v("cells_across_stone"), 3),
           fmt(v("smoothing_passes")), fmt(v("pressure_work_J"), 4), fmt(1e3 * v("first_duration_s"), 5) + ends(h, 0),
           fmt(v("first_exit_m_s"), 4), fmt(v("contacts")), fmt(v("wall_s"), 2)});
  }
  return m;
}

std::string grid_left_out(const Record& seq, double max_width_cells) {
  if (!(seq.number("left_out") > 0)) return "";
  if (!seq.has_number("left_out_too_wide")) return fmt(seq.number("left_out")) + " grid(s) left out: more than 2048² cells.";
  std::string s;
  if (seq.number("left_out_too_large") > 0) s += fmt(seq.number("left_out_too_large")) + " grid(s) left out: more than 2048² cells. ";
  if (seq.number("left_out_too_wide") > 0)
    s += fmt(seq.number("left_out_too_wide")) + " grid(s) left out: the head would be more than " + fmt(max_width_cells) + " cells wide (its smoothing "
         "passes grow as (width/cell)²).";
  return s;
}

// What forces the water in section 6's own sequence, and how it is spread on the grid.
std::string grid_head_words(const std::string& forcing, double own_width_m, const std::string& passes) {
  if (forcing != "pressure")
    return "The stone forces the water with its draught b, sampled at the grid points (model/README.md §2.4).";
  const std::string head = "The head h the stone presses with is its wetted faces' pressure rastered on the cells (model/README.md §2.4), ";
  if (own_width_m > 0)
    return head + "smoothed to a width of " + fmt(100 * own_width_m, 3) +
           " cm (the case's `head_width_m`: 2 (width/cell)² binomial passes, at least " + passes + ").";
  return head + "smoothed over a fixed number of cells (" + passes + " binomial passes), so a finer grid resolves a narrower, stronger patch: where "
                "the changes do not shrink, the scene's water response (and through it the stone's contacts) is a property of the "
                "grid, not of the stone.";
}

// One quantity of section 6 against the cell: a line for each sequence (seqs[0] the scene's own,
// whose cells get the ticks) and its finest grid with the water step halved as a point in the
// line's colour (gnuplot's line type k is the k-th series').
Figure grid_figure(const std::string& name, const std::string& title, const std::vector<const Record*>& seqs,
                   const std::vector<std::string>& titles, const std::string& column, const std::string& label) {
  std::vector<PlotSeries> series;
  double smallest = std::numeric_limits<double>::infinity(), largest = 0;
  for (std::size_t i = 0; i < seqs.size(); ++i) {
    if (seqs[i]->table("grids").rows() == 0) continue;
    series.push_back(table_series(titles[i], *seqs[i], "grids", "cell_m", column));
    for (double c : seqs[i]->table("grids").column("cell_m")) {
      smallest = std::min(smallest, c);
      largest = std::max(largest, c);
    }
    const std::string line_type = std::to_string(series.size());
    if (seqs[i]->has_table("half_step") && seqs[i]->table("half_step").rows() > 0)
      series.push_back(table_series(titles[i] + ", step ½", *seqs[i], "half_step", "cell_m", column, "points pt 6 ps 1.5 lt " + line_type));
  }
  // Room above and below the points; on the log axis the cells' own span (gnuplot would widen it
  // to whole decades) with a tick at each, from finite stored values only.
  std::string extra = "set offsets 0, 0, graph 0.05, graph 0.05";
  if (std::isfinite(smallest) && std::isfinite(largest) && smallest > 0) {
    std::string tics;
    for (double c : seqs[0]->table("grids").column("cell_m"))
      if (std::isfinite(c) && c > 0) tics += (tics.empty() ? "" : ", ") + fmt(c, 4);
    extra += "\nset xrange [" + fmt(smallest / 1.4, 4) + ":" + fmt(largest * 1.4, 4) + "]\nset format x \"%g\"\nset xtics (" + tics + ")";
  }
  const PlotAxes ax{"cell (m), water step ∝ cell", label, true, false, extra};
  return line_figure(name, title, ax, series, "cell_m", column);
}

SectionOutput grid_section(const Record& g) {
  SectionWriter w(g, "6. Does the coupled scene converge as the grid is refined?");
  const double own_width = g.has_number("head_width_m") ? g.number("head_width_m") : 0.0;
  const std::string passes = g.has_number("default_passes") ? fmt(g.number("default_passes")) : std::string("3");  // before 7 December: 3
  // The case's own coupling where it is not the section's two-way (stored since 7 December).
  const std::string coupled = g.has_text("case_coupling") && g.text("case_coupling") != "two_way"
                                  ? "; run two-way, where the case is " + code(g.text("case_coupling")) +
                                        ": the section refines the waves the stone makes"
                                  : std::string();
  w.text("Scene " + code(g.text("case")) + " (" + g.text("forcing") + " forcing" + coupled + ") on its own cell of " + fmt(100 * g.number("base_cell_m"), 3) +
         " cm and on finer ones, the water step scaled with the cell (σ fixed), on a " + fmt(g.number("pond_m"), 3) + " m × " +
         fmt(g.number("pond_m"), 3) + " m pond around the first touch, until " +
         (g.has_number("end_s") ? fmt(g.number("end_s"), 3) + " s" : std::string("the scene's end (the stone never touched: nothing was run)")) +
         ". There is no exact solution of the coupled scene: what can be asked is whether its answers settle as the cells "
         "shrink — whether every change is smaller than the one before. A table's last row (\"step ½\") is its finest grid again "
         "with the water step halved: " +
         (g.has_text("level_in_time") && g.text("level_in_time") == "extrapolated"
              ? std::string("the stone reads the surface extrapolated from the last two water steps, so an event time carries a "
                            "second-order error of that step")
              : std::string("the stone sees the surface held over each water step, so an event time carries a first-order error of "
                            "that step")) +
         ", which this sequence (σ fixed) does not separate from the cell's; a quantity whose "
         "changes do not shrink but whose last change is no larger than what halving the step moves it is *not decided*. "
         "The stone is " + fmt(100 * g.number("stone_diameter_m"), 3) +
         " cm across. " + grid_head_words(g.text("forcing"), own_width, passes));
  if (g.has_text("initial_surface")) {
    // A case on a disturbed surface (stored since 7 December): sampled afresh on each grid.
    const double end_s = g.has_number("end_s") ? g.number("end_s") : 0.0;
    const bool clear = g.number("pond_inside_case") > 0 && g.number("walls_reach_s") > end_s;
    w.text("The case starts from " + g.text("initial_surface") + " (`[water.initial]`): each grid samples it afresh at its own cell "
           "points, in the case's frame (model/water/disturbance.hpp). " +
           (g.has_text("boundary") && g.text("boundary") == "periodic"
                ? std::string("The pond's edges are not the case's (its periodic seams fall elsewhere), and from the start they ")
                : std::string("The pond's walls are not the case's, and from the start they ")) +
           "send waves into that surface; at c = " + fmt(g.number("wave_speed_m_s"), 3) + " m/s from " +
           fmt(100 * std::max(0.0, g.number("wall_distance_m")), 3) + " cm away they reach the first contact's track (on still "
           "water) after " + fmt(1e3 * g.number("walls_reach_s"), 4) + " ms" +
           (!clear ? std::string(": see the verdict below.")
            : 2 * end_s <= g.number("walls_reach_s")
                ? ", after twice the section's end at " + fmt(1e3 * end_s, 4) +
                      " ms: until then the pond's answers are the case's. (The bound at c is a soft one: the leapfrog's front "
                      "is dispersed ahead of c. Measured on the shipped scenes' water, a wall's waves stay below a millionth of the "
                      "surface's height until half their arrival at c and reach percents of it at that arrival: "
                      "model/README.md §2.4.)"
                : ", after the section's end at " + fmt(1e3 * end_s, 4) + " ms but before twice it. The bound at c is a "
                      "soft one: the leapfrog's front is dispersed ahead of c, and measured on the shipped scenes' water a wall's waves "
                      "stay below a millionth of the surface's height until half their arrival at c but reach percents of it "
                      "at that arrival (model/README.md §2.4); some of them may reach the track by the end. A wider "
                      "grid.pond_m, with the walls' arrival at least twice the end, keeps them out."));
  }
  w.table(grid_table_markdown(g));
  const double max_cells = g.has_number("max_width_cells") ? g.number("max_width_cells") : 8.0;
  const std::string lo = grid_left_out(g, max_cells);
  if (!lo.empty()) w.text(lo);
  w.verdict("The coupled scene under refinement", g.at("verdict"));
  w.end_list();
  if (g.has_child("fixed_width") && !g.at("fixed_width").child_names().empty()) {
    w.text("**A head of fixed width.** The same grids again with the head smoothed to a fixed width in metres (`head_width_m` in a "
           "scene's `[water]`, model/README.md §2.4): 2 (width/cell)² binomial passes, each spreading a point by a variance of ½ cell², "
           "so the head's standard deviation is the width on every grid fine enough (at least " + passes + " passes, as the scene's own; at most " +
           fmt(g.number("max_width_cells")) + " cells wide). If the changes shrink here, what did not settle above is the head's "
           "width in cells; a change that still does not shrink, by more than the water step moves it, has another cause.");
    for (const auto& key : g.at("fixed_width").child_names()) {
      const Record& seq = g.at("fixed_width").at(key);
      w.text("*Head " + fmt(100 * seq.number("head_width_m"), 3) + " cm wide:*");
      if (seq.table("grids").rows() > 0) w.table(grid_table_markdown(seq));
      const std::string l = grid_left_out(seq, max_cells);
      if (!l.empty()) w.text(l);
      w.verdict("The coupled scene under refinement, head " + fmt(100 * seq.number("head_width_m"), 3) + " cm wide", seq.at("verdict"));
      w.end_list();
    }
  }
  // The pressure work and the exit speed against the cell, one line a sequence, the finest grid
  // with the water step halved as a lone point (reports before 7 December: the scene's own only).
  if (g.table("grids").rows() > 0) {
    std::vector<const Record*> seqs{&g};
    std::vector<std::string> titles{own_width > 0 ? "head " + fmt(100 * own_width, 3) + " cm (the case's)"
                                                  : "head " + passes + " passes (the scene's)"};
    if (g.has_child("fixed_width"))
      for (const auto& key : g.at("fixed_width").child_names()) {
        seqs.push_back(&g.at("fixed_width").at(key));
        titles.push_back("head " + fmt(100 * seqs.back()->number("head_width_m"), 3) + " cm");
      }
    w.figure(grid_figure("grid_pressure_work", "The waves' pressure work in the first contact, as the cells shrink", seqs, titles,
                         "pressure_work_J", "pressure work W (J)"));
    w.figure(grid_figure("grid_exit_speed", "The first contact's exit speed, as the cells shrink", seqs, titles, "first_exit_m_s",
                         "exit speed (m/s)"));
  }
  // The water step alone at the scene's cell (stored since 7 December, with level_in_time).
  if (g.has_child("water_step")) water_step_part(w, g.at("water_step"));
  if (g.has_text("water_step_left_out")) w.text("**The level between water steps.** Not run: " + g.text("water_step_left_out") + ".");
  return w.finish();
}

// ---- 7. speed ---------------------------------------------------------------------------------

SectionOutput speed_section(const Record& s, int number) {
  // The sweep's stepper: the adaptive scheme by its tolerance, a fixed one by its contact step
  // (records written before the sweep named its scheme: the contact step).
  auto sweep_stepper_words = [](const Record& r) {
    if (r.has_text("sweep_scheme") && (r.text("sweep_scheme") == "bs32" || r.text("sweep_scheme") == "dp54"))
      return r.text("sweep_scheme") + ", rtol " + fmt(r.number("sweep_rtol"), 2);
    return (r.has_text("sweep_scheme") ? r.text("sweep_scheme") + ", " : std::string()) + "contact step " +
           fmt(r.number("sweep_contact_dt_s"), 2) + " s";
  };
  SectionWriter w(s, std::to_string(number) + ". Speed");
  w.text("Measured in one run of this binary, on a machine with " + fmt(s.number("cores")) + " cores and a 1-minute load average of " +
         fmt(s.number("load_before"), 3) + " before and " + fmt(s.number("load_after"), 3) + " after (other jobs share the cores: "
         "wall times include their share). The scene " + code(s.text("case")) + " (" + fmt(s.number("scene_frames")) +
         " frames) is run " + fmt(s.number("scene_repeats")) + " times per thread count; frames/s from the best wall time (the least "
         "disturbed), the median beside it; the stencil " + code(s.text("stencil")) + " (" + s.text("kernel_isa") + ") against a copy "
         "kernel on arrays of the same size, best samples (wall); the sweep: " + fmt(s.number("sweep_throws")) + " real-time throws "
         "(" + sweep_stepper_words(s) + ") on " + fmt(s.number("sweep_workers")) + " workers, best wall time.");
  MarkdownTable t({"figure", "measured", "verdict"});
  t.row({"the seed's scene, 1 thread: frames/s", fmt(s.number("scene_fps_1core"), 4) + " (median " + fmt(s.number("scene_fps_1core_median"), 4) +
                                                    "; thread CPU " + fmt(s.number("scene_fps_1core_cpu"), 4) + ")",
         target_verdict(s, "scene_target", "scene_fps_1core")});
  t.row({"the seed's scene, " + fmt(s.number("many_threads")) + " threads: frames/s",
         fmt(s.number("scene_fps_2cores"), 4) + " (median " + fmt(s.number("scene_fps_2cores_median"), 4) + ")", "–"});
  t.row({"stencil at " + fmt(s.number("stencil_n_small")) + "²: cells/s", fmt(s.number("stencil_cells_per_s_small"), 3) + " (" +
                                                                             fmt(s.number("bandwidth_fraction_small"), 3) + " of its copy bound)",
         "–"});
  t.row({"stencil at " + fmt(s.number("stencil_n_large")) + "²: cells/s, fraction of the copy bound",
         fmt(s.number("stencil_cells_per_s_large"), 3) + ", " + fmt(s.number("bandwidth_fraction_large"), 3) + " (median " +
             fmt(s.number("bandwidth_fraction_large_median"), 3) + ")",
         target_verdict(s, "bandwidth_target", "bandwidth_fraction_large")});
  t.row({"rate per cell, small grid over large", fmt(s.number("per_cell_ratio"), 3), target_verdict(s, "per_cell_target", "per_cell_ratio")});
  t.row({"bounce-count sweep: throws/s", fmt(s.number("sweep_throws_per_s"), 4) + " (" + fmt(s.number("sweep_cpu_s"), 3) + " s CPU over " +
                                             fmt(s.number("sweep_wall_s"), 3) + " s wall)",
         target_verdict(s, "sweep_target", "sweep_throws_per_s")});
  w.table(t);
  for (const char* k : {"scene_target", "bandwidth_target", "per_cell_target", "sweep_target"}) w.verdict("Target", s.at(k));
  w.end_list();
  w.text("Where the scene's time goes (1 thread, best run, wall clock): stone " + ms(s.number("stone_wall_s")) + ", draught " +
         ms(s.number("draught_wall_s")) + ", water " + ms(s.number("water_wall_s")) + ", recording " + ms(s.number("recording_wall_s")) +
         " of " + ms(s.number("wall_s")) + " (" + ms(s.number("cpu_s")) + " thread CPU). The slowest frame is frame " +
         fmt(s.number("slowest_frame")) + " (t = " + fmt(s.number("slowest_frame_t_s"), 3) + " s): " + ms(s.number("slowest_frame_wall_s")) +
         " wall, " + ms(s.number("slowest_frame_cpu_s")) + " CPU.");
  w.text("What a throw of the sweep costs (its profile, thread CPU): " + ms(s.number("sweep_cpu_per_throw_s")) + " per throw, for " +
         fmt(s.number("sweep_simulated_per_throw_s"), 3) + " s simulated, " + fmt(s.number("sweep_steps_per_throw"), 4) + " stone steps of which " +
         fmt(s.number("sweep_contact_steps_per_throw"), 4) + " near the water, " + us(s.number("sweep_cpu_per_step_s")) +
         " per step; the target allows " + ms(s.number("sweep_cpu_budget_per_throw_s")) + " per throw on " + fmt(s.number("sweep_workers")) +
         " fully available workers.");
  PlotAxes ax{"t (s)", "cost of the frame (ms)", false, true, ""};
  w.figure(line_figure("frame_cost", "The cost of each frame (1 thread)", ax,
                       {table_series("wall", s, "frames", "t_s", "wall_ms", "lines"),
                        table_series("thread CPU", s, "frames", "t_s", "cpu_ms", "lines"),
                        table_series("stone (wall)", s, "frames", "t_s", "stone_ms", "lines"),
                        table_series("water (wall)", s, "frames", "t_s", "water_ms", "lines")},
                       "t_s", "ms"));
  return w.finish();
}

// ---- 8. frames --------------------------------------------------------------------------------

Figure still_figure(const std::string& name, const Record& r) {
  Figure fig;
  fig.name = "still_" + name;
  fig.title = "The scene " + name + " at t = " + fmt(r.number("t_s"), 3) + " s";
  fig.width_px = 1280;
  fig.height_px = 540;
  auto matrix = [](const std::string& table, double x0, double y0, double dx) {
    std::ostringstream s;
    s.precision(9);
    s << "'" << table << ".dat' matrix using (" << x0 << "+$1*" << dx << "):(" << y0 << "+$2*" << dx << "):3";
    return s.str();
  };
  // The numbers the script is written from, finite (a NaN was written as `nan`, which gnuplot
  // refuses as an undefined variable): data edited by hand is refused by name (stored_values.hpp).
  auto at = [&r](const char* key) { return stored_finite(r, key); };
  FramePlot p;
  p.top = matrix(fig.name + "_top", at("top_x0_m"), at("top_y0_m"), at("top_dx_m"));
  p.near = matrix(fig.name + "_near", at("near_x0_m"), at("near_y0_m"), at("near_dx_m"));
  if (r.table("track").rows() >= 2) p.track = "'" + fig.name + "_track.dat' using 1:2";
  if (r.table("touches").rows() >= 1) p.touches = "'" + fig.name + "_touches.dat' using 1:2";
  p.stone_x_m = at("stone_x_m");
  p.stone_y_m = at("stone_y_m");
  p.stone_z_m = at("stone_z_m");
  p.stone_radius_m = at("stone_radius_m");
  p.stone_sunk = r.text("stone_status") == "sank";
  p.pond_x0_m = at("pond_x0_m");
  p.pond_x1_m = at("pond_x1_m");
  p.pond_y0_m = at("pond_y0_m");
  p.pond_y1_m = at("pond_y1_m");
  const int n = static_cast<int>(r.table("near").columns.size());
  p.near_x0_m = at("near_x0_m");
  p.near_x1_m = at("near_x0_m") + (n - 1) * at("near_dx_m");
  p.near_y0_m = at("near_y0_m");
  p.near_y1_m = at("near_y0_m") + (n - 1) * at("near_dx_m");
  if (!std::isfinite(p.near_x1_m) || !std::isfinite(p.near_y1_m))  // finite parts, an overflowing window
    throw RecordError(r.path() + ": 'near_dx_m' × the window's " + std::to_string(n) + " columns is not a finite width");
  // The colour scale from the drawn data (reports/common/colour_scale.hpp), the 3-D box from its window's.
  const RobustScale top = robust_scale(r.table("top").values), near = robust_scale(r.table("near").values);
  p.scale_m = top.scale;
  p.near_z_m = near.scale > 0 ? 1.2 * near.scale : top.scale;
  p.title = "t = " + fmt(r.number("t_s"), 4) + " s" + (p.stone_sunk ? ", the stone has sunk" : "") + "   (colour ±" +
            fmt(1e3 * p.scale_m, 2) + " mm: " + fmt(double(top.beyond)) + " of " + fmt(double(top.disturbed)) +
            " disturbed cells beyond it, the largest " + fmt(1e3 * top.largest, 2) + " mm)";
  fig.title += ": colour scale ±" + fmt(1e3 * p.scale_m, 2) + " mm, the largest height drawn " + fmt(1e3 * top.largest, 2) + " mm";
  fig.script = frame_plot_commands(p);
  for (const char* part : {"top", "near", "track", "touches"}) {  // each as stored (every column)
    fig.tables.emplace_back(fig.name + "_" + part, r.table(part));
    fig.copies.emplace_back(fig.name + "_" + part, TableCopy{r.path() + "/" + part, {}, {}, ""});
  }
  return fig;
}

SectionOutput frames_section(const Record& f, int number) {
  SectionWriter w(f, std::to_string(number) + ". Still frames");
  w.text("For each scene the most telling frame: the one with the most disturbed water (cells with |z| above " +
         pct(f.number("threshold_fraction")) + " of the scene's largest |z|) among the frames before a cell above that height reaches the pond's edge (smaller waves may reach it first). "
         "Left, the water from above (the dashed square is the right panel's window), the stone's track (line), its first "
         "touches (crosses) and the stone (filled; hollow once sunk); right, the water around the stone (while it is in the air, "
         "around its latest touch), heights on the colour scale. The colour scale is symmetric, ± the 99th percentile of |z| over the "
         "view's disturbed cells (|z| above 1 % of the view's largest), so that at most 1 % of them are drawn at its ends; the 3-D "
         "box spans 1.2 times the same measure of its own window, the stone drawn on its lid when higher. Both come from the "
         "stored heights (block means of the field), said on each frame. `stoneskip scene CASE --movie FILE.mp4` draws "
         "a movie the same way.");
  for (const auto& name : f.strings("cases")) {
    const Record& r = f.at(name);
    w.subheading(code(name) + ": " + r.text("title"));
    if (!r.flag("found")) {
      w.text("No still: " + r.text("problem") + ".");
      continue;
    }
    w.text("Frame chosen: " + r.text("why") + "." +
           (r.flag("near_on_touch") ? " The stone is in the air: the right panel shows the water around its latest touch." : ""));
    w.figure(still_figure(name, r));
  }
  return w.finish();
}

}  // namespace

RenderedReport render_scene_report(const StoredReport& stored) {
  const Record& secs = stored.sections;
  RenderedReport out;
  std::ostringstream m;
  const Record& settings = secs.at("settings");
  m << "# The seed's scene, whole: the stone makes waves\n\n"
    << "Lee & Baek's system is a stone skipping over a 500 × 500 height field whose bounces make waves, at more than 90 frames "
       "per second. This report runs that system — the real-time stone on a live, two-way coupled field (model/README.md §2.4) — on the "
       "shipped scenes (";
  bool first = true;
  for (const auto& name : settings.strings("cases")) {
    m << (first ? "" : ", ") << code(settings.at(name).text("file"));
    first = false;
  }
  m << "; preset " << code(settings.text("preset")) << ") and says what the waves change, whether the coupled water is computed "
       "right, how much each shortcut costs in accuracy, and how fast it runs.\n\n"
    << "**What the model is for.** The stone presses on the water as a surface pressure of head h: z_tt = c²∇²(z + h) − μ z_t "
       "(model/README.md §2.4). With `forcing = \"pressure\"` (the default) h is the pressure the stone's wetted faces press with, "
       "so the water receives the stone's vertical impulse; with `\"displacement\"` it is the stone's draught b, which makes a stone "
       "held still settle with the surface under it halfway between its bottom and the far water (§2.4's closed form), not at its "
       "bottom as a real resting plate's would. Either way the water is linear and shallow: the model is meant for contacts much "
       "shorter than footprint/c — a skipping stone's — where the water has no time to settle; section 1 gives each scene's "
       "forcing and its contact time against footprint/c.\n\n";
  out.markdown = m.str() + findings(secs);
  append(out, coupling_section(secs.at("coupling")));
  append(out, stability_section(secs.at("stability")));
  append(out, convergence_section(secs.at("convergence")));
  append(out, rings_section(secs.at("rings")));
  append(out, shortcuts_section(secs.at("shortcuts")));
  // Reports before the grid section have none: their speed and frames keep their numbers 6 and 7.
  const int after = secs.has_child("grid") ? 7 : 6;
  if (secs.has_child("grid")) append(out, grid_section(secs.at("grid")));
  append(out, speed_section(secs.at("speed"), after));
  append(out, frames_section(secs.at("frames"), after + 1));
  out.markdown += provenance_markdown(stored);
  for (const auto& f : out.figures)
    if (f.name.rfind("still_", 0) == 0) out.headline_figure = f.name;  // the last still: the front page's picture
  return out;
}

}  // namespace stoneskip
