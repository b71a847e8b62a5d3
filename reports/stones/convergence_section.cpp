// Section 1 of the stones report: how the real-time stepper converges to the CVODE reference, and
// how the reference's own error follows its tolerance — formatted from the stored record.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "reports/common/markdown.hpp"
#include "reports/common/plot.hpp"
#include "reports/stones/report_sections.hpp"
#include "verification/convergence/order_fit.hpp"

namespace stoneskip {

namespace {

std::string list_text(const std::vector<double>& v) {
  std::string s;
  for (double x : v) s += (s.empty() ? "" : ", ") + fmt(x, 3);
  return s.empty() ? "–" : s;
}

// "p [low, high] (n pts)"; a fit with the correction term (verification/convergence/order_fit.hpp)
// says so and gives the single power's too.
std::string observed(const Record& fit) {
  if (!fit.flag("valid") || fit.number("points") < 3) return order_interval(fit);
  std::string s = order_interval(fit) + " (" + fmt(fit.number("points")) + " pts";
  if (fit.has("corrected") && fit.flag("corrected"))
    s += ", with h^(p+1); one power: " + fmt(fit.number("single_order"), 3) + " [" + fmt(fit.number("single_low"), 3) +
         ", " + fmt(fit.number("single_high"), 3) + "]";
  return s + ")";
}

// What the position's own fit says of the formal order (the free-flight state's paragraph), from its
// stored verdict: a self-convergence test checks the position's order apart from this study.
std::string position_words(const Record& fp, double formal) {
  const std::string v = fp.at("verdict").text("verdict");
  const std::string self = "a self-convergence test of the scheme checks the position's order "
                           "(verification/stones/realtime_order_test.cpp).";
  if (v == to_string(OrderVerdict::converges_at_expected_order)) return "The position keeps the formal order " + fmt(formal) + "; " + self;
  return "The position's own fit here: " + v + "; " + self;
}

// Whether any series of the record had the correction term tested, and how many used it.
std::pair<int, int> correction_counts(const Record& c) {
  int tested = 0, used = 0;
  const Record& series = c.at("series");
  for (const auto& key : c.strings("series_keys")) {
    const Record& fit = series.at(key).at("fit");
    if (!fit.has("correction_tested")) continue;
    ++tested;
    if (fit.flag("corrected")) ++used;
  }
  return {tested, used};
}

// The adaptive schemes of the record (those with series against the tolerance), each with its
// fixed-step member's formal order (its scheme-alone series'; 0 where it has none), in the order
// the series list them.
std::vector<std::pair<std::string, double>> adaptive_schemes(const Record& c) {
  std::vector<std::pair<std::string, double>> out;
  const Record& series = c.at("series");
  const auto keys = c.strings("series_keys");
  for (const auto& key : keys) {
    const Record& s = series.at(key);
    if (!s.flag("against_tolerance")) continue;
    const std::string scheme = s.text("scheme");
    if (std::any_of(out.begin(), out.end(), [&](const auto& a) { return a.first == scheme; })) continue;
    double formal = 0;
    for (const auto& other : keys) {
      const Record& f = series.at(other);
      if (f.text("scheme") == scheme && !f.flag("against_tolerance")) formal = f.number("formal_order");
    }
    out.push_back({scheme, formal});
  }
  return out;
}

// "`a`", "`a` and `b`", "`a`, `b` and `c`".
std::string scheme_list(const std::vector<std::pair<std::string, double>>& schemes) {
  std::vector<std::string> names;
  for (const auto& s : schemes) names.push_back("`" + s.first + "`");
  return and_list(names);
}

}  // namespace

// The first paragraph's words on the adaptive schemes: what they run and the orders they should show
// ("" pieces where the study ran none).
ConvergenceAdaptiveWords convergence_adaptive_words(const Record& c) {
  const auto adaptive = adaptive_schemes(c);
  ConvergenceAdaptiveWords w;
  if (adaptive.empty()) return w;
  const bool one = adaptive.size() == 1;
  w.runs = std::string(one ? ", its adaptive scheme (" : ", its adaptive schemes (") + scheme_list(adaptive) +
           ") with shrinking tolerances (rtol = atol_m)";
  std::vector<std::pair<std::string, double>> members;
  for (const auto& a : adaptive)
    if (a.second > 0) members.push_back(a);
  if (members.size() == 1) {
    w.members = ", and `" + members[0].first + "`'s fixed-step member " + fmt(members[0].second) + " when the scheme runs alone";
  } else if (members.size() > 1) {
    std::vector<std::string> each;
    for (const auto& m : members) each.push_back("`" + m.first + "` (" + fmt(m.second) + ")");
    w.members = ", and the fixed-step members of " + and_list(each) + " when the scheme runs alone";
  }
  w.proportional = std::string(one ? "; the adaptive scheme's" : "; an adaptive scheme's") +
                   " error should fall in proportion to its tolerance (order 1 in tol: its controller keeps the local "
                   "error of each step near tol × the step's share)";
  w.fitted = one ? " The adaptive scheme's errors against its tolerance are fitted with a single power."
                 : " The adaptive schemes' errors against their tolerances are fitted with a single power.";
  return w;
}

namespace {

// The series of one quantity, all schemes, as a figure.
Figure series_figure(const std::string& name, const std::string& title, const Record& c, const std::string& quantity,
                     const std::string& x_label, const std::string& y_label) {
  std::vector<PlotSeries> ps;
  const Record& series = c.at("series");
  for (const auto& key : c.strings("series_keys")) {
    const Record& s = series.at(key);
    if (s.text("quantity") != quantity || s.flag("against_tolerance")) continue;
    const Record& fit = s.at("fit");
    ps.push_back(table_series(s.text("scheme") + " (formal " + fmt(s.number("formal_order")) + ", observed " +
                                  (fit.flag("valid") ? fmt(fit.number("order"), 3) : std::string("–")) + ")",
                              s, "points", "h_s", "error"));
  }
  PlotAxes ax;
  ax.x_label = x_label;
  ax.y_label = y_label;
  ax.log_x = ax.log_y = true;
  return line_figure(name, title, ax, ps, "h_s", "error");
}

// The runs of one series left out of its fit for a reason other than the reference's accuracy
// (failed, a contact list unlike the reference's, at round-off: N ε × scale), as "scheme, h = … s:
// reason" (with_quantity: prefixed by the quantity).
std::vector<std::string> left_out(const Record& s, bool with_quantity) {
  std::vector<std::string> out;
  const auto h = s.table("points").column("h_s");
  const auto below_floor = s.table("points").column("below_floor");
  const auto& n = s.strings("notes");
  for (std::size_t i = 0; i < h.size() && i < n.size(); ++i)
    if (!n[i].empty() && (below_floor[i] == 0.0 || n[i].rfind("at round-off", 0) == 0))
      out.push_back((with_quantity ? s.text("quantity") + ", " : std::string()) + s.text("scheme") +
                    (s.flag("against_tolerance") ? ", tolerance " + fmt(h[i], 3) : ", h = " + fmt(h[i], 3) + " s") + ": " +
                    n[i]);
  return out;
}

// One adaptive scheme's series against its tolerance (one figure per scheme: two schemes' nine
// series each on one plot could not be told apart).
Figure tolerance_figure(const Record& c, const std::string& scheme, const std::string& name) {
  std::vector<PlotSeries> ps;
  const Record& series = c.at("series");
  for (const auto& key : c.strings("series_keys")) {
    const Record& s = series.at(key);
    if (!s.flag("against_tolerance") || s.text("scheme") != scheme) continue;
    const Record& fit = s.at("fit");
    ps.push_back(table_series(s.text("quantity") + " (" + s.text("unit") + "; observed " +
                                  (fit.flag("valid") ? fmt(fit.number("order"), 3) : std::string("–")) + ")",
                              s, "points", "h_s", "error"));
  }
  PlotAxes ax;
  ax.x_label = "tolerance (rtol = atol_m)";
  ax.y_label = "error against the reference";
  ax.log_x = ax.log_y = true;
  return line_figure(name, "Adaptive stepper " + scheme + ": error against its tolerance", ax, ps, "tolerance", "error");
}

// The events' series (quantity, words), in the order shown.
const std::vector<std::pair<std::string, std::string>>& event_quantities() {
  static const std::vector<std::pair<std::string, std::string>> q{
      {"contact1_start_time", "first touch: start time of the first contact (s)"},
      {"touch_points", "first-touch points of every contact (m)"},
      {"contact1_end_time", "end time of the first contact (s)"},
      {"sink_time", "sinking time (s)"},
      {"sink_position", "sinking point (m)"}};
  return q;
}

// One row per event quantity, one column per scheme: observed order [95 % CI] against the expected
// order (the scheme's formal order, or 1 against an adaptive scheme's tolerance) and the verdict.
MarkdownTable event_table(const Record& c) {
  const Record& series = c.at("series");
  std::vector<std::string> schemes;
  for (const auto& key : c.strings("series_keys")) {
    const Record& s = series.at(key);
    if (std::find(schemes.begin(), schemes.end(), s.text("scheme")) == schemes.end()) schemes.push_back(s.text("scheme"));
  }
  std::vector<std::string> head{"event"};
  for (const auto& sc : schemes) head.push_back(sc);
  MarkdownTable t(head);
  for (const auto& [q, words] : event_quantities()) {
    std::vector<std::string> cells{words};
    bool any = false;
    for (const auto& sc : schemes) {
      const std::string key = q + "." + sc;
      if (!series.has_child(key)) {
        cells.push_back("–");
        continue;
      }
      any = true;
      const Record& s = series.at(key);
      const Record& fit = s.at("fit");
      cells.push_back(observed(fit) + ", expected " + fmt(s.number("formal_order")) +
                      (s.flag("against_tolerance") ? " in tol" : "") + ": **" + fit.at("verdict").text("verdict") + "**");
    }
    if (any) t.row(cells);
  }
  return t;
}

}  // namespace

SectionOutput convergence_section(const Record& c) {
  SectionWriter w(c, "1. Convergence of the real-time model, each water law");
  const std::string contact_step = "dt × " + fmt(c.number("contact_ratio"), 3);
  const ConvergenceAdaptiveWords adaptive = convergence_adaptive_words(c);
  w.lead("What is measured.",
         "The real-time stepper's fixed schemes (a finer *contact step* near and in the water) are run on one throw "
         "with shrinking steps" + adaptive.runs + ", and each "
         "result is compared with the CVODE reference solution of the same equations (rtol = " +
             fmt(c.number("reference_rtol"), 2) +
             ", every contact event located). If the stepper is correct, its error falls like h^p with p its scheme's "
             "formal order (semi-implicit Euler 1, midpoint 2, RK4 4" + adaptive.members + ")" + adaptive.proportional +
             ". The observed p is a "
             "least-squares fit of log error against log h (or log tol) with its 95 % interval; the verdict asks for the "
             "whole interval within " +
             fmt(c.number("order_tolerance"), 2) +
             " of the formal order, says *order not established* when the interval is too wide to decide (or rests on "
             "fewer than three points), when the error does not fall at some halving, or when its local order drifts "
             "across the steps by more than twice that tolerance (the bend of log error against log h significant by "
             "an F test: an error running onto a floor), and *does not converge* only when the slope is shown to be at "
             "most " +
             fmt(c.number("minimum_order"), 2) +
             ". The pairwise orders of neighbouring step sizes show whether the slope is steady; Celik's GCI (fine grid) "
             "estimates the remaining relative error of a scalar from the three finest runs.");
  if (const auto [tested, used] = correction_counts(c); tested > 0)
    w.text("A fixed step's error has the expansion e = C h^p (1 + d h + O(h²)) (Hairer, Nørsett & Wanner, *Solving "
           "ODEs I*, Thm II.8.1). At this throw's coarsest steps the spinning stone turns through an angle of order one "
           "radian in a step, far from h → 0, so the second term bends a single power, whose interval can then miss p "
           "while the pairwise orders approach it. A fixed-step series with at least 4 points whose error falls at "
           "every halving (" + fmt(tested) + " here; an error that rises as h shrinks is not approaching C h^p) is "
           "therefore also fitted as log e = log C + p log h + d h, and that fit's p and interval (Student t, n − 3 "
           "degrees of freedom, so wider) are used where the extra term lowers the residual significantly (F test at "
           "95 %): " + fmt(used) + " of the " + fmt(tested) + " series, marked *with h^(p+1)* with the single "
           "power's p beside it." + adaptive.fitted);
  w.text("Throw: **" + c.text("case") + "**. The reference makes " + fmt(c.number("reference_contacts")) + " contacts and " +
         fmt(c.number("reference_bounces")) + " bounces and ends (" + c.text("reference_outcome") + ") at " +
         fmt(c.number("reference_end_time_s"), 4) + " s. Two kinds of measurement:");
  w.bullet("*the scheme alone* — N equal steps of `realtime_step` with no contact logic, over a free-flight interval [0, " +
           fmt(c.number("flight_interval_end_s"), 3) + " s] and over an interval holding the whole first contact [" +
           fmt(c.number("contact_interval_start_s"), 4) + ", " + fmt(c.number("contact_interval_end_s"), 4) +
           "] s, starting from the reference state. Error: the largest relative error of position (in stone radii), "
           "velocity, orientation (angle) and angular momentum at the end; over the free-flight interval also the "
           "position and the orientation alone, since a part can converge faster than the whole. This isolates the "
           "integrator.");
  w.bullet("*the whole stepper* — `run_realtime` with flight step dt and contact step " + contact_step +
           ": contact start and end times, exit speed and centre-of-mass position at the end of the first contact, the "
           "bounce positions (the centre of mass where each contact ends in a take-off) and the first-touch points of "
           "every contact, and the state in free flight after the first bounce (t = " +
           fmt(c.number("free_flight_time_s"), 4) + " s). The step sizes on the axis are the flight steps.");
  w.end_list();
  w.text("Points whose error is below the difference between the reference and a check run at rtol " +
         fmt(c.number("check_rtol"), 2) + " (a bound on the reference's own error) are shown but left out of the fit, and so, on the scheme-alone "
         "intervals, are errors at or below N ε times the quantity's scale (the rounding N steps can accumulate: a scheme "
         "exact on the problem shows only that; listed below as \"at round-off\").");
  for (const auto& p : c.strings("problems")) w.text("> Could not measure: " + p);

  MarkdownTable table({"quantity", "scheme", "formal p", "observed p [95 % CI]", "pairwise p (coarse → fine)", "GCI fine",
                       "verdict"});
  const Record& series = c.at("series");
  std::ostringstream notes;
  for (const auto& key : c.strings("series_keys")) {
    const Record& s = series.at(key);
    const Record& fit = s.at("fit");
    std::string gci = "–";
    if (s.has_child("gci")) {
      // Divergent or at round-off: Celik's GCI is not defined (gci_fine is stored as 0), and "0 %"
      // read as "no error left" (GciResult::brief).
      const Record& g = s.at("gci");
      const std::string kind = g.text("kind");
      // An apparent order that is not reasonable: the formal order and Fs = 3 (gci.hpp; records
      // written before the rule have no `reverted`).
      const std::string reverted = g.has("reverted") && g.flag("reverted")
                                       ? "; p = " + fmt(g.number("order")) + " not reasonable: the formal " +
                                             fmt(g.number("order_used")) + " with Fs = " + fmt(g.number("safety_factor"))
                                       : "";
      gci = kind == "divergent" || kind == "converged to round-off"
                ? "none (" + kind + ")"
                : fmt(100 * g.number("gci_fine"), 2) + " % (" + kind + reverted + ")";
    }
    table.row({s.text("description"), s.text("scheme"),
               fmt(s.number("formal_order")) + (s.flag("against_tolerance") ? " (in tol)" : ""), observed(fit),
               list_text(fit.table("pairwise").column("order")), gci, verdict_markdown(fit.at("verdict"))});
    for (const auto& line : left_out(s, true)) notes << "* " << line << "\n";
  }
  w.table(table);
  if (!notes.str().empty()) w.text("Runs left out of the fits, with the reason:\n\n" + notes.str());
  // A scheme whose free-flight state converges faster than its formal order: say which part does.
  for (const auto& key : c.strings("series_keys")) {
    const Record& st = series.at(key);
    if (st.text("quantity") != "flight_interval_state") continue;
    const std::string sc = st.text("scheme");
    const std::string pk = "flight_interval_position." + sc, ok = "flight_interval_orientation." + sc;
    if (!series.has_child(pk) || !series.has_child(ok)) continue;
    const Record &fs = st.at("fit"), &fp = series.at(pk).at("fit"), &fo = series.at(ok).at("fit");
    const double formal = st.number("formal_order");
    // Faster by more than the judgement's tolerance: the whole interval above formal + tolerance.
    const double margin = formal + fs.at("verdict").number("tolerance");
    // And only where the stored verdicts say "another order" (an error that grows at some refinement
    // establishes none, whatever its interval).
    const std::string other = to_string(OrderVerdict::converges_at_other_order);
    if (!fs.flag("valid") || !(fs.number("order_low") > margin) || fs.at("verdict").text("verdict") != other) continue;
    // The orientation faster than the state's formal order: "another order" against the formal one
    // (reports before 7 December), or, where its series expects a steady spin's order above the
    // formal one (steady_spin_order, stone_stepper.hpp), at that order.
    const std::string at_expected = to_string(OrderVerdict::converges_at_expected_order);
    const bool spin_expected = series.at(ok).number("formal_order") > formal;
    const bool orientation_faster = fo.flag("valid") && fo.number("order_low") > margin &&
                                    (fo.at("verdict").text("verdict") == other ||
                                     (spin_expected && fo.at("verdict").text("verdict") == at_expected));
    w.text("`" + sc + "` on the free-flight interval converges faster than its formal order " + fmt(formal) +
           " (state: p = " + observed(fs) + "). By part: orientation p = " + observed(fo) + "; position p = " +
           observed(fp) + ", pairwise " + list_text(fp.table("pairwise").column("order")) + ". " +
           (orientation_faster
                ? "The orientation converges faster than the formal order, and it dominates the state error. In a "
                  "steady spin a step multiplies the quaternion by the scheme's stability polynomial R(φ) (φ = ωh/2): "
                  "for an odd order p its leading error changes the quaternion's length, not its angle, and the "
                  "renormalisation removes it, so the attitude converges at p + 1 (steady_spin_order, "
                  "solvers/realtime/stone_stepper.hpp" +
                      (spin_expected ? std::string(", the order its row expects") : std::string()) +
                      (sc == "bs32" ? std::string("; bs32's R = 1 + iφ − φ²/2 − iφ³/6 leaves a phase error of φ⁵/30 a step: order 4")
                                    : std::string()) +
                      "). " + position_words(fp, formal)
                : "The orientation does not converge faster either: this is not explained here."));
  }

  w.lead("The events' orders.",
         "Contact start (the first touch), the first-touch points, contact end and the sinking are located inside the "
         "step on the step's cubic Hermite interpolant (solvers/README.md), so each fixed scheme should locate them at "
         "its own order up to 4 (RK4: 4) and the adaptive scheme in proportion to its tolerance. The fixed schemes' "
         "steps end at the kinks named here (`kinks` = " +
             (c.has("fixed_kinks") ? "`" + c.text("fixed_kinks") + "`" : std::string("not recorded")) +
             "; `all`: every vertex crossing and every wet face's and the air disk's flow switch, located on the "
             "step's interpolant, and under `savitsky` and `savitsky_wagner` the distribution's own switches: "
             "where the wetted span's ends change vertex, a face's flow switches at its centre of pressure, the "
             "planing share reaches 1, a face joins or leaves the loaded region, and under `savitsky_wagner` where "
             "a vertex crosses the raised waterline or the deepest vertex changes, model/stone/load_switches.hpp): "
             "a step taken across a kink makes an O(h²)–O(h³) local error there, so without them no scheme shows "
             "more than order 2–3 through a contact. Where the loaded region changes the loads jump, and a jump "
             "inside a step costs O(h) whatever the scheme, even where it is located, for a stage can lie past it "
             "while the trajectory does not; so the fixed schemes hold the loaded region over each step, and the "
             "reference over each segment between its restarts at every event (solvers/README.md). The same fits "
             "and verdicts as above, one row per event:");
  w.table(event_table(c));
  {
    // The same events under every law and distribution.
    std::vector<std::string> items;
    auto add = [&](const std::string& law, const Record& r) {
      const Record& law_series = r.at("series");
      std::string cells;
      for (const auto& [q, words] : event_quantities()) {
        const std::string key = q + ".rk4";
        if (!law_series.has_child(key)) continue;
        const Record& fit = law_series.at(key).at("fit");
        cells += (cells.empty() ? "" : "; ") + words.substr(0, words.find(':')) + " " + observed(fit) + " (" +
                 fit.at("verdict").text("verdict") + ")";
      }
      if (!cells.empty()) items.push_back("`" + law + "`: " + cells);
    };
    add(c.text("law"), c);
    if (c.has("other_laws_list"))
      for (const auto& law : c.strings("other_laws_list")) add(law, c.at("other_laws").at(law));
    if (!items.empty()) {
      const bool all = c.has("fixed_kinks") && c.text("fixed_kinks") == "all";
      w.text(std::string(all ? "Every law's and distribution's non-smooth points are located here, so RK4's events can "
                               "show order 4 through the contacts under each, once its steps are short against the "
                               "events' spacing (see *How to read it* below)"
                             : "The fixed schemes' steps end at every law's non-smooth points only with `kinks` = "
                               "`all`, not run here") +
             ". RK4's events by law and distribution:");
      for (const auto& it : items) w.bullet(it);
      w.end_list();
    }
  }

  const std::string xl = "flight step dt (s), contact step " + contact_step;
  w.figure(series_figure("conv_flight_interval", "Scheme alone, free-flight interval: error against step", c,
                         "flight_interval_state", "step h (s)", "relative state error"));
  w.figure(series_figure("conv_contact_interval", "Scheme alone, interval holding the first contact: error against step", c,
                         "contact_interval_state", "step h (s)", "relative state error"));
  w.figure(series_figure("conv_bounce_positions", "Whole stepper: bounce-position error against flight step", c,
                         "bounce_positions", xl, "largest bounce-position error (m)"));
  w.figure(series_figure("conv_contact_end", "Whole stepper: error of the first contact's end time", c, "contact1_end_time",
                         xl, "error (s)"));
  w.figure(series_figure("conv_free_flight", "Whole stepper: state error in free flight after the first bounce", c,
                         "free_flight_state", xl, "relative state error"));
  // The first adaptive scheme's figure keeps the name it had when it was the only one.
  const auto pairs = adaptive_schemes(c);
  for (std::size_t i = 0; i < pairs.size(); ++i)
    w.figure(tolerance_figure(c, pairs[i].first,
                              i == 0 ? std::string("conv_adaptive_tolerance") : "conv_adaptive_tolerance_" + pairs[i].first));
  {
    const Record& ev = c.at("events");
    const Table& cr = ev.table("crowding");
    std::string steps;
    for (std::size_t i = 0; i < cr.rows(); ++i)
      steps += (i ? ", " : "") + fmt(cr.column("h_s")[i], 2) + " s: " + fmt(100 * cr.column("fraction")[i], 2) + " %";
    w.lead("Events inside the first contact.",
           "The reference locates " + fmt(ev.number("count"), 6) + " events (vertex crossings, face switches) between " +
               fmt(ev.number("contact_start_s"), 4) + " and " + fmt(ev.number("contact_end_s"), 4) +
               " s: consecutive events are " + fmt(ev.number("min_spacing_s"), 2) + " s apart at the least and " +
               fmt(ev.number("median_spacing_s"), 2) + " s at the median. Share of the scheme-alone steps inside the contact "
               "that hold two or more events: " + steps + ".");
  }
  w.lead("How to read it.",
         "In free flight the forces are smooth and every scheme should show its formal order. Through a contact the "
         "water force is only piecewise smooth in time: the wetted area of a triangle grows like depth² when a vertex goes "
         "under, and a face's force switches off when its normal velocity changes sign, so the force is continuous with "
         "a jump in its second derivative (Newtonian law) or its first (planing law, ∝ u) at every such event, and under "
         "the savitsky distributions the force itself jumps where a face joins or leaves the loaded region. A fixed-step "
         "method stepping across such an event makes a local error of O(h³), O(h²) or O(h) there, so the scheme alone "
         "shows at most order 3, 2 or 1 through a contact, and then only once its steps are short against the spacing "
         "of the events; until then the fit is pre-asymptotic and its verdict says so. The whole stepper adds its own "
         "event handling (contact start and end located by interpolation inside the step, and the kinks above) and "
         "coarse steps can change the contact list itself (listed above): such runs have no bounce-position error.");

  // Every other water law: the same series, compactly.
  if (c.has("other_laws_list") && !c.strings("other_laws_list").empty()) {
    w.subheading("The other water laws");
    w.text("The same throw and the same measurements with each other law (its published C_w); the table above is for `" +
           c.text("law") + "`. Same verdict rules; each cell is the observed order with its 95 % interval and the verdict.");
    const Record& others = c.at("other_laws");
    for (const auto& law : c.strings("other_laws_list")) {
      const Record& l = others.at(law);
      w.lead("`" + law + "`.", "Throw: " + l.text("case") + "; the reference makes " + fmt(l.number("reference_contacts")) +
                                   " contacts and " + fmt(l.number("reference_bounces")) + " bounces and ends (" +
                                   l.text("reference_outcome") + ") at " + fmt(l.number("reference_end_time_s"), 4) + " s.");
      for (const auto& p : l.strings("problems")) w.text("> Could not measure: " + p);
      // One row per quantity, one column per scheme: observed p [95 % CI] and the verdict.
      const Record& ls = l.at("series");
      std::vector<std::string> quantities, schemes;
      for (const auto& key : l.strings("series_keys")) {
        const Record& s = ls.at(key);
        if (std::find(quantities.begin(), quantities.end(), s.text("quantity")) == quantities.end())
          quantities.push_back(s.text("quantity"));
        if (std::find(schemes.begin(), schemes.end(), s.text("scheme")) == schemes.end()) schemes.push_back(s.text("scheme"));
      }
      std::vector<std::string> head{"quantity"};
      for (const auto& sc : schemes) head.push_back(sc + " (formal " + fmt(ls.at(quantities.front() + "." + sc).number("formal_order")) + ")");
      MarkdownTable lt(head);
      std::vector<std::string> dropped;
      for (const auto& q : quantities) {
        std::vector<std::string> cells{ls.at(q + "." + schemes.front()).text("description")};
        for (const auto& sc : schemes) {
          const std::string key = q + "." + sc;
          if (!ls.has_child(key)) {
            cells.push_back("–");
            continue;
          }
          const Record& fit = ls.at(key).at("fit");
          cells.push_back(observed(fit) + ": **" + fit.at("verdict").text("verdict") + "**");
          for (const auto& line : left_out(ls.at(key), false))
            if (std::find(dropped.begin(), dropped.end(), line) == dropped.end()) dropped.push_back(line);
        }
        lt.row(cells);
      }
      w.table(lt);
      if (!dropped.empty()) {
        std::string list;
        for (const auto& line : dropped) list += "* " + line + "\n";
        w.text("Runs left out of the fits, with the reason:\n\n" + list);
      }
    }
  }

  // The reference's own error against its tolerance.
  const Record& t = c.at("reference_tolerance");
  w.subheading("The reference's own error against its tolerance");
  const Table& pts = t.table("points");
  const auto rtol = pts.column("rtol");
  w.text("CVODE (" + t.text("method") + ") at rtol from " + fmt(rtol.front(), 2) + " to " + fmt(rtol.back(), 2) +
         " (atol = rtol × " + fmt(t.number("atol_ratio"), 2) + ") against a run at rtol " + fmt(t.number("truth_rtol"), 2) +
         ". A slope near 1 means the error control works through the located contact events (tolerance proportionality).");
  MarkdownTable t2({"rtol", "bounces", "bounce-position error (m)", "contact-time error (s)", "RHS evaluations", "CPU (s)",
                    "note"});
  const auto& probs = t.strings("problems");
  for (std::size_t i = 0; i < pts.rows(); ++i)
    t2.row({fmt(rtol[i], 2), fmt(pts.column("bounces")[i]), fmt(pts.column("bounce_position_error_m")[i]),
            fmt(pts.column("contact_time_error_s")[i]), fmt(pts.column("rhs_evaluations")[i], 8),
            fmt(pts.column("cpu_s")[i], 3), probs[i]});
  w.table(t2);
  w.verdict("Slope of log(bounce-position error) against log(rtol)", t.at("bounce_position_fit").at("verdict"));
  w.verdict("Slope of log(contact-time error) against log(rtol)", t.at("contact_time_fit").at("verdict"));
  w.verdict("Error from rtol " + fmt(t.number("drop_from_rtol"), 2) + " to " + fmt(t.number("drop_to_rtol"), 2),
            t.at("drop"));
  w.end_list();
  {
    const PlotSeries a = table_series("bounce-position error (m)", t, "points", "rtol", "bounce_position_error_m");
    const PlotSeries b = table_series("contact-time error (s)", t, "points", "rtol", "contact_time_error_s");
    PlotSeries ideal{"slope 1", {}, {}, "lines dt 2", {}, {}};
    if (!a.y.empty() && std::isfinite(a.y.front())) ideal = power_law_guide("slope 1", rtol, rtol.front(), a.y.front(), 1);
    PlotAxes ax;
    ax.x_label = "rtol";
    ax.y_label = "error against rtol " + fmt(t.number("truth_rtol"), 2);
    ax.log_x = ax.log_y = true;
    w.figure(line_figure("ref_tolerance", "CVODE reference: error against tolerance", ax, {a, b, ideal}, "rtol", "error"));
  }
  return w.finish();
}

}  // namespace stoneskip
