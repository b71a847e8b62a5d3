// Section 3 of the stones report: bounce count against spin (the paper's Fig. 8), speed, attack
// angle and path angle, with bisected thresholds; momentum against time (the paper's Fig. 9) —
// formatted from the stored records.
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>

#include "reports/common/markdown.hpp"
#include "reports/common/plot.hpp"
#include "reports/stones/report_sections.hpp"

namespace stoneskip {

namespace {

// Why the run that stopped threshold i's bisection failed, as stored (absent in older data): ": "
// and the solver's reason, or "".
std::string stopped_because(const Record& sweep, std::size_t i) {
  if (!sweep.string_lists().count("threshold_failures")) return "";
  const auto& why = sweep.strings("threshold_failures");
  return i < why.size() && !why[i].empty() ? ": " + why[i] : std::string();
}


constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string axis_of(const std::string& p) {
  if (p == "spin_rev_s") return "spin (rev/s)";
  if (p == "speed_m_s") return "speed (m/s)";
  if (p == "attack_angle_deg") return "attack angle (deg)";
  if (p == "path_angle_deg") return "path angle (deg)";
  return p;
}

std::string who(const Record& s) { return s.text("convention") + ", " + (s.text("solver") == "realtime" ? "real-time" : "reference"); }

std::string count_text(double c) { return c < 0 ? std::string("failed") : fmt(c); }

// The stored runs of one bounce-count sweep as (parameter, count) points in order: the grid's counts,
// both ends of every bracket of its thresholds (bisected or not) and the run that stopped a
// bisection, a failed run as a count < 0.
std::vector<std::pair<double, double>> count_points(const Record& s) {
  std::vector<std::pair<double, double>> pts;
  const Table& counts = s.table("counts");
  const auto v = counts.column("value"), b = counts.column("bounces");
  for (std::size_t i = 0; i < v.size(); ++i) pts.emplace_back(v[i], b[i]);
  const Table& th = s.table("thresholds");
  const auto lo = th.column("lo"), hi = th.column("hi"), below = th.column("count_below"), above = th.column("count_above");
  for (std::size_t i = 0; i < th.rows(); ++i) {
    pts.emplace_back(lo[i], below[i]);
    pts.emplace_back(hi[i], above[i]);
  }
  if (th.has_column("failed_at"))  // the run that stopped a bisection (absent in older data)
    for (double x : th.column("failed_at"))
      if (!std::isnan(x)) pts.emplace_back(x, -1.0);
  std::stable_sort(pts.begin(), pts.end(), [](const auto& p, const auto& q) { return p.first < q.first; });
  return pts;
}

// One sweep's curve: the stored runs as dots (grid values and bracket ends; the figure test checks
// them against data.h5) and, through them, a step outline per run of successful solves: each count
// holds to halfway to its neighbours, so a change is drawn at the middle of its bracket and the last
// value shows over the last half spacing. A failed run ends the outline — never bridged — and is a
// cross on a row of its own at -1.
// wide: the reference's curve, drawn wider and beneath the real-time one (where the two agree, a
// border of the reference's colour shows around the real-time line, and its crosses are larger).
std::vector<PlotSeries> count_curve(const Record& s, const std::string& title, const std::string& colour, bool wide) {
  const std::string counts = s.path() + "/counts", th = s.path() + "/thresholds";
  using Rows = TableSource::Rows;
  auto sources = [&](Rows rows, double at) {
    std::vector<TableSource> out;
    for (const auto& [table, x, y] : {std::tuple{counts, "value", "bounces"}, std::tuple{th, "lo", "count_below"},
                                      std::tuple{th, "hi", "count_above"}}) {
      TableSource src;
      src.table = table;
      src.x_column = x;
      src.y_column = y;
      src.rows = rows;
      src.y_drawn_at = at;
      out.push_back(src);
    }
    return out;
  };
  PlotSeries outline{title, {}, {}, std::string(wide ? "lines lw 5" : "lines lw 1.5") + colour, {}, {}};
  outline.derived = DerivedSeries{};
  outline.derived->kind = DerivedSeries::Kind::outline;  // through `dots`, the next series (of_offset 1)
  PlotSeries dots{"", {}, {}, "points pt 7 ps 0.5" + colour, sources(Rows::y_nonnegative, kNaN), {}};
  PlotSeries failed{title + ": solve failed", {}, {}, std::string(wide ? "points pt 2 ps 2.6 lw 3" : "points pt 2 ps 1.4 lw 2") + colour,
                    sources(Rows::y_negative, -1), {}};
  if (s.table("thresholds").has_column("failed_at")) {
    TableSource stopped;  // rows without one have failed_at NaN: not drawn
    stopped.table = th;
    stopped.x_column = "failed_at";
    stopped.y_column = "count_below";
    stopped.y_drawn_at = -1;
    failed.sources.push_back(stopped);
  }
  const auto pts = count_points(s);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto [x, y] = pts[i];
    if (y < 0) {
      failed.x.push_back(x);
      failed.y.push_back(-1);
      if (!outline.x.empty() && !std::isnan(outline.x.back())) {  // a gap: the line stops here
        outline.x.push_back(kNaN);
        outline.y.push_back(kNaN);
      }
      continue;
    }
    dots.x.push_back(x);
    dots.y.push_back(y);
    const bool first = i == 0 || pts[i - 1].second < 0, last = i + 1 == pts.size() || pts[i + 1].second < 0;
    outline.x.push_back(first ? x : 0.5 * (pts[i - 1].first + x));
    outline.y.push_back(y);
    outline.x.push_back(last ? x : 0.5 * (x + pts[i + 1].first));
    outline.y.push_back(y);
  }
  std::vector<PlotSeries> out{outline, dots};
  if (!failed.x.empty()) out.push_back(failed);
  return out;
}

// What the mesh study (§3c) says of the base stone's mesh, found among its meshes by its triangle
// count and its mass (one match, or nothing is said; records written before the base stored its
// triangles say nothing either): against its cut's reference, and whether that cut's count settles.
std::string mesh_caveat(const Record& base, const Record& m) {
  if (!base.has_number("triangles") || !m.has_table("meshes") || !m.has_table("cuts")) return "";
  const Table& t = m.table("meshes");
  const auto tri = t.column("triangles"), n = t.column("segments"), cut = t.column("centre_cut"), refs = t.column("reference");
  const auto mass = t.column("mass_kg");
  std::size_t found = t.rows(), matches = 0;
  for (std::size_t k = 0; k < t.rows(); ++k)
    if (tri[k] == base.number("triangles") && std::abs(mass[k] - base.number("mass_kg")) <= 1e-9 * mass[k]) found = k, ++matches;
  if (matches != 1) return "";
  auto name = [&](std::size_t k) {
    return "N = " + fmt(n[k], 6) + ", " + (cut[k] > 0 ? "centre" : "diagonal") + " cut, " + fmt(tri[k], 6) + " triangles";
  };
  const std::size_t ref = static_cast<std::size_t>(refs[found]);
  std::string s = "**These counts are the base stone's mesh's** (" + name(found) + "). Section 3c repeats " +
                  fmt(m.number("throws"), 4) + " throws with other meshes of the same solid";
  if (ref == found) return s + ", this mesh being its cut's finest there.";
  s += ": against " + name(ref) + ", this mesh's count differs on " + fmt(t.column("changed")[found], 4) + " of the " +
       fmt(m.number("throws"), 4);
  if (t.column("not_established")[found] > 0) s += ", no difference established on " + fmt(t.column("not_established")[found], 4);
  if (t.column("undecided")[found] > 0) s += ", not decided on " + fmt(t.column("undecided")[found], 4);
  s += " (ensembles, 95 % interval)";
  const Table& cuts = m.table("cuts");
  for (std::size_t row = 0; row < cuts.rows(); ++row) {
    if ((cuts.column("centre_cut")[row] > 0) != (cut[found] > 0)) continue;
    const double settled = cuts.column("settled_segments")[row];
    if (std::isnan(settled) || settled > n[found])
      s += ", and the " + std::string(cut[found] > 0 ? "centre" : "diagonal") + " cut's count is not shown to have settled at N = " +
           fmt(n[found], 6) + ". A count or a threshold below is this mesh's, not shown to be the solid's";
    else
      s += "; from N = " + fmt(settled, 6) + " that cut's counts show no difference from N = " +
           fmt(cuts.column("reference_segments")[row], 6);
  }
  return s + ".";
}

}  // namespace

SectionOutput sweeps_section(const Record& c, const Record& fig9, const Record* mesh) {
  SectionWriter w(c, "3. Bounce-count curves");
  w.lead("What is measured.",
         "The bounce count (contacts that end with the stone leaving the water, model/README.md §1.8) of one base throw as one "
         "parameter varies, from the CVODE reference and from the real-time stepper with the case's settings, in both "
         "conventions (`physical`: the corrected force laws; `paper`: Lee & Baek's Eq. 1–3 and 6 as printed). Where the "
         "count changes between two grid values, the parameter is bisected until the bracket is narrower than the "
         "tolerance given, so thresholds are values, not grid cells.");
  if (c.has_child("base")) {
    const Record& b = c.at("base");
    w.text("Base throw: **" + b.text("label") + "** (" + b.text("stone") + ", " + fmt(1000 * b.number("mass_kg"), 3) +
           " g; U = " + fmt(b.number("speed_m_s"), 3) + " m/s, β = " + fmt(b.number("path_angle_deg"), 3) + "°, α = " +
           fmt(b.number("attack_angle_deg"), 3) + "°, spin " + fmt(b.number("spin_rev_s"), 3) +
           " rev/s unless swept). Real-time settings: " +
           (b.flag("adaptive") ? "`" + b.text("scheme") + "` at rtol " + fmt(b.number("rtol"), 2) + ", atol " +
                                     fmt(b.number("atol_m"), 2) + " m (largest step " + fmt(b.number("dt_s"), 3) + " s)."
                               : "`" + b.text("scheme") + "`, " + fmt(b.number("dt_s"), 3) + " s flight step, " +
                                     fmt(b.number("contact_dt_s"), 3) + " s contact step."));
    if (mesh) {
      const std::string caveat = mesh_caveat(b, *mesh);
      if (!caveat.empty()) w.text(caveat);
    }
  }
  for (const auto& param : c.strings("parameters")) {
    const Record& pr = c.at(param);
    const auto names = pr.strings("sweeps");
    w.subheading("Bounce count against " + axis_of(param));
    std::vector<PlotSeries> ps;
    bool any_failed = false;
    for (std::size_t i = 0; i < names.size(); ++i) {
      const Record& s = pr.at(names[i]);
      const std::string colour = " lc " + std::to_string(i + 1);
      for (PlotSeries& p : count_curve(s, who(s), colour, s.text("solver") != "realtime")) {
        any_failed |= p.style.rfind("points pt 2", 0) == 0 && !p.x.empty();
        ps.push_back(std::move(p));
      }
    }
    PlotAxes ax;
    ax.x_label = axis_of(param);
    ax.y_label = "bounces";
    ax.extra = "set yrange [" + std::string(any_failed ? "-1.5" : "-0.5") + ":*]\nset offsets 0, 0, 1, 0\n" +
               (any_failed ? "set ytics add ('failed' -1)\n" : "");
    w.figure(line_figure("sweep_" + param, "Bounce count against " + axis_of(param), ax, ps, param, "bounces"));
    w.text("Dots: every stored run (the grid values and both ends of each bracket). Each count holds to halfway to its "
           "neighbours, so a change is drawn at the middle of its final bracket — the value in the thresholds table below — "
           "and the last grid value holds over the last half spacing. × on the row *failed*: a run whose solve failed; the "
           "line stops at the run before it and starts again at the run after it, never bridged. The reference's lines "
           "and crosses are drawn wider, beneath the real-time ones: where the two agree, the reference shows as a border.");
    std::vector<std::string> headers{axis_of(param)};
    for (const auto& n : names) headers.push_back(who(pr.at(n)));
    MarkdownTable counts(headers);
    const auto values = pr.table("values").column("value");
    for (std::size_t i = 0; i < values.size(); ++i) {
      std::vector<std::string> row{fmt(values[i], 3)};
      for (const auto& n : names) row.push_back(count_text(pr.at(n).table("counts").column("bounces")[i]));
      counts.row(row);
    }
    w.table(counts);
    w.text("Thresholds (bisected to the tolerance; the value is the middle of the final bracket):");
    MarkdownTable th({"convention, solver", "thresholds: value (bounces below → above)", "runs", "CPU (s)"});
    for (const auto& n : names) {
      const Record& s = pr.at(n);
      const Table& t = s.table("thresholds");
      std::ostringstream txt;
      for (std::size_t i = 0; i < t.rows(); ++i) {
        const double lo = t.column("lo")[i], hi = t.column("hi")[i];
        const bool stopped = t.has_column("failed_at") && !std::isnan(t.column("failed_at")[i]);
        const std::string change = count_text(t.column("count_below")[i]) + "→" + count_text(t.column("count_above")[i]);
        txt << (i ? "; " : "") << fmt(0.5 * (lo + hi), 4)
            << (t.column("bisected")[i] != 0 ? " ± " + fmt(0.5 * (hi - lo), 2) + " (" + change + ")"
                : stopped ? " ± " + fmt(0.5 * (hi - lo), 2) + " (" + change + "; not located: bisection stopped at a " +
                                "failed run, " + fmt(t.column("failed_at")[i], 4) + stopped_because(s, i) + ")"
                          : " (not bisected) (" + change + ")");
        // Bisection follows one change per grid cell; a cell whose far end has another count holds more.
        if (t.has_column("count_at_cell_end") &&
            t.column("bisected")[i] != 0 && t.column("count_at_cell_end")[i] != t.column("count_above")[i]) {
          double end = hi;  // the grid value that closes the cell: the smallest at or above hi
          for (double v : s.table("counts").column("value"))
            if (v >= hi && (end == hi || v < end)) end = v;
          txt << ", then " << count_text(t.column("count_at_cell_end")[i]) << " at " << fmt(end, 4)
              << ": more changes in this cell, not located";
        }
      }
      if (t.rows() == 0) txt << "none: the count does not change";
      th.row({who(s), txt.str(), fmt(s.number("runs"), 8), fmt(s.number("cpu_s"), 3)});
    }
    w.table(th);
    const Record& cmp = pr.at("comparison");
    for (const auto& conv : cmp.child_names()) {
      const Record& k = cmp.at(conv);
      std::string counts_range = std::isnan(k.number("reference_max_bounces"))
                                     ? std::string("nothing")
                                     : fmt(k.number("reference_min_bounces")) + "–" + fmt(k.number("reference_max_bounces"));
      std::string line = conv + " convention: at the grid's values the reference counts " + counts_range +
                         " bounces (the bisections between them may find more; the table above has them)";
      if (k.number("reference_failed") > 0) line += " (" + fmt(k.number("reference_failed")) + " reference runs failed)";
      line += "; the real-time stepper agrees at " + fmt(k.number("agree")) + " of " + fmt(k.number("grid_points")) +
              " grid values; " + fmt(k.number("reference_thresholds")) +
              (k.has_number("cells_with_more_changes") && k.number("cells_with_more_changes") > 0
                   ? " or more changes of the reference count (" + fmt(k.number("cells_with_more_changes")) +
                         " grid cells hold changes bisection did not locate) — "
                   : " changes of the reference count — ") +
              verdict_markdown(k.at("character"));
      w.bullet(line + ".");
    }
    w.end_list();
  }

  // Fig. 9: momentum against time.
  w.subheading("Momentum against time (the paper's Fig. 9)");
  w.text("The seed's 8 m/s throw without spin and with spin, both solvers, both conventions (the numbers beside the "
         "seed's claims are in section 5).");
  for (const char* conv : {"physical", "paper"}) {
    std::vector<PlotSeries> ps;
    for (const auto& key : fig9.strings("histories")) {
      const Record& h = fig9.at(key);
      if (h.text("convention") != conv) continue;
      ps.push_back(table_series(h.text("label") + " (" + fmt(h.number("bounces")) + " bounces)", h, "history", "t_s",
                                "momentum_kg_m_s", h.text("solver").rfind("realtime", 0) == 0 ? "lines dt 2" : "lines"));
    }
    PlotAxes ax;
    ax.x_label = "time (s)";
    ax.y_label = "momentum |p| (kg m/s)";
    Figure f = line_figure(std::string("fig9_momentum_") + conv, std::string("Momentum against time, ") + conv + " convention",
                           ax, ps, "t_s", "momentum_kg_m_s");
    f.data_path = fig9.path();
    w.figure(f);
  }
  return w.finish();
}

}  // namespace stoneskip
