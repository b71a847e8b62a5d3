// Section 1 of the stones report: how the real-time stepper converges to the CVODE reference, and
// how the reference's own error follows its tolerance.
#include <cmath>
#include <map>
#include <sstream>

#include "reports/common/markdown.hpp"
#include "reports/stones/plot_helpers.hpp"
#include "reports/stones/report_sections.hpp"

namespace stoneskip {

namespace {

std::string pairwise_text(const OrderFit& f) {
  std::ostringstream s;
  for (std::size_t i = 0; i < f.pairwise.size(); ++i) s << (i ? ", " : "") << fmt(f.pairwise[i], 3);
  return s.str();
}

std::string verdict(const ConvergenceSeries& s) {
  if (!s.fit.valid) return "no fit: " + s.fit.problem;
  const double p = s.fit.order;
  if (std::abs(p - s.formal_order) <= 0.2) return "formal order";
  if (p < 0.3) return "does not converge";
  if (p < s.formal_order) return "below formal order";
  return "above formal order";
}

Figure series_figure(const std::string& name, const std::string& title, const std::vector<ConvergenceSeries>& all,
                     const std::string& quantity, const std::string& x_label, const std::string& y_label) {
  std::vector<PlotSeries> ps;
  for (const auto& s : all) {
    if (s.quantity != quantity) continue;
    PlotSeries p;
    p.title = s.scheme + " (formal " + std::to_string(s.formal_order) + ", observed " +
              (s.fit.valid ? fmt(s.fit.order, 3) : std::string("–")) + ")";
    p.x = s.h_s;
    p.y = s.error;
    ps.push_back(p);
  }
  PlotAxes ax;
  ax.x_label = x_label;
  ax.y_label = y_label;
  ax.log_x = ax.log_y = true;
  return line_figure(name, title, ax, ps, "h_s", "error");
}

}  // namespace

SectionOutput convergence_section(const RealtimeConvergenceResult& c, const ReferenceToleranceResult& tol,
                                  const H5Group& data) {
  SectionOutput out;
  // Data.
  H5Group g = data.create_group("convergence");
  g.set_attr("case", c.case_label);
  g.set_attr("flight_interval_end_s", c.flight_interval_end_s);
  g.set_attr("contact_interval_start_s", c.contact_interval_start_s);
  g.set_attr("contact_interval_end_s", c.contact_interval_end_s);
  g.set_attr("free_flight_time_s", c.free_flight_time_s);
  for (const auto& s : c.series) {
    Table t;
    t.columns = {"h_s", "value", "error", "in_fit"};
    for (std::size_t i = 0; i < s.h_s.size(); ++i) t.add_row({s.h_s[i], s.value[i], s.error[i], s.in_fit[i] ? 1.0 : 0.0});
    const std::string name = s.quantity + "_" + s.scheme;
    g.write_table(name, t);
  }
  {
    H5Group r = data.create_group("reference_tolerance");
    r.set_attr("case", tol.case_label);
    r.set_attr("method", tol.method);
    Table t;
    t.columns = {"rtol", "ok", "bounce_position_error_m", "contact_time_error_s", "rhs_evaluations", "cpu_s"};
    for (const auto& p : tol.points)
      t.add_row({p.rtol, p.ok ? 1.0 : 0.0, p.bounce_position_error_m, p.contact_time_error_s,
                 static_cast<double>(p.rhs_evaluations), p.cpu_s});
    r.write_table("points", t);
  }

  // Words.
  std::ostringstream md;
  md << "## 1. Convergence of the real-time model\n\n"
     << "**What is measured.** The real-time stepper (fixed steps; a finer *contact step* near and in the water) is "
        "run on one throw with shrinking steps, and each result is compared with the CVODE reference solution of the "
        "same equations (rtol = " << fmt(c.reference_rtol, 1) << ", every contact event located). If the stepper is correct, its error falls like "
        "h^p with p its scheme's formal order (semi-implicit Euler 1, midpoint 2, RK4 4). The observed p is a "
        "least-squares fit of log error against log h with its 95 % interval; the pairwise orders of neighbouring "
        "step sizes show whether the slope is steady; Celik's GCI (fine grid) estimates the remaining relative error "
        "of a scalar from the three finest runs.\n\n"
     << "Throw: **" << c.case_label << "** (physical convention). The reference makes " << c.reference.contacts.size()
     << " contacts and " << c.reference.bounces << " bounces and ends (" << to_string(c.reference.outcome) << ") at "
     << fmt(c.reference.end_time_s, 4) << " s.\n\n"
     << "Two kinds of measurement:\n\n"
     << "* *the scheme alone* — N equal steps of `realtime_step` with no contact logic, over a free-flight interval "
        "[0, " << fmt(c.flight_interval_end_s, 3) << " s] and over an interval holding the whole first contact ["
     << fmt(c.contact_interval_start_s, 4) << ", " << fmt(c.contact_interval_end_s, 4)
     << "] s, starting from the reference state. Error: the largest relative error of position (in stone radii), "
        "velocity, orientation (angle) and angular momentum at the end. This isolates the integrator.\n"
     << "* *the whole stepper* — `run_realtime` with flight step dt and contact step dt/10: contact start and end "
        "times, exit speed and centre-of-mass position at the end of the first contact, the bounce positions (the centre of mass where each contact ends) and the first-touch points of every "
        "contact, and the state in free flight after the first bounce (t = "
     << fmt(c.free_flight_time_s, 4) << " s). The step sizes on the axis are the flight steps.\n\n"
     << "Points whose error is below the difference between the reference and a check run at rtol "
     << fmt(c.check_rtol, 1) << " (an upper bound of the reference's own error) are shown but left out of the fit.\n\n";
  {
    auto p_of = [&](const std::string& q, const char* scheme) {
      for (const auto& s : c.series)
        if (s.quantity == q && s.scheme == scheme) return s.fit.valid ? fmt(s.fit.order, 3) : std::string("–");
      return std::string("–");
    };
    auto line = [&](const std::string& q) {
      return p_of(q, "semi_implicit_euler") + " / " + p_of(q, "midpoint") + " / " + p_of(q, "rk4");
    };
    md << "**What it finds** (observed order, semi-implicit Euler / midpoint / RK4; formal 1 / 2 / 4):\n\n"
       << "* scheme alone, free flight: " << line("flight_interval_state") << "\n"
       << "* scheme alone, through the whole first contact: " << line("contact_interval_state") << "\n"
       << "* whole stepper, contact start time: " << line("contact1_start_time") << "; end time: "
       << line("contact1_end_time") << "\n"
       << "* whole stepper, bounce positions (centre of mass where each contact ends): " << line("bounce_positions")
       << "; first-touch points: " << line("touch_points") << "\n"
       << "* whole stepper, state in free flight after the first bounce: " << line("free_flight_state") << "\n\n";
  }
  for (const auto& p : c.problems) md << "> Could not measure: " << p << "\n\n";

  MarkdownTable table({"quantity", "scheme", "formal p", "observed p [95 % CI]", "pairwise p (coarse → fine)",
                       "GCI fine", "verdict"});
  for (const auto& s : c.series) {
    std::string gci = "–";
    if (s.has_gci) gci = fmt(100 * s.gci.gci_fine, 2) + " % (" + std::string(to_string(s.gci.kind)) + ")";
    std::string observed = s.fit.valid ? fmt(s.fit.order, 3) + " [" + fmt(s.fit.order_low, 3) + ", " +
                                             fmt(s.fit.order_high, 3) + "] (" + std::to_string(s.fit.points) + " pts)"
                                       : "–";
    table.row({s.description, s.scheme, std::to_string(s.formal_order), observed, pairwise_text(s.fit), gci,
               verdict(s)});
  }
  md << table.str() << "\n";
  // Failures and notes per point.
  std::ostringstream notes;
  for (const auto& s : c.series)
    for (std::size_t i = 0; i < s.h_s.size(); ++i)
      if (!s.notes[i].empty() && s.notes[i].find("below the reference") == std::string::npos)
        notes << "* " << s.quantity << ", " << s.scheme << ", h = " << fmt(s.h_s[i], 3) << " s: " << s.notes[i] << "\n";
  if (!notes.str().empty()) md << "Runs left out of the fits, with the reason:\n\n" << notes.str() << "\n";

  out.figures.push_back(series_figure("conv_flight_interval", "Scheme alone, free-flight interval: error against step",
                                      c.series, "flight_interval_state", "step h (s)", "relative state error"));
  out.figures.push_back(series_figure("conv_contact_interval",
                                      "Scheme alone, interval holding the first contact: error against step", c.series,
                                      "contact_interval_state", "step h (s)", "relative state error"));
  out.figures.push_back(series_figure("conv_bounce_positions", "Whole stepper: bounce-position error against flight step",
                                      c.series, "bounce_positions", "flight step dt (s), contact step dt/10",
                                      "largest bounce-position error (m)"));
  out.figures.push_back(series_figure("conv_contact_end", "Whole stepper: error of the first contact's end time",
                                      c.series, "contact1_end_time", "flight step dt (s), contact step dt/10",
                                      "error (s)"));
  out.figures.push_back(series_figure("conv_free_flight", "Whole stepper: state error in free flight after the first bounce",
                                      c.series, "free_flight_state", "flight step dt (s), contact step dt/10",
                                      "relative state error"));
  for (const auto& f : out.figures) md << figure_markdown(f);

  md << "**How to read it.** In free flight the forces are smooth and every scheme should show its formal order. "
        "Through a contact the water force is only piecewise smooth in time: the wetted area of a triangle grows "
        "like depth² when a vertex goes under, and a face's force switches off when its normal velocity changes "
        "sign, so the force is continuous with a continuous first derivative but has a jump in its second time "
        "derivative at every such event. A fixed-step method stepping across such an event makes a local error of "
        "O(h³) there, which caps the global order at 3: RK4 falls to about 3 through a contact (and its pairwise "
        "orders scatter at coarse steps, where many events fall inside single steps), while orders 1 and 2 keep "
        "theirs once the step is small enough. The whole stepper adds its own event handling: contact start and end are found by linear interpolation of the deepest "
        "vertex's depth (second order), and the first-touch point is the deepest vertex at the end of the first "
        "wet step, which is wrong by up to one contact step of travel — first order whatever the scheme. Coarse steps "
        "also change the contact list itself (extra contacts, listed above): such runs have no bounce-position "
        "error.\n\n";

  // Reference tolerance proportionality.
  md << "### The reference's own error against its tolerance\n\n"
     << "CVODE (" << tol.method << ") at rtol from " << fmt(tol.points.front().rtol, 1) << " to "
     << fmt(tol.points.back().rtol, 1) << " (atol = rtol/100) against a run at rtol 1e-12. A slope near 1 means the "
        "error control works through the located contact events (tolerance proportionality).\n\n";
  MarkdownTable t2({"rtol", "bounces", "bounce-position error (m)", "contact-time error (s)", "RHS evaluations",
                    "CPU (s)", "note"});
  for (const auto& p : tol.points)
    t2.row({fmt(p.rtol, 1), std::to_string(p.bounces), fmt_or_dash(p.bounce_position_error_m),
            fmt_or_dash(p.contact_time_error_s), std::to_string(p.rhs_evaluations), fmt(p.cpu_s, 3), p.problem});
  md << t2.str() << "\n";
  md << "Slope of log(bounce-position error) against log(rtol): " << tol.bounce_position_fit.brief()
     << "; of the contact-time error: " << tol.contact_time_fit.brief() << ". The bounce-position error falls by "
     << fmt_or_dash(tol.error_drop_1e6_to_1e10, 3) << "× from rtol 1e-6 to 1e-10 (issue 4 asks for at least 100×).\n\n";
  {
    PlotSeries a, b;
    a.title = "bounce-position error (m)";
    b.title = "contact-time error (s)";
    for (const auto& p : tol.points) {
      a.x.push_back(p.rtol);
      a.y.push_back(p.bounce_position_error_m);
      b.x.push_back(p.rtol);
      b.y.push_back(p.contact_time_error_s);
    }
    PlotSeries ideal;
    ideal.title = "slope 1";
    ideal.style = "lines dt 2";
    if (!tol.points.empty() && std::isfinite(tol.points.front().bounce_position_error_m)) {
      const double c0 = tol.points.front().bounce_position_error_m / tol.points.front().rtol;
      for (const auto& p : tol.points) {
        ideal.x.push_back(p.rtol);
        ideal.y.push_back(c0 * p.rtol);
      }
    }
    PlotAxes ax;
    ax.x_label = "rtol";
    ax.y_label = "error against rtol 1e-12";
    ax.log_x = ax.log_y = true;
    Figure f = line_figure("ref_tolerance", "CVODE reference: error against tolerance", ax, {a, b, ideal}, "rtol", "error");
    md << figure_markdown(f);
    out.figures.push_back(f);
  }
  out.markdown = md.str();
  return out;
}

}  // namespace stoneskip
