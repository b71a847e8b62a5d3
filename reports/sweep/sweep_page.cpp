#include "reports/sweep/sweep_page.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

#include "reports/common/html_page.hpp"
#include "reports/common/markdown.hpp"
#include "reports/sweep/sweep_maps.hpp"
#include "tools/io/atomic_file.hpp"

namespace stoneskip {

namespace {

struct Stats {
  std::size_t n = 0;
  double mean = NAN, min = NAN, max = NAN, median = NAN, sum = 0;
};

Stats stats_of(std::vector<double> v) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  Stats s;
  s.n = v.size();
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  s.sum = std::accumulate(v.begin(), v.end(), 0.0);
  s.mean = s.sum / static_cast<double>(v.size());
  s.min = v.front();
  s.max = v.back();
  s.median = v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
  return s;
}

}  // namespace

std::string sweep_markdown(const SweepData& d, const std::vector<Figure>& figures, const std::string& source) {
  const Table& t = d.throws;
  const std::size_t rows = t.rows();
  std::ostringstream md;
  md << "# Sweep: " << d.provenance.title << "\n\n";
  md << "From `" << source << "` (sweep file `" << d.provenance.sweep_file << "`, base case `"
     << d.provenance.base_case_file << "`";
  for (const auto& o : d.provenance.base_overrides) md << " with `" << o << "`";
  md << "), " << d.provenance.code_version << ", written " << d.provenance.created_utc << ".\n\n";

  md << "## Design\n\n" << to_string(d.design.kind) << " design, " << rows << " throws";
  if (d.design.kind != DesignKind::grid) md << " (seed " << d.design.seed << ")";
  md << "; solvers: " << to_string(d.solvers) << ".\n\n";
  MarkdownTable axes({"varied key", "from", "to", "scale", d.design.kind == DesignKind::grid ? "points" : "strata"});
  for (const auto& a : d.design.axes)
    axes.row({"`" + a.key + "`", fmt(a.from, 6), fmt(a.to, 6), to_string(a.scale),
              d.design.kind == DesignKind::grid              ? std::to_string(a.count)
              : d.design.kind == DesignKind::latin_hypercube ? std::to_string(d.design.samples)
                                                             : "–"});
  md << axes.str() << "\n";

  md << "## Outcomes and bounce counts\n\n";
  MarkdownTable out({"solver", "sank", "reached t_max", "failed", "not run", "bounces: min", "median", "mean", "max"});
  for (const auto& s : solver_names(d.solvers)) {
    const std::vector<double> o = t.column(s + "_outcome");
    auto count = [&](double code) { return std::to_string(std::count(o.begin(), o.end(), code)); };
    const Stats b = stats_of(usable_counts(d, s));
    out.row({s, count(kOutcomeSank), count(kOutcomeTimeLimit), count(kOutcomeFailed), count(kOutcomeNotRun), fmt(b.min, 3),
             fmt(b.median, 3), fmt(b.mean, 3), fmt(b.max, 3)});
  }
  md << out.str() << "\n";
  if (d.solvers == SweepSolvers::both) {
    const std::vector<double> rt = usable_counts(d, "realtime"), ref = usable_counts(d, "reference");
    // Every count of the sentence runs over the same rows: the throws that both solvers solved (a
    // failed row's contact counts compare a partial solution and are not the sentence's).
    const std::vector<double> missed = t.column("disagreement_missed_contacts");
    const std::vector<double> spurious = t.column("disagreement_spurious_contacts");
    std::size_t both = 0, agree = 0, within1 = 0;
    std::vector<double> miss_both, spur_both;
    for (std::size_t i = 0; i < rt.size(); ++i) {
      if (!std::isfinite(rt[i]) || !std::isfinite(ref[i])) continue;
      ++both;
      agree += rt[i] == ref[i] ? 1 : 0;
      within1 += std::abs(rt[i] - ref[i]) <= 1 ? 1 : 0;
      miss_both.push_back(missed[i]);
      spur_both.push_back(spurious[i]);
    }
    const Stats miss = stats_of(miss_both);
    const Stats spur = stats_of(spur_both);
    md << "**Real-time against reference.** Of " << both << " throws that both solved, the bounce counts agree at "
       << agree << " (" << fmt(both ? 100.0 * agree / both : NAN, 3) << " %) and differ by at most one at " << within1
       << "; the real-time stepper missed " << fmt(miss.sum, 6) << " of the reference's contacts and added "
       << fmt(spur.sum, 6) << " (contact matching: verification/stones/contact_comparison.hpp). A bounce count "
       << "can be chaotic (a relative nudge of 1e-9 to a throw's speed can change it), so this is a description of "
       << "these throws, not a verdict on the solvers: the stones report decides that on ensembles of perturbed "
       << "throws (section 3b).\n\n";
  }

  md << "## Cost\n\n";
  MarkdownTable cost({"part", "per throw: mean (ms)", "median (ms)", "max (ms)", "max / min", "total (s)"});
  std::vector<std::pair<std::string, std::string>> parts = {{"case set-up (parse + build)", "cost_setup_wall_s"}};
  for (const auto& s : solver_names(d.solvers)) parts.emplace_back(s + " solve (wall)", "cost_" + s + "_wall_s");
  double solves = 0, setup = 0;
  for (const auto& [label, column] : parts) {
    if (!t.has_column(column)) continue;
    const Stats c = stats_of(t.column(column));
    (column == "cost_setup_wall_s" ? setup : solves) += c.sum;
    cost.row({label, fmt(1e3 * c.mean, 3), fmt(1e3 * c.median, 3), fmt(1e3 * c.max, 3),
              fmt(c.min > 0 ? c.max / c.min : NAN, 3), fmt(c.sum, 4)});
  }
  md << cost.str() << "\nThe case set-up (a copy of the parsed base case with the throw's values set, read by the case reader, the stone rebuilt) is "
     << fmt(solves > 0 ? 100.0 * setup / (setup + solves) : NAN, 2) << " % of the work.\n\n";
  const ScheduleStats& r = d.run.schedule;
  md << "**The run that finished the file:** " << r.ranks << " rank" << (r.ranks == 1 ? "" : "s") << ", "
     << r.master_threads << " compute thread" << (r.master_threads == 1 ? "" : "s") << " on rank 0; " << r.throws
     << " throws computed (" << r.remote_throws << " by other ranks), " << d.run.throws_recovered
     << " recovered from an interrupted run's journal; " << fmt(r.wall_s, 4) << " s wall, "
     << fmt(r.wall_s > 0 ? r.throws / r.wall_s : NAN, 4) << " throws/s; " << r.chunks
     << " chunks (at most " << d.run.max_chunk << " throws); rank 0's scheduling thread used "
     << fmt(r.master_cpu_s, 3) << " s CPU, " << fmt(r.master_busy_cpu_s, 3) << " s of it handling results and requests ("
     << fmt(r.throws ? 1e6 * r.master_busy_cpu_s / r.throws : NAN, 3) << " µs per throw: the master's cost per task), the rest "
     << "polling; the journal took " << fmt(d.run.journal_wall_s, 3) << " s wall.\n\n";

  md << "## Maps\n\n";
  if (figures.empty()) md << "No figures.\n\n";
  for (const auto& f : figures) md << figure_markdown(f);
  if (!d.notes.empty()) {
    md << "## Notes\n\n" << d.notes.size() << (d.notes.size() == 1 ? " throw needs" : " throws need")
       << " words (first 20 shown):\n\n";
    MarkdownTable notes({"throw", "solver", "detail"});
    for (std::size_t i = 0; i < std::min<std::size_t>(20, d.notes.size()); ++i)
      notes.row({std::to_string(d.notes[i].throw_index), d.notes[i].solver, d.notes[i].detail});
    md << notes.str() << "\n";
  }
  return md.str();
}

SweepPageSummary write_sweep_page(const std::filesystem::path& dir, const SweepData& d, const std::string& source,
                                  const SweepMapOptions& maps, bool render) {
  const std::vector<Figure> figs = sweep_map_figures(d, maps);  // before any file: a bad column writes nothing
  std::filesystem::create_directories(dir);
  Hdf5Writer w(dir / "data.h5");
  stamp_provenance(w.root());
  w.root().set_attr("source", source);
  const H5Group g = w.root().create_group("figures");
  for (const auto& f : figs) store_figure(g, f);
  w.commit();
  SweepPageSummary s;
  s.figures = figs.size();
  if (render) s.render = render_figures(dir, figs);
  const std::string markdown = mark_figures_not_drawn(sweep_markdown(d, figs, source), figs, s.render);
  write_text_file(dir / "index.md", markdown);
  write_text_file(dir / "index.html", html_page(markdown));
  return s;
}

}  // namespace stoneskip
