// The stones report: six questions asked of the real-time stone model and its two solvers,
// formatted from the stored section records.
#include "reports/stones/stones_report.hpp"

#include <sstream>

#include "reports/common/markdown.hpp"
#include "reports/stones/report_sections.hpp"

namespace stoneskip {

namespace {

std::string cost_table(const Record& secs) {
  MarkdownTable t({"section", "wall (s)", "CPU, all threads (s)"});
  double wall = 0, cpu = 0;
  for (const auto& name : secs.child_names()) {
    const Record& s = secs.at(name);
    if (!s.has_child("cost")) continue;
    t.row({name, fmt(s.at("cost").number("wall_s"), 3), fmt(s.at("cost").number("cpu_s"), 3)});
    wall += s.at("cost").number("wall_s");
    cpu += s.at("cost").number("cpu_s");
  }
  t.row({"total", fmt(wall, 3), fmt(cpu, 3)});
  return t.str();
}

}  // namespace

RenderedReport render_stones_report(const StoredReport& s) {
  const Record& secs = s.sections;
  const Record& settings = secs.at("settings");
  RenderedReport out;
  std::ostringstream md;
  md << "# Stones report: the real-time stone model, verified and validated\n\n"
     << "This report asks six questions of stoneskip's stone model (Lee & Baek 2013: a rigid triangle-mesh stone with a "
        "water force on each wetted triangle — their Newtonian impact law, Clanet et al.'s planing law, or Nagahiro & "
        "Hayakawa's lift and drag) and of the two solvers that integrate it: the **real-time stepper** (fixed "
        "steps, as a game would run it) and the **reference** (SUNDIALS CVODE with tight tolerances, every contact "
        "event located by root finding).\n\n"
     << "1. Does the real-time stepper converge to the reference, at the rate its scheme promises, with each water law?\n"
     << "2. What does accuracy cost — which step does the real-time model need for a given bounce-position error, and "
        "how does that compare with the reference?\n"
     << "3. How does the bounce count depend on spin, speed and angles (the paper's Fig. 8 and 9), and where exactly "
        "does it change?\n"
     << "4. Which throws break a solver, and how?\n"
     << "5. How does each water law compare with experiments (Clanet et al. 2004, Bocquet 2003) and with the paper's "
        "own claims — and why do the paper's printed equations behave so differently?\n"
     << "6. Which water law skips like a real stone, and which is the cheapest that does?\n\n"
     << "Settings: the `" << settings.text("preset") << "` preset, " << fmt(settings.number("workers")) << " worker threads."
     << (settings.text("preset") != "full" ? " **This is a reduced run: coarse grids and single timings — a smoke test, not the report's numbers.**" : "")
     << " The case files of every throw are stored with the data (`/sections/settings`).\n\n";
  out.markdown = md.str();
  append(out, convergence_section(secs.at("convergence")));
  append(out, work_precision_section(secs.at("work_precision")));
  append(out, sweeps_section(secs.at("sweeps"), secs.at("validation").at("fig9")));
  append(out, hard_cases_section(secs.at("hard_cases")));
  append(out, validation_section(secs.at("validation")));
  append(out, ranking_section(secs.at("validation")));
  out.markdown += "## Cost of this report\n\n" + cost_table(secs) + "\n";
  out.markdown += provenance_markdown(s);
  return out;
}

}  // namespace stoneskip
