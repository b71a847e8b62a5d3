// Section 2 of the stones report: what accuracy costs — work-precision diagrams of the real-time
// stepper against CVODE, and the step the real-time model needs for a given bounce-position error.
#include <cmath>
#include <sstream>

#include "reports/common/markdown.hpp"
#include "reports/stones/plot_helpers.hpp"
#include "reports/stones/report_sections.hpp"

namespace stoneskip {

SectionOutput work_precision_section(const WorkPrecisionResult& wp, const H5Group& data) {
  SectionOutput out;
  H5Group g = data.create_group("work_precision");
  std::ostringstream md;
  md << "## 2. Speed against error\n\n"
     << "**What is measured.** Each throw is solved by the real-time stepper over a range of flight steps (from a "
        "60 Hz game frame, 1/60 s, down to 1.25e-4 s; contact step dt/10, and for semi-implicit Euler also dt/100 as "
        "in the shipped cases) and by CVODE, BDF and Adams, over rtol 1e-3 … 1e-9 (atol = rtol/100). The error is "
        "the largest distance between a run's bounce positions (the centre of mass where each contact ends: where "
        "the stone takes off again, or sinks) and those of a CVODE run at rtol 1e-11 (the *truth*; a second run at "
        "1e-12 says how far the truth itself can be trusted). The cost is the CPU time of one throw (the minimum of repeated runs, one thread) "
        "and the number of right-hand-side evaluations. A run whose contact list differs from the reference's "
        "(a missed or extra contact, a different bounce count) has no meaningful bounce-position error: it is "
        "listed as a failure below the figures, not dropped.\n\n";
  int idx = 0;
  for (const auto& t : wp.throws) {
    const std::string tag = "wp" + std::to_string(idx++);
    H5Group tg = g.create_group(tag);
    tg.set_attr("throw", t.label);
    Table table;
    table.columns = {"realtime", "setting", "ok", "bounces", "bounce_position_error_m", "touch_error_m",
                     "contact_time_error_s", "cpu_s", "rhs_evaluations", "steps"};
    std::vector<std::string> families;
    for (const auto& p : t.points) {
      table.add_row({p.realtime ? 1.0 : 0.0, p.setting, p.ok ? 1.0 : 0.0, static_cast<double>(p.bounces),
                     p.bounce_position_error_m, p.touch_error_m, p.contact_time_error_s, p.cpu_s,
                     static_cast<double>(p.rhs_evaluations), static_cast<double>(p.steps)});
      if (families.empty() || families.back() != p.family) families.push_back(p.family);
    }
    tg.write_table("points", table);
    tg.write_strings("family", [&] {
      std::vector<std::string> f;
      for (const auto& p : t.points) f.push_back(p.family);
      return f;
    }());

    md << "### Throw: " << t.label << "\n\n"
       << "Reference (rtol 1e-11): " << t.truth.contacts.size() << " contacts, " << t.truth.bounces << " bounces, "
       << to_string(t.truth.outcome) << " at " << fmt(t.truth.end_time_s, 4) << " s; " << t.truth.stats.steps
       << " steps, " << t.truth.stats.rhs_evaluations << " RHS evaluations, " << t.truth.stats.segments
       << " integration segments between located events, " << fmt(t.truth.stats.cpu_s, 3) << " s CPU. "
       << (std::isfinite(t.truth_uncertainty_m)
               ? "The rtol 1e-12 check moves its bounce positions by " + fmt(t.truth_uncertainty_m, 2) + " m.\n\n"
               : "**The rtol 1e-12 check does not reproduce its contact list** (" + t.truth_check_problem +
                     "): this throw's bounces are sensitive to perturbations far below any solver's error, so no "
                     "solver can be judged on them.\n\n");
    std::vector<PlotSeries> by_cpu, by_rhs;
    for (const auto& fam : families) {
      PlotSeries a, b;
      a.title = b.title = fam;
      for (const auto& p : t.points) {
        if (p.family != fam) continue;
        a.x.push_back(p.cpu_s);
        a.y.push_back(p.bounce_position_error_m);
        b.x.push_back(static_cast<double>(p.rhs_evaluations));
        b.y.push_back(p.bounce_position_error_m);
      }
      by_cpu.push_back(a);
      by_rhs.push_back(b);
    }
    PlotAxes ax;
    ax.x_label = "CPU time per throw (s)";
    ax.y_label = "bounce-position error (m)";
    ax.log_x = ax.log_y = true;
    Figure f1 = line_figure(tag + "_cpu", "Work-precision (CPU time): " + t.label, ax, by_cpu, "cpu_s", "error_m");
    ax.x_label = "right-hand-side evaluations per throw";
    Figure f2 = line_figure(tag + "_rhs", "Work-precision (RHS evaluations): " + t.label, ax, by_rhs,
                            "rhs_evaluations", "error_m");
    md << figure_markdown(f1) << figure_markdown(f2);
    out.figures.push_back(f1);
    out.figures.push_back(f2);

    // The answer: cheapest setting per family and target.
    md << "**The cheapest setting that reaches a bounce-position error**\n\n";
    MarkdownTable ans({"target error (m)", "solver", "setting (dt s / rtol)", "error (m)", "CPU (s)", "RHS evaluations"});
    for (const auto& c : t.cheapest)
      ans.row({fmt(c.target_error_m, 1), c.family, c.found ? fmt(c.setting, 3) : "not reached",
               c.found ? fmt(c.error_m, 2) : "–", c.found ? fmt(c.cpu_s, 3) : "–",
               c.found ? std::to_string(c.rhs_evaluations) : "–"});
    md << ans.str() << "\n";
    std::ostringstream fails;
    for (const auto& p : t.points)
      if (!p.ok) fails << "* " << p.family << " at " << fmt(p.setting, 3) << ": " << p.problem << "\n";
    if (!fails.str().empty()) md << "Failures (no error plotted):\n\n" << fails.str() << "\n";
  }
  // The answer to the study's question, from the first throw (the one with a clean contact list).
  if (!wp.throws.empty()) {
    const auto& t = wp.throws.front();
    md << "**The answer (throw: " << t.label << ").** ";
    for (double target : {1e-2, 1e-3}) {
      const CheapestSetting* best_rt = nullptr;
      const CheapestSetting* best_cv = nullptr;
      for (const auto& c : t.cheapest) {
        if (c.target_error_m != target || !c.found) continue;
        const bool rt = c.family.rfind("realtime", 0) == 0;
        const CheapestSetting*& slot = rt ? best_rt : best_cv;
        if (!slot || c.cpu_s < slot->cpu_s) slot = &c;
      }
      md << "For bounce positions within " << fmt(100 * target, 2) << " cm, ";
      if (best_rt)
        md << "the cheapest real-time setting is " << best_rt->family << " with a flight step of "
           << fmt(best_rt->setting, 3) << " s (" << fmt(1000 * best_rt->cpu_s, 3) << " ms CPU per throw, "
           << best_rt->rhs_evaluations << " RHS evaluations)";
      else
        md << "no real-time setting tried gets there";
      if (best_cv)
        md << "; the cheapest CVODE setting is " << best_cv->family << " at rtol " << fmt(best_cv->setting, 2) << " ("
           << fmt(1000 * best_cv->cpu_s, 3) << " ms, " << best_cv->rhs_evaluations << " RHS evaluations)";
      else
        md << "; no CVODE setting tried gets there";
      md << ". ";
    }
    md << "Coarse real-time steps do not merely lose accuracy: they change the contact list (extra skips, listed "
          "above), so below some step the bounce count itself is wrong. Lower left is better in the figures; "
          "each family's curve ends where its runs stop reproducing the reference's contacts.\n\n";
  }
  out.markdown = md.str();
  return out;
}

}  // namespace stoneskip
