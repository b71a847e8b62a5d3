// Section 4 of the stones report: throws chosen to break a solver, and the largest stable step.
#include <cmath>
#include <sstream>

#include "reports/common/markdown.hpp"
#include "reports/stones/plot_helpers.hpp"
#include "reports/stones/report_sections.hpp"

namespace stoneskip {

SectionOutput hard_cases_section(const std::vector<HardCaseResult>& hard, const std::vector<StableStepRow>& stable,
                                 const StableStepOptions& so, const H5Group& data) {
  SectionOutput out;
  H5Group g = data.create_group("hard_cases");
  std::ostringstream md;
  md << "## 4. Hard cases\n\n"
     << "**What is measured.** Throws chosen to break a solver (`cases/hard/`). Each is solved by CVODE (rtol 1e-9) "
        "and by the real-time stepper, first with the case's own steps and then with one fixed step h for flight "
        "and contact alike, growing from 1e-5 s towards a game frame. For each run: does the state stay finite; "
        "does the stepper miss a contact the reference has (it stepped over it: tunnelling) or report one the "
        "reference does not have; is the bounce count the same; and does the stone gain energy over a contact "
        "(more than 1e-4 of its release kinetic energy). In the `physical` convention the water and the air can "
        "only take energy out (spec §1.6), so a gain there is a numerical artefact; in the `paper` convention the "
        "model itself can create energy.\n\n";
  MarkdownTable summary({"case", "reference (CVODE)", "real-time, case steps", "real-time, largest single step that is ok"});
  for (const auto& h : hard) {
    H5Group cg = g.create_group(history_group_name(h.file));
    cg.set_attr("title", h.title);
    cg.set_attr("file", h.file);
    cg.set_attr("reference_verdict", h.reference_verdict);
    Table t;
    t.columns = {"dt_s", "contact_dt_s", "finite", "bounces", "contacts", "missed", "spurious", "max_energy_gain_J",
                 "cpu_s"};
    std::vector<std::string> verdicts;
    double largest_ok = 0;
    bool prefix_ok = true;
    for (std::size_t i = 0; i < h.runs.size(); ++i) {
      const HardRun& r = h.runs[i];
      t.add_row({r.dt_s, r.contact_dt_s, r.finite ? 1.0 : 0.0, static_cast<double>(r.result.bounces),
                 static_cast<double>(r.result.contacts.size()), static_cast<double>(r.contacts.missed),
                 static_cast<double>(r.contacts.spurious), r.result.max_energy_gain_J, r.result.stats.cpu_s});
      verdicts.push_back(r.setting + ": " + r.verdict);
      if (i > 0) {
        prefix_ok = prefix_ok && r.verdict == "ok";
        if (prefix_ok) largest_ok = r.dt_s;
      }
    }
    cg.write_table("runs", t);
    cg.write_strings("verdicts", verdicts);
    summary.row({h.title + " (`" + h.file + "`)", h.reference_verdict, h.runs.front().verdict,
                 largest_ok > 0 ? fmt(largest_ok, 3) + " s" : "none of the steps tried"});
  }
  md << summary.str() << "\n";
  {
    std::vector<std::string> ref_failed, case_bad, energy;
    for (const auto& h : hard) {
      if (h.reference.outcome == Outcome::failed) ref_failed.push_back(h.file);
      if (h.runs.front().verdict != "ok") case_bad.push_back(h.file);
      if (h.convention == Convention::physical)
        for (const auto& r : h.runs)
          if (r.energy_created) {
            energy.push_back(h.file + " (from h = " + fmt(r.dt_s, 2) + " s)");
            break;
          }
    }
    auto list = [](const std::vector<std::string>& v) {
      std::string s;
      for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + ("`" + v[i] + "`");
      return v.empty() ? std::string("none") : s;
    };
    md << "*What it finds:* the reference fails on " << list(ref_failed)
       << "; the real-time stepper with the case's own steps departs from the reference on " << list(case_bad)
       << "; in the physical convention the stepper creates energy over a contact on " << list(energy)
       << ". In these throws, growing the step first adds spurious skips (the stone is pushed out of the water by a force applied "
          "for too long), then misses contacts, and only at the largest steps creates energy or fails.\n\n";
  }
  md << "Every run, with what went wrong:\n\n";
  for (const auto& h : hard) {
    md << "**" << h.title << "** (`" << h.file << "`, " << to_string(h.convention) << " convention; reference: "
       << h.reference_verdict << ")\n\n";
    MarkdownTable t({"real-time setting", "bounces", "contacts", "max energy gain (J)", "CPU (s)", "verdict"});
    for (const auto& r : h.runs)
      t.row({r.setting + (r.setting == "case settings" ? " (" + fmt(r.dt_s, 2) + " / " + fmt(r.contact_dt_s, 2) + " s)" : ""),
             r.finite ? std::to_string(r.result.bounces) : "–", std::to_string(r.result.contacts.size()),
             fmt(r.result.max_energy_gain_J, 3), fmt(r.result.stats.cpu_s, 3), r.verdict});
    md << t.str() << "\n";
  }

  // Largest stable step against speed.
  H5Group sg = g.create_group("largest_stable_step");
  Table st;
  st.columns = {"speed_m_s", "reference_bounces", "largest_finite_s", "largest_no_energy_gain_s", "largest_same_contacts_s"};
  for (const auto& r : stable)
    st.add_row({r.speed_m_s, static_cast<double>(r.reference_bounces), r.largest_finite_s, r.largest_no_energy_gain_s,
                r.largest_same_contacts_s});
  sg.write_table("rows", st);
  md << "### Largest stable step against throw speed\n\n"
     << "One fixed step h (flight = contact) of " << to_string(so.scheme)
     << ", h = 1e-5 s · 2^k; for each speed the largest h such that every smaller h tried is also (a) finite, (b) "
        "finite and without energy gain, (c) all that and with the reference's contact and bounce count.\n\n";
  MarkdownTable mt({"speed (m/s)", "reference bounces / contacts", "(a) finite up to h (s)", "(b) no energy gain up to h (s)",
                    "(c) same contacts up to h (s)", "bounces at each h (−1: failed)"});
  for (const auto& r : stable) {
    std::ostringstream b;
    for (std::size_t i = 0; i < r.bounces.size(); ++i) b << (i ? " " : "") << r.bounces[i];
    auto h = [](double v) { return v > 0 ? fmt(v, 3) : std::string("< smallest"); };
    mt.row({fmt(r.speed_m_s, 3), std::to_string(r.reference_bounces) + " / " + std::to_string(r.reference_contacts),
            h(r.largest_finite_s), h(r.largest_no_energy_gain_s), h(r.largest_same_contacts_s), b.str()});
  }
  md << mt.str() << "\n";
  {
    PlotSeries a, b, c;
    a.title = "(a) finite";
    b.title = "(b) no energy gain";
    c.title = "(c) same contacts as the reference";
    for (const auto& r : stable) {
      a.x.push_back(r.speed_m_s);
      b.x.push_back(r.speed_m_s);
      c.x.push_back(r.speed_m_s);
      a.y.push_back(r.largest_finite_s > 0 ? r.largest_finite_s : std::nan(""));
      b.y.push_back(r.largest_no_energy_gain_s > 0 ? r.largest_no_energy_gain_s : std::nan(""));
      c.y.push_back(r.largest_same_contacts_s > 0 ? r.largest_same_contacts_s : std::nan(""));
    }
    PlotAxes ax;
    ax.x_label = "throw speed (m/s)";
    ax.y_label = "largest step h (s)";
    ax.log_x = ax.log_y = true;
    Figure f = line_figure("largest_stable_step", "Largest stable single step of the real-time stepper against throw speed",
                           ax, {a, b, c}, "speed_m_s", "h_s");
    md << figure_markdown(f);
    out.figures.push_back(f);
  }
  out.markdown = md.str();
  return out;
}

}  // namespace stoneskip
