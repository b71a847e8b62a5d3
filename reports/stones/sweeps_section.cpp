// Section 3 of the stones report: bounce count against spin (the paper's Fig. 8), speed, attack
// angle and path angle, with bisected thresholds; momentum against time (the paper's Fig. 9).
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "reports/common/markdown.hpp"
#include "reports/stones/plot_helpers.hpp"
#include "reports/stones/report_sections.hpp"

namespace stoneskip {

std::string fmt_or_dash(double v, int significant) { return std::isfinite(v) ? fmt(v, significant) : "–"; }

std::string history_group_name(const std::string& label) {
  std::string s;
  for (char c : label) {
    if (std::isalnum(static_cast<unsigned char>(c)))
      s += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    else if (!s.empty() && s.back() != '_')
      s += '_';
  }
  while (!s.empty() && s.back() == '_') s.pop_back();
  return s;
}

void write_history(const H5Group& parent, const std::string& name, const ThrowHistory& h) {
  H5Group g = parent.create_group(name);
  g.set_attr("label", h.label);
  g.set_attr("solver", h.solver);
  g.set_attr("convention", std::string(to_string(h.convention)));
  g.set_attr("bounces", static_cast<long long>(h.result.bounces));
  g.set_attr("outcome", std::string(to_string(h.result.outcome)));
  g.write_table("history", h.table);
  Table c;
  c.columns = {"start_s", "end_s", "entry_speed_m_s", "exit_speed_m_s", "entry_energy_J", "exit_energy_J",
               "first_touch_x_m", "first_touch_y_m", "bounced"};
  for (const auto& k : h.result.contacts)
    c.add_row({k.start_s, k.end_s, k.entry_speed_m_s, k.exit_speed_m_s, k.entry_energy_J, k.exit_energy_J,
               k.first_touch_m.x(), k.first_touch_m.y(), k.bounced ? 1.0 : 0.0});
  g.write_table("contacts", c);
}

namespace {

std::string unit_of(SweepParameter p) {
  switch (p) {
    case SweepParameter::spin_rev_s: return "rev/s";
    case SweepParameter::speed_m_s: return "m/s";
    default: return "°";
  }
}

std::string axis_of(SweepParameter p) {
  switch (p) {
    case SweepParameter::spin_rev_s: return "spin (rev/s)";
    case SweepParameter::speed_m_s: return "speed (m/s)";
    case SweepParameter::attack_angle_deg: return "attack angle (deg)";
    case SweepParameter::path_angle_deg: return "path angle (deg)";
  }
  return "";
}

std::string solver_word(const SolverChoice& s) { return s.kind == SolverKind::realtime ? "real-time" : "reference"; }

}  // namespace

SectionOutput sweeps_section(const std::vector<BounceSweepResult>& sweeps, const std::vector<ThrowHistory>& fig9,
                             const H5Group& data) {
  SectionOutput out;
  H5Group g = data.create_group("sweeps");
  std::ostringstream md;
  md << "## 3. Bounce-count curves\n\n"
     << "**What is measured.** The bounce count (contacts that end with the stone leaving the water, spec §1.8) "
        "of one base throw as one parameter varies, from the CVODE reference and from the real-time stepper with "
        "the case's settings, in both conventions (`physical`: the corrected force laws; `paper`: Lee & Baek's "
        "Eq. 1–3 and 6 as printed). Where the count changes between two grid values, the parameter is bisected "
        "until the bracket is narrower than the tolerance given, so thresholds are values, not grid cells.\n\n";
  if (!sweeps.empty())
    md << "Base throw: **" << sweeps.front().spec.base.label << "** (" << sweeps.front().spec.base.stone.description
       << ", " << fmt(sweeps.front().spec.base.stone.mass.mass_kg * 1000, 3) << " g; U = "
       << fmt(sweeps.front().spec.base.parameters.speed_m_s, 3) << " m/s, β = "
       << fmt(sweeps.front().spec.base.parameters.path_angle_deg, 3) << "°, α = "
       << fmt(sweeps.front().spec.base.parameters.attack_angle_deg, 3) << "°, spin "
       << fmt(sweeps.front().spec.base.parameters.spin_rev_s, 3) << " rev/s unless swept). Real-time settings: "
       << sweeps.front().spec.base.realtime.dt_s << " s flight step, " << sweeps.front().spec.base.realtime.contact_dt_s
       << " s contact step.\n\n";
  // Group by parameter.
  std::map<int, std::vector<const BounceSweepResult*>> by_param;
  for (const auto& s : sweeps) by_param[static_cast<int>(s.spec.parameter)].push_back(&s);
  for (const auto& [pi, list] : by_param) {
    const SweepParameter param = static_cast<SweepParameter>(pi);
    std::vector<PlotSeries> ps;
    MarkdownTable counts([&] {
      std::vector<std::string> h{axis_of(param)};
      for (const auto* s : list) h.push_back(std::string(to_string(s->spec.convention)) + ", " + solver_word(s->spec.solver));
      return h;
    }());
    const auto& values = list.front()->spec.values;
    for (std::size_t i = 0; i < values.size(); ++i) {
      std::vector<std::string> row{fmt(values[i], 3)};
      for (const auto* s : list) row.push_back(s->counts[i] < 0 ? "failed" : std::to_string(s->counts[i]));
      counts.row(row);
    }
    for (const auto* s : list) {
      H5Group sg = g.create_group(s->spec.name);
      sg.set_attr("parameter", std::string(to_string(param)));
      sg.set_attr("convention", std::string(to_string(s->spec.convention)));
      sg.set_attr("solver", s->spec.solver.label());
      sg.set_attr("threshold_tolerance", s->spec.threshold_tolerance);
      sg.set_attr("runs", static_cast<long long>(s->runs));
      sg.set_attr("cpu_s", s->cpu_s);
      Table t;
      t.columns = {"value", "bounces"};
      for (std::size_t i = 0; i < s->spec.values.size(); ++i) t.add_row({s->spec.values[i], static_cast<double>(s->counts[i])});
      sg.write_table("counts", t);
      Table th;
      th.columns = {"lo", "hi", "count_below", "count_above", "bisected"};
      for (const auto& x : s->thresholds)
        th.add_row({x.lo, x.hi, static_cast<double>(x.count_below), static_cast<double>(x.count_above), x.bisected ? 1.0 : 0.0});
      sg.write_table("thresholds", th);
      // The curve: grid counts merged with both ends of every bisected bracket (sharp steps).
      std::vector<std::pair<double, double>> pts;
      for (std::size_t i = 0; i < s->spec.values.size(); ++i)
        if (s->counts[i] >= 0) pts.emplace_back(s->spec.values[i], s->counts[i]);
      for (const auto& x : s->thresholds)
        if (x.bisected) {
          if (x.count_below >= 0) pts.emplace_back(x.lo, x.count_below);
          if (x.count_above >= 0) pts.emplace_back(x.hi, x.count_above);  // −1: a failed run, not a count
        }
      std::sort(pts.begin(), pts.end());
      PlotSeries p;
      p.title = std::string(to_string(s->spec.convention)) + ", " + solver_word(s->spec.solver);
      p.style = "steps";
      for (const auto& [x, y] : pts) {
        p.x.push_back(x);
        p.y.push_back(y);
      }
      ps.push_back(p);
    }
    PlotAxes ax;
    ax.x_label = axis_of(param);
    ax.y_label = "bounces";
    ax.extra = "set yrange [-0.5:*]\nset offsets 0, 0, 1, 0";
    Figure f = line_figure(std::string("sweep_") + to_string(param), "Bounce count against " + axis_of(param), ax, ps,
                           to_string(param), "bounces");
    md << "### Bounce count against " << axis_of(param) << "\n\n" << figure_markdown(f);
    out.figures.push_back(f);
    md << counts.str() << "\n";
    md << "Thresholds (bisected to the tolerance; the value is the middle of the final bracket):\n\n";
    MarkdownTable th({"convention, solver", "thresholds: value (bounces below → above)", "runs", "CPU (s)"});
    for (const auto* s : list) {
      std::ostringstream txt;
      int shown = 0;
      for (const auto& x : s->thresholds) {
        if (shown++) txt << "; ";
        auto cnt = [](int c) { return c < 0 ? std::string("failed") : std::to_string(c); };
        txt << fmt(x.value(), 4) << (x.bisected ? " ± " + fmt(0.5 * (x.hi - x.lo), 2) : " (not bisected)") << " ("
            << cnt(x.count_below) << "→" << cnt(x.count_above) << ")";
      }
      if (s->thresholds.empty()) txt << "none: the count does not change";
      th.row({std::string(to_string(s->spec.convention)) + ", " + solver_word(s->spec.solver), txt.str(),
              std::to_string(s->runs), fmt(s->cpu_s, 3)});
    }
    md << th.str() << "\n";
    // What it finds: agreement of the solvers per convention, and how many changes of the count sit
    // right next to a grid value (the count flips as soon as the parameter moves: sensitive dependence).
    md << "*What it finds:* ";
    for (Convention conv : {Convention::physical, Convention::paper}) {
      const BounceSweepResult* ref = nullptr;
      const BounceSweepResult* rt = nullptr;
      for (const auto* s : list)
        if (s->spec.convention == conv) (s->spec.solver.kind == SolverKind::reference ? ref : rt) = s;
      if (!ref || !rt) continue;
      int agree = 0, n = static_cast<int>(ref->counts.size()), lo = 1 << 30, hi = -1, failed = 0;
      for (int i = 0; i < n; ++i) {
        agree += ref->counts[i] == rt->counts[i] ? 1 : 0;
        if (ref->counts[i] < 0) ++failed;
        else {
          lo = std::min(lo, ref->counts[i]);
          hi = std::max(hi, ref->counts[i]);
        }
      }
      int hugging = 0, bisected = 0;
      for (const auto& x : ref->thresholds) {
        if (!x.bisected) continue;
        ++bisected;
        for (double v : ref->spec.values)
          if (std::abs(x.value() - v) <= 2 * ref->spec.threshold_tolerance) {
            ++hugging;
            break;
          }
      }
      md << to_string(conv) << " convention: the reference counts " << (hi < 0 ? std::string("nothing") : std::to_string(lo) + "–" + std::to_string(hi))
         << " bounces";
      if (failed) md << " (" << failed << " reference runs failed)";
      md << ", the real-time stepper agrees at " << agree << " of " << n << " grid values; " << ref->thresholds.size()
         << " changes of the reference count";
      if (bisected >= 3 && hugging * 2 >= bisected)
        md << ", " << hugging << " of the " << bisected << " bisected ones within two tolerances of a grid value — "
           << "the count changes as soon as the parameter moves off the grid value, i.e. it depends sensitively on "
              "the throw (not a curve with a few clean steps)";
      md << ". ";
    }
    md << "\n\n";
    (void)unit_of;
  }

  // Fig. 9: momentum against time.
  H5Group hg = data.create_group("fig9");
  for (const auto& h : fig9) write_history(hg, history_group_name(h.label), h);
  md << "### Momentum against time (the paper's Fig. 9)\n\n"
     << "The seed's 8 m/s throw without spin and with spin, both solvers, both conventions. Lee & Baek report "
        "for their model: without spin three bounces with momentum falling fast at each; with spin, more bounces "
        "and a gradual fall.\n\n";
  for (const char* conv : {"physical", "paper"}) {
    std::vector<PlotSeries> ps;
    for (const auto& h : fig9) {
      if (std::string(to_string(h.convention)) != conv) continue;
      PlotSeries p;
      p.title = h.label + " (" + std::to_string(h.result.bounces) + " bounces)";
      p.style = h.label.find("real-time") != std::string::npos ? "lines dt 2" : "lines";
      p.x = h.table.column("t_s");
      p.y = h.table.column("momentum_kg_m_s");
      ps.push_back(p);
    }
    PlotAxes ax;
    ax.x_label = "time (s)";
    ax.y_label = "momentum |p| (kg m/s)";
    Figure f = line_figure(std::string("fig9_momentum_") + conv, std::string("Momentum against time, ") + conv + " convention",
                           ax, ps, "t_s", "momentum_kg_m_s");
    md << figure_markdown(f);
    out.figures.push_back(f);
  }
  out.markdown = md.str();
  return out;
}

}  // namespace stoneskip
