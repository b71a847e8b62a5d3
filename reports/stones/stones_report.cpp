// The stones report: six questions asked of the real-time stone model and its two solvers,
// formatted from the stored section records.
#include "reports/stones/stones_report.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <utility>

#include "reports/common/html_page.hpp"
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

// "[§N](#anchor)": a link to the level-2 heading that starts "N. " (empty when there is none).
std::string section_link(const std::string& markdown, const std::string& number) {
  for (const Heading& h : headings(markdown))
    if (h.level == 2 && h.text.rfind(number + ". ", 0) == 0) return " ([§" + number + "](#" + h.anchor + "))";
  return "";
}

// How many of the fits under `series` (one child per quantity and scheme, each with fit/verdict)
// say each verdict, most frequent first: "20 converge at the expected order, 3 …".
std::string verdict_counts(const Record& series) {
  std::map<std::string, int> count;
  int fits = 0;
  for (const auto& name : series.child_names()) {
    const Record& s = series.at(name);
    if (!s.has_child("fit") || !s.at("fit").has_child("verdict")) continue;
    ++count[s.at("fit").at("verdict").text("verdict")];
    ++fits;
  }
  std::vector<std::pair<int, std::string>> order;
  for (const auto& [v, n] : count) order.push_back({-n, v});
  std::sort(order.begin(), order.end());
  std::string out = std::to_string(fits) + " order fits: ";
  for (std::size_t i = 0; i < order.size(); ++i) out += (i ? ", " : "") + std::to_string(-order[i].first) + " **" + order[i].second + "**";
  return out;
}

// The report's findings, one bullet per question, each a stored verdict (or a count of them) and
// a link to the section that shows it.
std::string findings_markdown(const Record& secs, const std::string& md) {
  std::ostringstream f;
  f << "## Findings\n\n";
  const Record& c = secs.at("convergence");
  if (c.has_child("series"))
    f << "* The real-time stepper against the reference, `" << c.text("law") << "` law: " << verdict_counts(c.at("series"))
      << section_link(md, "1") << ".\n";
  if (c.has_child("reference_tolerance") && c.at("reference_tolerance").has_child("drop")) {
    const Record& t = c.at("reference_tolerance");
    f << "* The reference's own error against its tolerance: " << verdict_markdown(t.at("drop"));
    // The drop asks only that the error fall; whether it falls in proportion to rtol is the slopes'
    // verdict, said beside it (a drop of 100 over 1e4 in rtol passes an error ∝ √rtol).
    for (const auto& [fit, words] : {std::pair{"bounce_position_fit", "bounce position"}, std::pair{"contact_time_fit", "contact time"}})
      if (t.has_child(fit) && t.at(fit).has_child("verdict"))
        f << "; in proportion to rtol (slope 1), " << words << ": " << verdict_markdown(t.at(fit).at("verdict"));
    f << section_link(md, "1") << ".\n";
  }
  const Record& wp = secs.at("work_precision");
  if (wp.has_child("restarts") && wp.at("restarts").has_child("verdict"))
    f << "* CVODE's restarts at a contact: **" << wp.at("restarts").at("verdict").text("verdict") << "**" << section_link(md, "2") << ".\n";
  if (secs.has_child("work_precision_grid")) {
    const Record& g = secs.at("work_precision_grid").at("default_choice");
    f << "* The adaptive stepper's default over a grid of throws: "
      << (g.flag("found") ? "the grid supports rtol " + fmt(g.number("tolerance"), 2) : std::string("no tolerance run meets the rule"))
      << ", the cases' default is " << fmt(g.number("default_tolerance"), 2) << " (**" << g.text("beside_default_phrase") << "**)";
    // A choice made on the point estimate says so, with the interval it could not exclude.
    if (g.flag("found") && g.text("agreement_bound") == "point_estimate") {
      f << ", on the point estimate: " << fmt(g.number("agreeing")) << " of " << fmt(g.number("n")) << " throws, 95 % interval "
        << fmt(g.number("wilson_lo"), 3) << "–" << fmt(g.number("wilson_hi"), 3);
      if (g.number("wilson_lo") < g.number("agreement_target"))
        f << ", which does not show the target " << fmt(g.number("agreement_target"), 3) << " (that takes "
          << fmt(g.number("throws_to_show_target"), 6)
          << " agreeing throws; `stoneskip bench` measures the agreement on a larger grid, solvers/README.md)";
    }
    f << section_link(md, "2") << ".\n";
  }
  const Record& sw = secs.at("sweeps");
  for (const auto& p : sw.child_names()) {
    const Record& r = sw.at(p);
    if (!r.has_child("comparison")) continue;
    std::string line;
    for (const auto& conv : r.at("comparison").child_names()) {
      const Record& k = r.at("comparison").at(conv);
      if (k.has_child("character")) line += (line.empty() ? "" : ", ") + conv + " convention **" + k.at("character").text("verdict") + "**";
    }
    if (!line.empty()) f << "* Bounce count against `" << p << "`: " << line << section_link(md, "3") << ".\n";
  }
  if (secs.has_child("mesh")) {
    // The paper's mesh (N = 11, diagonal cut) where the study has it, else its first mesh, against
    // its cut's reference; each cut's settled N; the paper mesh's mirror pairs.
    const Record& m = secs.at("mesh");
    const Table& t = m.table("meshes");
    const auto n = t.column("segments"), cut = t.column("centre_cut"), tri = t.column("triangles"), refs = t.column("reference");
    std::size_t paper = 0;
    for (std::size_t k = 0; k < t.rows(); ++k)
      if (n[k] == 11 && cut[k] == 0) paper = k;
    auto name = [&](std::size_t k) {
      return "N = " + fmt(n[k], 6) + ", " + (cut[k] > 0 ? "centre" : "diagonal") + " cut (" + fmt(tri[k], 6) + " triangles)";
    };
    const std::string throws = fmt(m.number("throws"), 4);
    const std::size_t ref = static_cast<std::size_t>(refs[paper]);
    f << "* Bounce counts against the mesh:";
    if (ref != paper) {
      f << " the stone of " << name(paper) << " against " << name(ref) << ": **different bounce counts** on "
        << fmt(t.column("changed")[paper], 4) << " of " << throws << " throws";
      if (t.column("not_established")[paper] > 0) f << ", no difference established on " << fmt(t.column("not_established")[paper], 4);
      if (t.column("undecided")[paper] > 0) f << ", **not decided** on " << fmt(t.column("undecided")[paper], 4);
      f << " (ensembles, 95 % interval)";
    }
    const Table& cuts = m.table("cuts");
    for (std::size_t row = 0; row < cuts.rows(); ++row) {
      const double settled = cuts.column("settled_segments")[row];
      if (cuts.column("meshes")[row] < 2) continue;
      f << "; " << (cuts.column("centre_cut")[row] > 0 ? "centre" : "diagonal") << " cut: "
        << (std::isnan(settled) ? std::string("**the count is not shown to settle**")
                                : "no difference established from N = " + fmt(settled, 6) + " to " +
                                      fmt(cuts.column("reference_segments")[row], 6));
    }
    if (t.column("mirror_pairs")[paper] > 0)
      f << "; a throw against its mirror image: different on " << fmt(t.column("mirror_different")[paper], 4) << " of "
        << fmt(t.column("mirror_pairs")[paper], 4) << " pairs with " << name(paper);
    f << section_link(md, "3c") << ".\n";
  }
  const Record& v = secs.at("validation");
  if (v.has_child("conventions")) {
    const Record& cv = v.at("conventions");
    if (cv.has_child("paper_energy"))
      f << "* The paper's equations as printed (`paper` convention), energy over the contacts: " << verdict_markdown(cv.at("paper_energy"))
        << section_link(md, "5") << ".\n";
    if (cv.has_child("physical_energy"))
      f << "* The `physical` convention, energy over the contacts: **" << cv.at("physical_energy").text("verdict") << "**"
        << section_link(md, "5") << ".\n";
  }
  if (v.has_child("ranking") && v.at("ranking").has_child("answer"))
    f << "* Which water law and pressure distribution skip like a real stone: **" << v.at("ranking").at("answer").text("verdict") << "**"
      << section_link(md, "6") << ".\n";
  return f.str() + "\n";
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
        "Hayakawa's lift and drag) and of the two solvers that integrate it: the **real-time stepper** (explicit "
        "Runge–Kutta as a game would run it: by default the adaptive Bogacki–Shampine 3(2) pair `bs32` with its kinks "
        "located, or a fixed-step scheme named for a study of it) and the **reference** (SUNDIALS CVODE with tight tolerances, every contact "
        "event located by root finding).\n\n"
     << "1. Does the real-time stepper converge to the reference, at the rate its scheme promises, with each water law?\n"
     << "2. What does accuracy cost — which step does the real-time model need for a given bounce-position error, and "
        "how does that compare with the reference?\n"
     << "3. How does the bounce count depend on spin, speed and angles (the paper's Fig. 8 and 9), and where exactly "
        "does it change?\n"
     << "4. Which throws break a solver, and how?\n"
     << "5. How does each water law compare with experiments (Clanet et al. 2004, Rosellini et al. 2005), with "
        "Bocquet's (2003) model estimates, and with the paper's own claims — and why do the paper's printed equations behave so differently?\n"
     << "6. Which water law skips like a real stone, and which is the cheapest that does?\n\n"
     << "Settings: the `" << settings.text("preset") << "` preset, " << fmt(settings.number("workers")) << " worker threads."
     << (settings.text("preset") != "full" ? " **This is a reduced run: coarse grids and single timings — a smoke test, not the report's numbers.**" : "")
     << " The case files of every throw are stored with the data (`/sections/settings`).\n\n";
  out.markdown = md.str();
  append(out, convergence_section(secs.at("convergence")));
  append(out, work_precision_section(secs.at("work_precision")));
  if (secs.has_child("work_precision_grid")) append(out, work_precision_grid_section(secs.at("work_precision_grid")));
  append(out, sweeps_section(secs.at("sweeps"), secs.at("validation").at("fig9"),
                             secs.has_child("mesh") ? &secs.at("mesh") : nullptr));
  if (secs.has_child("count_ensembles")) append(out, count_ensembles_section(secs.at("count_ensembles")));
  if (secs.has_child("mesh")) append(out, mesh_section(secs.at("mesh")));
  append(out, hard_cases_section(secs.at("hard_cases")));
  append(out, validation_section(secs.at("validation")));
  append(out, ranking_section(secs.at("validation")));
  out.markdown += "## Cost of this report\n\n" + cost_table(secs) + "\n";
  out.markdown += provenance_markdown(s);
  // The findings go before the first section, with links into the sections rendered above.
  const std::size_t first = out.markdown.find("\n## ") + 1;
  out.markdown.insert(first, findings_markdown(secs, out.markdown));
  for (const auto& f : out.figures)
    if (f.name == "conventions_energy") out.headline_figure = f.name;  // the front page's picture: the printed equations gain energy
  return out;
}

}  // namespace stoneskip
