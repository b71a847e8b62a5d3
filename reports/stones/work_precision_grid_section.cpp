// Subsection 2.1 of the stones report: work against precision over a grid of throws — bounce-count
// agreement with its Wilson interval and contact-time errors against right-hand sides, per solver
// family — and the adaptive stepper's default tolerance the grid supports, formatted from the
// stored record (verification/stones/work_precision_grid.hpp decides the choice).
#include <algorithm>
#include <cmath>

#include "reports/common/markdown.hpp"
#include "reports/common/plot.hpp"
#include "reports/stones/report_sections.hpp"
#include "verification/stones/work_precision_grid_check.hpp"

namespace stoneskip {

namespace {

// A default tighter than the tolerance the grid chose: supported where the grid ran it or a tighter
// one (every tolerance from the chosen one down met the rule); beyond the grid's tightest, the grid
// says only that a looser one would do (audit: "the grid supports it" was said of 1e-9 on a grid
// whose tightest run was 1e-8).
std::string tighter_words(const Record& ch, double def) {
  double tightest = 1e300;
  if (ch.has_table("per_tolerance"))
    for (const double t : ch.table("per_tolerance").column("tolerance")) tightest = std::min(tightest, t);
  if (def >= tightest) return "the grid supports it and a looser one would do on these throws.";
  return "tighter than any the grid ran (the tightest, " + fmt(tightest, 2) +
         ", met the rule): a looser one would do on these throws, and the default itself was not run.";
}


std::string list_text(const std::vector<double>& v, const std::string& unit) {
  std::string s;
  for (double x : v) s += (s.empty() ? "" : ", ") + fmt(x, 3);
  return s + unit;
}

// The real-time budget: bs32 at the cases' default tolerance with at most N right-hand sides per
// frame, the smallest budget the grid's rule picks, and per budget what a frame costs at most.
void budget_text(SectionWriter& w, const Record& c) {
  const Record& b = c.at("budget_choice");
  const double frame_ms = 1000 * b.number("frame_dt_s");
  std::string s = "`" + b.text("family") + "` runs `bs32` at rtol = atol_m " + fmt(b.number("rtol"), 2) +
                  " (the cases' default) with at most N right-hand sides per " + fmt(frame_ms, 3) +
                  " ms frame: when the error test would need more, the step is taken at the size the budget "
                  "allows and accepted whatever its error (solvers/realtime/stone_stepper.hpp, \"Budget\"). Its rows in the "
                  "table above are the error it then makes, on the same throws and against the same truths. ";
  if (b.flag("found"))
    s += "**The smallest budget that keeps the default tolerance's rule is " + fmt(b.number("rhs_per_frame"), 7) +
         " right-hand sides per frame**: " + fmt(b.number("agreeing")) + " of " + fmt(b.number("n")) +
         " throws keep the truth's bounce count there (95 % interval " + fmt(b.number("wilson_lo"), 3) + "–" +
         fmt(b.number("wilson_hi"), 3) + "), median contact-time error " + fmt(b.number("median_contact_time_error_s"), 2) + " s.";
  else
    s += "**No budget run keeps the default tolerance's rule.**";
  w.lead("The real-time budget.", s);
  w.text("In full: " + b.text("reason") + ".");
  MarkdownTable t({"RHS per frame", "meets the rule", "steps forced", "largest error ratio accepted", "CPU per RHS (µs)",
                   "CPU per frame at most (ms)", "of the frame"});
  const Table& per = b.table("per_budget");
  for (std::size_t i = 0; i < per.rows(); ++i) {
    auto col = [&](const char* k) { return per.column(k)[i]; };
    t.row({fmt(col("rhs_per_frame"), 7), col("meets") != 0 ? "yes" : "no", pct(col("forced_step_fraction")),
           fmt(col("max_error_ratio"), 3), fmt(1e6 * col("cpu_per_rhs_s"), 3), fmt(1e3 * col("cpu_per_frame_bound_s"), 3),
           pct(col("frame_fraction"))});
  }
  w.table(t);
  w.lead("How to read the budget.",
         "A step the budget forces is accepted with an error-test ratio above 1 (1 is the tolerance); the largest such "
         "ratio and the share of steps forced are the stepper's own account of the error it made, and the bounce counts "
         "and contact times above are the error measured against the truth. A frame's stone costs at most N right-hand "
         "sides: the CPU bound per frame is N times the mean CPU per right-hand side of that budget's runs on this "
         "machine, beside the frame it must fit in.");
}

}  // namespace

SectionOutput work_precision_grid_section(const Record& c) {
  check_work_precision_grid_record(c);  // what follows from other stored values is derived again, not trusted
  SectionWriter w(c, "2.1 Speed against error over a grid of throws: the adaptive stepper's default");
  const Record& ch = c.at("default_choice");
  const auto& families = c.strings("families");
  const double n_throws = c.number("throw_count");
  w.lead("What is measured.",
         "The base throw *" + c.text("base_label") + "* (physical convention, its own water law) at spins " +
             list_text(c.table("spins").column("spin_rev_s"), " rev/s") + " × attack angles " +
             list_text(c.table("attack_angles").column("attack_angle_deg"), "°") + ": " + fmt(n_throws) +
             " throws. Each has a truth (CVODE BDF at rtol " + fmt(c.number("truth_rtol"), 2) + ", atol = rtol × " +
             fmt(c.number("atol_ratio"), 2) + ", restarting at every event) and a second truth at rtol " +
             fmt(c.number("truth_check_rtol"), 2) + "; a throw whose two truths disagree on the bounce count is "
             "chaotic at the truth's own accuracy and is set aside, counted, as is one whose truth fails. On the " +
             fmt(c.number("kept")) + " throws kept (" + fmt(c.number("chaotic")) + " set aside as chaotic, " +
             fmt(c.number("truth_failed")) + " for a failed truth) run `bs32` at rtol = atol_m " +
             list_text(c.table("adaptive_rtol").column("rtol"), "") + ", the fixed schemes at flight steps " +
             list_text(c.table("dt_s").column("dt_s"), " s") + " (contact step × " + fmt(c.number("contact_ratio"), 2) +
             ") and CVODE " + c.text("method") + " at rtol " + list_text(c.table("cvode_rtol").column("rtol"), "") +
             ". Per family and setting: the fraction of throws whose bounce count equals the truth's, with its 95 % "
             "Wilson score interval (Wilson 1927; Newcombe 1998); the median and largest contact start or end time error "
             "over the throws whose contact lists match the truth's; the mean right-hand sides and " + c.text("clock") +
             " per throw. A failed run counts as a disagreeing throw and is listed below.");
  const auto& aside = c.strings("set_aside");
  if (!aside.empty()) {
    std::string list;
    for (const auto& a : aside) list += "* " + a + "\n";
    w.text("Set aside:\n\n" + list);
  }

  // The default the grid supports, beside the cases' default.
  const double chosen = ch.number("tolerance"), def = ch.number("default_tolerance");
  const std::string by = ch.text("agreement_bound") == "wilson_lower" ? "the Wilson 95 % lower bound of the agreement"
                                                                      : "the agreement's point estimate";
  std::string s = "The rule: the loosest `" + ch.text("family") + "` tolerance at which, and at every tighter one, " + by +
                  " is at least " + fmt(ch.number("agreement_target"), 3) + " and the median contact-time error is below " +
                  fmt(ch.number("contact_time_threshold_s"), 2) + " s. ";
  const std::string where = ch.text("beside_default");
  if (ch.flag("found")) {
    s += "**The grid supports rtol = atol_m = " + fmt(chosen, 2) + "**: there " + fmt(ch.number("agreeing")) + " of " +
         fmt(ch.number("n")) + " throws keep the truth's bounce count (95 % interval " + fmt(ch.number("wilson_lo"), 3) +
         "–" + fmt(ch.number("wilson_hi"), 3) + "), the median contact-time error is " +
         fmt(ch.number("median_contact_time_error_s"), 2) + " s, at " + fmt(ch.number("mean_rhs_evaluations"), 5) +
         " right-hand sides and " + fmt(1000 * ch.number("mean_cpu_s"), 3) + " ms CPU per throw. ";
    s += where == "same" ? "The cases' default (`kDefaultAdaptiveTolerance`, " + fmt(def, 2) + ") is this tolerance: they agree."
         : where == "default_tighter"
             ? "The cases' default (`kDefaultAdaptiveTolerance`, " + fmt(def, 2) + ") is tighter: " + tighter_words(ch, def)
             : "**The cases' default (`kDefaultAdaptiveTolerance`, " + fmt(def, 2) +
                   ") is looser than the grid supports: it does not meet the rule here.**";
  } else {
    s += "**No tolerance run meets it**, so the grid does not support the cases' default (`kDefaultAdaptiveTolerance`, " +
         fmt(def, 2) + ").";
  }
  s += " With every throw agreeing, the Wilson lower bound reaches " + fmt(ch.number("agreement_target"), 3) + " only from " +
       fmt(ch.number("throws_to_show_target")) + " throws on: " +
       (ch.number("n") >= ch.number("throws_to_show_target")
            ? std::string("this grid is large enough to show it.")
            : "this grid of " + fmt(ch.number("n")) + " kept throws can show a target of that size only as a point "
              "estimate, not with 95 % confidence.");
  w.lead("What it finds.", s);
  w.text("In full: " + ch.text("reason") + ".");
  const auto& missed = c.strings("adaptive_disagreements");
  if (!missed.empty()) {
    std::string list;
    for (const auto& m : missed) list += "* " + m + "\n";
    w.text("The `" + ch.text("family") + "` runs whose bounce count differs from the truth's:\n\n" + list);
  }

  // The table per family and setting, and the figures drawn from it.
  MarkdownTable t({"family", "setting (tolerance, dt s or RHS per frame)", "same count", "95 % interval", "contact lists match",
                   "median contact-time error (s)", "largest (s)", "RHS per throw", "CPU per throw (ms)", "failed"});
  const Table& sum = c.table("summary");
  for (std::size_t i = 0; i < sum.rows(); ++i) {
    auto col = [&](const char* k) { return sum.column(k)[i]; };
    t.row({families.at(static_cast<std::size_t>(col("family"))), fmt(col("setting"), 7),
           fmt(col("agreeing")) + " of " + fmt(col("n")), fmt(col("wilson_lo"), 3) + "–" + fmt(col("wilson_hi"), 3),
           fmt(col("timed")), fmt(col("median_contact_time_error_s"), 2), fmt(col("max_contact_time_error_s"), 2),
           fmt(col("mean_rhs_evaluations"), 5), fmt(1000 * col("mean_cpu_s"), 3), fmt(col("failed"))});
  }
  std::vector<PlotSeries> agreement, times;
  for (std::size_t f = 0; f < families.size(); ++f) {
    TableSource how;
    how.where_column = "family";  // the rows of this family
    how.where_value = static_cast<double>(f);
    how.x_column = "mean_rhs_evaluations";
    how.y_column = "agreement";
    const std::string colour = " lt " + std::to_string(f + 1);
    agreement.push_back(table_series(families[f], c, "summary", how, "linespoints" + colour));
    // The Wilson 95 % lower bound in the family's colour, dashed (the table's interval; the rule
    // may judge on it): one legend entry says what the dashed lines are.
    how.y_column = "wilson_lo";
    agreement.push_back(table_series(f == 0 ? "dashed: each family's Wilson 95 % lower bound" : "", c, "summary", how,
                                     "lines dt 2" + colour));
    how.y_column = "median_contact_time_error_s";
    how.rows = TableSource::Rows::y_positive;  // no contact list matched: a gap
    times.push_back(table_series(families[f], c, "summary", how));
  }
  PlotAxes ax;
  ax.x_label = "right-hand sides per throw (mean over the grid)";
  ax.y_label = "fraction of throws with the truth's bounce count";
  ax.log_x = true;
  // The rule's target, as a line (verification/stones/work_precision_grid.hpp).
  ax.extra = "set yrange [0:1.05]\nset arrow from graph 0, first " + fmt(ch.number("agreement_target"), 6) +
             " to graph 1, first " + fmt(ch.number("agreement_target"), 6) + " nohead dt 3 lw 2 lc rgb '#555555' front\n" +
             "set label 'target " + fmt(ch.number("agreement_target"), 3) + "' at graph 0.01, first " +
             fmt(ch.number("agreement_target"), 6) + " offset 0, 0.6 front";
  w.figure(line_figure("wpgrid_agreement", "Bounce-count agreement over the grid against work", ax, agreement,
                       "rhs_evaluations", "agreement"));
  ax.y_label = "median contact start or end time error (s)";
  ax.log_y = true;
  ax.extra = "";
  w.figure(line_figure("wpgrid_contact_times", "Median contact-time error over the grid against work", ax, times,
                       "rhs_evaluations", "error_s"));
  w.table(t);
  const auto& fails = c.strings("failures");
  if (!fails.empty()) {
    std::string list;
    for (const auto& f : fails) list += "* " + f + "\n";
    w.text("Failed runs (counted as disagreeing):\n\n" + list);
  }
  w.lead("How to read it.",
         "Up and to the left is better on the first figure, down and to the left on the second. A family's agreement "
         "need not rise steadily as it tightens: a throw near a bounce-count threshold may be kept by chance at a loose "
         "setting. The interval is what the grid can say about throws like these; a fraction from a few throws is a "
         "point estimate with a wide interval, not a guarantee.");
  if (c.has_number("budget_run") && c.flag("budget_run")) budget_text(w, c);
  SectionOutput out = w.finish();
  out.markdown.insert(0, "#");  // a subsection of section 2: "### 2.1 …"
  return out;
}

}  // namespace stoneskip
