// Section 2 of the stones report: what accuracy costs — work-precision diagrams of the real-time
// stepper against CVODE, and the cheapest setting for a given bounce-position error — formatted
// from the stored record.
#include <cmath>
#include <sstream>

#include "reports/common/markdown.hpp"
#include "reports/common/plot.hpp"
#include "reports/stones/report_sections.hpp"

namespace stoneskip {

namespace {

std::string range_text(const std::vector<double>& v) {
  if (v.empty()) return "–";
  return fmt(v.front(), 3) + " … " + fmt(v.back(), 3);
}

}  // namespace

SectionOutput work_precision_section(const Record& c) {
  SectionWriter w(c, "2. Speed against error, each water law");
  w.lead("What is measured.",
         "Each throw is solved by the real-time stepper's fixed schemes over a range of flight steps (" +
             range_text(c.table("realtime_dt_s").column("dt_s")) + " s, each family with its contact step), by its "
             "adaptive scheme over tolerances rtol = atol_m " +
             (c.has_table("adaptive_rtol") ? range_text(c.table("adaptive_rtol").column("rtol")) : std::string("–")) +
             " and by CVODE over rtol " + range_text(c.table("rtol").column("rtol")) +
             " (atol = rtol × " + fmt(c.number("atol_ratio"), 2) +
             "). The error (the *headline* of each throw) is the largest distance between a run's bounce positions (the "
             "centre of mass where a contact ends in a take-off) and those of a CVODE run at rtol " +
             fmt(c.number("truth_rtol"), 2) + " — or, for a throw whose reference never bounces, the distance between "
             "the points where the two sank" +
             " (the *truth*; a second run at " + fmt(c.number("truth_check_rtol"), 2) +
             " says how far the truth itself can be trusted). The cost is " + c.text("clock") + " (" +
             fmt(c.number("repeats")) +
             " repeats), and the number of right-hand-side evaluations. A run whose contact list differs from the "
             "reference's (a missed or extra contact, a different bounce count) has no meaningful bounce-position error: "
             "it is listed as a failure below the figures, not dropped.");
  for (const auto& key : c.strings("throws")) {
    const Record& t = c.at(key);
    const auto& families = t.strings("families");
    w.subheading("Throw: " + t.text("label"));
    const std::string what = t.text("headline") + " error (m)";
    const double unc = t.number("truth_uncertainty_m");
    // Data written before the kinks were stored says nothing of them.
    const std::string kinks =
        t.has("fixed_kinks")
            ? " The fixed schemes' steps end at kinks `" + t.text("fixed_kinks") + "`" +
                  (t.text("fixed_kinks") == "none"
                       ? " (their default: a kink inside a step caps a scheme near order 2 through a contact; §1 "
                         "says where its own fixed steps end, so the two sections' errors of one scheme can differ)."
                       : ".")
            : std::string();
    w.text("Water law: `" + t.text("law") + "`." + kinks + " Reference (rtol " + fmt(c.number("truth_rtol"), 2) + "): " + fmt(t.number("truth_contacts")) + " contacts, " +
           fmt(t.number("truth_bounces")) + " bounces, " + t.text("truth_outcome") + " at " +
           fmt(t.number("truth_end_time_s"), 4) + " s; " + fmt(t.number("truth_steps"), 8) + " steps, " +
           fmt(t.number("truth_rhs_evaluations"), 8) + " RHS evaluations, " + fmt(t.number("truth_segments"), 8) +
           " integration segments between located events, " + fmt(t.number("truth_cpu_s"), 3) + " s CPU. " +
           (std::isfinite(unc) ? "The check run moves its bounce positions by " + fmt(unc, 2) + " m."
                               : "**The check run does not reproduce its contact list** (" + t.text("truth_check_problem") +
                                     "): this throw's bounces are sensitive to perturbations far below any solver's "
                                     "error, so no solver can be judged on them."));
    std::vector<PlotSeries> by_cpu, by_rhs, times_by_rhs;
    for (std::size_t f = 0; f < families.size(); ++f) {
      TableSource how;
      how.y_column = "headline_error_m";
      how.where_column = "family";  // the rows of this solver family
      how.where_value = static_cast<double>(f);
      how.x_column = "cpu_s";
      by_cpu.push_back(table_series(families[f], t, "points", how));
      how.x_column = "rhs_evaluations";
      by_rhs.push_back(table_series(families[f], t, "points", how));
      how.y_column = "contact_time_error_s";
      times_by_rhs.push_back(table_series(families[f], t, "points", how));
    }
    // Per family: 1 where its setting is a tolerance (the adaptive scheme), else a flight step or CVODE's rtol.
    const std::vector<double> adaptive_family =
        t.has_table("family_kinds") ? t.table("family_kinds").column("adaptive") : std::vector<double>(families.size(), 0.0);
    PlotAxes ax;
    ax.x_label = "CPU time per throw (s)";
    ax.y_label = what;
    ax.log_x = ax.log_y = true;
    w.figure(line_figure("wp_" + key + "_cpu", "Work-precision (CPU time): " + t.text("label"), ax, by_cpu, "cpu_s", "error_m"));
    ax.x_label = "right-hand-side evaluations per throw";
    w.figure(line_figure("wp_" + key + "_rhs", "Work-precision (RHS evaluations): " + t.text("label"), ax, by_rhs,
                         "rhs_evaluations", "error_m"));
    ax.y_label = "largest contact start or end time error (s)";
    w.figure(line_figure("wp_" + key + "_times", "Contact times against RHS evaluations: " + t.text("label"), ax,
                         times_by_rhs, "rhs_evaluations", "error_s"));
    w.lead("The cheapest setting of each solver that reaches a " + t.text("headline") + " error", "");
    MarkdownTable ans({"target error (m)", "solver", "setting (dt s / tolerance / rtol)", "error (m)", "CPU (s)", "RHS evaluations"});
    const Table& ch = t.table("cheapest");
    for (std::size_t i = 0; i < ch.rows(); ++i) {
      const bool found = ch.column("found")[i] != 0;
      ans.row({fmt(ch.column("target_m")[i], 2), families.at(static_cast<std::size_t>(ch.column("family")[i])),
               found ? fmt(ch.column("setting")[i], 3) : "not reached", found ? fmt(ch.column("error_m")[i], 2) : "–",
               found ? fmt(ch.column("cpu_s")[i], 3) : "–", found ? fmt(ch.column("rhs_evaluations")[i], 8) : "–"});
    }
    w.table(ans);
    const Table& a = t.table("answer");
    // In the paper convention a throw's contact list is chaotic (model/README.md §2.4): the truth's
    // own check run may hold another one, so which runs keep the truth's list, and so reach these
    // errors, is chance at this accuracy, not a ranking of the solvers.
    if (t.has_text("convention") && t.text("convention") == "paper")
      w.text("This throw is in the paper convention, whose contact list is chaotic: a run reaches an error below only if "
             "it happens to keep the truth's contact list, so the lines below do not rank the solvers (section 3b "
             "compares them on ensembles).");
    for (std::size_t i = 0; i < a.rows(); ++i) {
      auto col = [&](const char* k) { return a.column(k)[i]; };
      std::string line = t.text("headline") + " within " + fmt(col("target_m"), 2) + " m: ";
      if (col("realtime_family") >= 0)
        line += "the cheapest real-time setting is " + families.at(static_cast<std::size_t>(col("realtime_family"))) +
                (adaptive_family.at(static_cast<std::size_t>(col("realtime_family"))) != 0
                     ? " at tolerance " + fmt(col("realtime_setting"), 2)
                     : " with a flight step of " + fmt(col("realtime_setting"), 3) + " s") +
                " (" + fmt(1000 * col("realtime_cpu_s"), 3) +
                " ms CPU per throw, " + fmt(col("realtime_rhs_evaluations"), 8) + " RHS evaluations)";
      else
        line += "no real-time setting tried gets there";
      if (col("cvode_family") >= 0)
        line += "; the cheapest CVODE setting is " + families.at(static_cast<std::size_t>(col("cvode_family"))) + " at rtol " +
                fmt(col("cvode_setting"), 2) + " (" + fmt(1000 * col("cvode_cpu_s"), 3) + " ms, " +
                fmt(col("cvode_rhs_evaluations"), 8) + " RHS evaluations)";
      else
        line += "; no CVODE setting tried gets there";
      w.bullet(line + ".");
    }
    w.end_list();
    const auto& fails = t.strings("failures");
    if (!fails.empty()) {
      std::string list;
      for (const auto& f : fails) list += "* " + f + "\n";
      w.text("Failures (no error plotted):\n\n" + list);
    }
  }
  if (c.has_child("adaptive_choice") && c.at("adaptive_choice").flag("studied")) {
    const Record& a = c.at("adaptive_choice");
    w.subheading("The adaptive stepper's default tolerance");
    const double chosen = a.number("tolerance"), def = a.number("default_tolerance");
    const std::vector<std::string> set_aside = a.has("set_aside") ? a.strings("set_aside") : std::vector<std::string>{};
    std::string s;
    if (!set_aside.empty()) {
      std::vector<std::string> italic;
      for (const std::string& n : set_aside) italic.push_back("*" + n + "*");
      const std::string names = and_list(italic);
      s += "The choice is made on the physical convention's throws, the convention the cases' default serves. " +
           std::string(set_aside.size() == 1 ? "One paper-convention throw is" : fmt(double(set_aside.size())) + " paper-convention throws are") +
           " set aside (" + names + "): the printed equations create energy in a contact, which makes a contact list "
           "chaotic, decided on ensembles of perturbed throws in section 3b, not on one run. ";
    }
    s += "Over the " + fmt(a.number("throws")) + (set_aside.empty() ? "" : " physical-convention") + " throws above, `" +
         a.text("family") + "` ";
    if (a.flag("found")) {
      s += "keeps every throw's contact list (so its bounce count) at every tolerance from the tightest run up to " +
           fmt(chosen, 2) + ", the loosest such tolerance: the study's choice. There its worst contact start or end "
           "time error is " + fmt(a.number("worst_contact_time_error_s"), 2) + " s and its worst headline error " +
           fmt(a.number("worst_headline_error_m"), 2) + " m, with " + fmt(a.number("rhs_evaluations"), 8) +
           " right-hand sides over the throws. ";
      s += def == chosen ? "The cases' default tolerance (rtol = atol_m = " + fmt(def, 2) + ") is this choice."
           : def < chosen ? "The cases' default tolerance (rtol = atol_m = " + fmt(def, 2) +
                                ") is tighter than this choice: it keeps the bounce counts of the bench grid's wider "
                                "ensemble (solvers/README.md), which these few throws do not test."
                          : "**The cases' default tolerance (rtol = atol_m = " + fmt(def, 2) +
                                ") is looser than this choice: on these throws it loses contacts.**";
    } else if (a.number("throws") == 0) {
      s += "has no physical-convention throw to choose on: the cases' default (rtol = atol_m = " + fmt(def, 2) +
           ") is neither supported nor refuted here.";
    } else {
      s += "changes some throw's contact list even at its tightest tolerance: the study cannot choose one, and the "
           "cases' default (rtol = atol_m = " + fmt(def, 2) + ") is not supported by it.";
    }
    w.text(s);
    MarkdownTable tt({"tolerance", "throws keeping the reference's contact list"});
    const Table& per = a.table("per_tolerance");
    for (std::size_t i = 0; i < per.rows(); ++i)
      tt.row({fmt(per.column("tolerance")[i], 2), fmt(per.column("throws_keeping_contacts")[i]) + " of " + fmt(a.number("throws"))});
    w.table(tt);
  }
  if (c.has_child("restarts")) {
    const Record& r = c.at("restarts");
    const auto& strategies = r.strings("strategies");
    const auto& methods = r.strings("methods");
    w.subheading("CVODE's restart strategies");
    std::string throws;
    for (const auto& l : r.strings("throws")) throws += (throws.empty() ? "" : "; ") + ("*" + l + "*");
    w.text("Where the right-hand side is only non-smooth (a vertex crossing or a face's switch leaves the force "
           "continuous) a restart of CVODE's multistep history may not pay. Each strategy — `every_event` (locate every "
           "vertex crossing and face switch and restart at each), `every_crossing` (restart at vertex crossings only), "
           "`at_jumps` (restart only where the force jumps: a flat face reaching or leaving the surface, and a contact's "
           "start), `never` — solves each throw at each method and rtol (atol = rtol × " +
           fmt(r.number("atol_ratio"), 2) + "), against a truth that restarts at every event at rtol " +
           fmt(r.number("truth_rtol"), 2) + ". A strategy keeps the contact times where, at every method and rtol, no run "
           "fails or changes its contact list and its worst contact-start or -end error is at most the larger of " +
           fmt(r.number("time_tolerance_s"), 2) + " s and " + fmt(r.number("error_factor"), 2) +
           "× `every_event`'s own worst error there. Cost: right-hand-side evaluations (the verdict's measure) and " +
           r.text("clock") + " (" + fmt(r.number("repeats")) + " repeats). The throws: " + throws + ".");
    w.verdict("Cheapest strategy that keeps the contact times (the reference's default is `" + r.text("default") + "`)",
              r.at("verdict"));
    w.end_list();
    MarkdownTable tot({"strategy", "failed runs", "worst error / tolerance", "RHS evaluations", "integration segments",
                       "CPU (s)"});
    for (const auto& name : strategies) {
      const Record& g = r.at(name);
      tot.row({code(name), fmt(g.number("failed")), fmt(g.number("error_ratio"), 3), fmt(g.number("rhs_evaluations"), 8),
               fmt(g.number("segments"), 8), fmt(g.number("cpu_s"), 3)});
    }
    w.table(tot);
    const Table& sum = r.table("summaries");
    MarkdownTable st({"method", "rtol", "strategy", "throws", "failed", "RHS evaluations", "segments", "CPU (s)",
                      "worst contact-time error (s)", "tolerance (s)", "keeps"});
    for (std::size_t i = 0; i < sum.rows(); ++i) {
      auto col = [&](const char* k) { return sum.column(k)[i]; };
      st.row({methods.at(static_cast<std::size_t>(col("method"))), fmt(col("rtol"), 2),
              code(strategies.at(static_cast<std::size_t>(col("strategy")))), fmt(col("throws")), fmt(col("failed")),
              fmt(col("rhs_evaluations"), 8), fmt(col("segments"), 8), fmt(col("cpu_s"), 3),
              fmt(col("worst_contact_time_error_s"), 2), fmt(col("tolerance_s"), 2), col("keeps") != 0 ? "yes" : "no"});
    }
    w.table(st);
  }
  w.lead("How to read it.",
         "Lower left is better. Each family's curve ends where its runs stop reproducing the reference's contacts: "
         "coarse real-time steps do not merely lose accuracy, they change the contact list, so below some step the "
         "bounce count itself is wrong. To pick the adaptive scheme's tolerance for an accuracy: on the figure of the "
         "error you care about (bounce positions, or contact times), find the `bs32` point whose error is below your "
         "target on every throw and take its tolerance; a tolerance whose run is listed among the failures (a changed "
         "contact list) is too loose for bounce counts whatever its error.");
  return w.finish();
}

}  // namespace stoneskip
