// The stones report's section on bounce counts against the stone's mesh
// (verification/stones/mesh_study.hpp), formatted from its stored record.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "reports/common/markdown.hpp"
#include "reports/stones/report_sections.hpp"
#include "verification/study/stored_values.hpp"

namespace stoneskip {

namespace {

std::string mesh_name(const Table& meshes, std::size_t m) {
  const auto n = meshes.column("segments"), c = meshes.column("centre_cut"), t = meshes.column("triangles");
  return "N = " + fmt(n[m], 6) + ", " + (c[m] > 0 ? "centre" : "diagonal") + " cut (" + fmt(t[m], 6) + " triangles)";
}

std::string throw_name(double spin, double attack) { return "spin " + fmt(spin, 6) + " rev/s, attack " + fmt(attack, 6) + "°"; }

// "k of n" tallies of one mesh, in words.
std::string tally_words(double changed, double none, double same, double undecided) {
  std::string s = "different on " + fmt(changed, 4) + ", no difference established on " + fmt(none, 4) + ", the same count on " +
                  fmt(same, 4);
  if (undecided > 0) s += ", not decided (runs failed, or too few members ran) on " + fmt(undecided, 4);
  return s;
}

// How the verdicts are tested, and at which levels. Records since the family levels store them;
// older ones tested every verdict at 95 % on its own, and keep that text.
std::string levels_words(const Record& m) {
  const std::string test =
      "Test: the paired t interval of the mean difference of the counts; a difference is established only where the "
      "interval excludes 0, and where no pair's difference varies (an interval without width) only where the exact "
      "sign-flip test's p is under the level's α; where a run of either ensemble failed, nothing is decided. ";
  if (!m.has_number("mirror_confidence"))
    return test + "Each verdict holds at 95 %: of this section's " + fmt(m.number("verdict_count"), 4) + " verdicts, about " +
           fmt(0.05 * m.number("verdict_count"), 2) + " could say \"different\" by chance where there is no difference.";
  const double family = m.number("family_confidence");
  const std::size_t cuts = m.at("verdicts").strings("cut_order").size(), mirrors = m.at("verdicts").strings("mirror_order").size();
  std::string s = test + "Against its cut's reference each verdict is at " + fmt(100 * m.number("reference_confidence"), 4) +
                  " % on its own: a chance \"different\" there can only make a mesh look unsettled, the cautious side of "
                  "the settled N below, where a stricter level would make settling easier by chance.";
  auto family_words = [&](const std::string& what, std::size_t n, double each) {
    return " The " + fmt(double(n), 4) + " " + what + " claim a difference where they find one, so they are one family held "
           "to " + fmt(100 * family, 4) + " % together (Bonferroni): each at " + fmt(100 * each, 4) + " %.";
  };
  if (cuts > 0) s += family_words("comparisons of the two cuts", cuts, m.number("cut_confidence"));
  if (mirrors > 0) s += family_words("mirror-pair comparisons", mirrors, m.number("mirror_confidence"));
  return s;
}

}  // namespace

SectionOutput mesh_section(const Record& m) {
  SectionWriter w(m, "3c. Bounce counts against the stone's mesh");
  const Table& meshes = m.table("meshes");
  const Table& counts = m.table("counts");
  const std::size_t nm = meshes.rows();
  const auto mass = meshes.column("mass_kg"), segs = meshes.column("segments"), refs = meshes.column("reference");
  // The solid changes with N: say how, from the stored masses.
  std::size_t lo_n = 0, hi_n = 0;
  for (std::size_t k = 0; k < nm; ++k) {
    if (segs[k] < segs[lo_n]) lo_n = k;
    if (segs[k] > segs[hi_n]) hi_n = k;
  }
  const std::string solid =
      mass[lo_n] == mass[hi_n]
          ? "The stone's mass is the case's at every N (" + fmt(1e3 * mass[lo_n], 4) + " g); its inertia follows the N-gon."
          : "With the case's density the N-gon's mass and inertia follow N: " + fmt(1e3 * mass[lo_n], 4) + " g at N = " +
                fmt(segs[lo_n], 6) + ", " + fmt(1e3 * mass[hi_n], 4) + " g at N = " + fmt(segs[hi_n], 6) + ".";
  w.lead("What is measured.",
         "Is a bounce count a property of the stone, or of the triangles it is drawn with? The same throws are thrown "
         "with prisms of N rim segments, each rim face cut along one diagonal (the paper's 44-triangle stone at N = 11: "
         "a mesh with a hand, model/README.md §1.1) or at its centre (a mesh that is its own mirror image). The cut "
         "changes the faces, not the solid; N changes both. " + solid + " Each throw runs as an ensemble of " +
             fmt(m.number("members"), 4) + " throws per mesh, the speed multiplied by 1 ± ε with ε log-spaced from " +
             fmt(m.number("perturbation_smallest"), 2) + " to " + fmt(m.number("perturbation_largest"), 2) +
             " (the same factors for every mesh, so members pair up), solved by " + m.text("solver") +
             ". Each mesh is compared with its cut's reference, the same cut at the largest N; where both cuts reach "
             "that N, the two references are compared with each other; and where the throws hold a spin and its mirror "
             "image (−spin, the same attack angle), each mesh's two ensembles are compared. " + levels_words(m));
  // Mean ± sd per mesh (rows) and throw (columns).
  const auto thr = counts.column("throw"), spin = counts.column("spin_rev_s"), attack = counts.column("attack_angle_deg"),
             mesh = counts.column("mesh"), mean = counts.column("count_mean"), sd = counts.column("count_sd"),
             lo = counts.column("count_min"), hi = counts.column("count_max"), failed = counts.column("failed");
  const std::size_t nt = stored_count(m, "throws", counts.rows());  // each throw has rows in the table
  std::vector<std::string> headers{"mesh", "mass (g)"};
  for (std::size_t t = 0; t < nt; ++t)
    for (std::size_t i = 0; i < counts.rows(); ++i)
      if (thr[i] == double(t)) {
        headers.push_back(throw_name(spin[i], attack[i]));
        break;
      }
  const Record& verdicts = m.at("verdicts");
  MarkdownTable table(headers);
  for (std::size_t k = 0; k < nm; ++k) {
    std::vector<std::string> row{mesh_name(meshes, k) + (refs[k] == double(k) ? " (its cut's reference)" : ""),
                                 fmt(1e3 * mass[k], 4)};
    for (std::size_t t = 0; t < nt; ++t)
      for (std::size_t i = 0; i < counts.rows(); ++i) {
        if (thr[i] != double(t) || mesh[i] != double(k)) continue;
        std::string cell = fmt_or_dash(mean[i]) + " ± " + fmt_or_dash(sd[i], 2) + " (" + fmt_or_dash(lo[i]) + "–" + fmt_or_dash(hi[i]) +
                           (failed[i] > 0 ? ", " + fmt(failed[i], 4) + " failed" : "") + ")";
        char key[64];
        std::snprintf(key, sizeof key, "throw_%zu_mesh_%zu", t + 1, k + 1);
        if (verdicts.has_child(key)) {
          const std::string v = verdicts.at(key).text("verdict");
          cell += v == "different bounce counts" ? " **≠**" : v == "same bounce count" ? " =" : v == "no difference established" ? "" : " ?";
        }
        row.push_back(cell);
      }
    table.row(row);
  }
  w.text("Mean ± sd (least–most) of the bounce counts of each ensemble. **≠**: different from its cut's reference "
         "(95 % interval); =: every member of both gives one and the same count; ?: not decided; no mark: no difference "
         "established.");
  w.table(table);
  // The tallies, per mesh.
  const auto changed = meshes.column("changed"), none = meshes.column("not_established"), same = meshes.column("same"),
             undecided = meshes.column("undecided"), pairs = meshes.column("mirror_pairs"),
             mdiff = meshes.column("mirror_different"), mnone = meshes.column("mirror_not_established"),
             msame = meshes.column("mirror_same"), mund = meshes.column("mirror_undecided");
  for (std::size_t k = 0; k < nm; ++k) {
    const std::size_t r = static_cast<std::size_t>(refs[k]);
    if (r == k) continue;
    w.bullet(mesh_name(meshes, k) + " against " + mesh_name(meshes, r) + ": " +
             tally_words(changed[k], none[k], same[k], undecided[k]) + " of " + fmt(double(nt), 4) + " throws.");
  }
  w.end_list();
  // Per cut: from which N on no difference from the reference is established.
  const Table& cuts = m.table("cuts");
  const auto cut_centre = cuts.column("centre_cut"), cut_ref = cuts.column("reference_segments"),
             cut_meshes = cuts.column("meshes"), settled = cuts.column("settled_segments");
  for (std::size_t c = 0; c < cuts.rows(); ++c) {
    const std::string cut = cut_centre[c] > 0 ? "centre" : "diagonal";
    if (cut_meshes[c] < 2)
      w.bullet("The " + cut + " cut has one mesh: nothing to compare it with.");
    else if (std::isnan(settled[c]))
      w.bullet("The " + cut + " cut: its reference is N = " + fmt(cut_ref[c], 6) +
               ", and even the next mesh below it differs from it, or is undecided, at some throw: **the count is not "
               "shown to settle** over these N.");
    else {
      bool below = false;
      const auto centre_col = meshes.column("centre_cut");
      for (std::size_t k = 0; k < nm; ++k) below = below || ((centre_col[k] > 0) == (cut_centre[c] > 0) && segs[k] < settled[c]);
      w.bullet("The " + cut + " cut: from N = " + fmt(settled[c], 6) + " to " + fmt(cut_ref[c], 6) +
               " no mesh differs from the reference at any throw (no difference established, none undecided)" +
               (below ? "; the next N below differs or is undecided at some throw." : "."));
    }
  }
  w.end_list();
  const auto& cut_order = verdicts.strings("cut_order");
  if (!cut_order.empty()) {
    int diff = 0, none_cut = 0, same_cut = 0, und = 0;
    for (const auto& key : cut_order) {
      const std::string v = verdicts.at(key).text("verdict");
      (v == "different bounce counts" ? diff : v == "no difference established" ? none_cut : v == "same bounce count" ? same_cut : und)++;
    }
    w.text("The two cuts' references against each other (the cut alone, at one N): " +
           tally_words(diff, none_cut, same_cut, und) + " of " + fmt(double(cut_order.size()), 4) + " throws.");
  }
  if (pairs.size() > 0 && pairs[0] > 0) {
    w.text("A throw against its mirror image (spin reversed), per mesh, over " + fmt(pairs[0], 4) + " pair(s):");
    for (std::size_t k = 0; k < nm; ++k)
      w.bullet(mesh_name(meshes, k) + ": " + tally_words(mdiff[k], mnone[k], msame[k], mund[k]) + ".");
    w.end_list();
  }
  {
    // One line per throw and cut: the mean count against N.
    std::vector<PlotSeries> series;
    const auto family = counts.column("family");
    std::vector<double> seen;
    for (std::size_t i = 0; i < counts.rows(); ++i) {
      bool known = false;
      for (double f : seen) known = known || f == family[i];
      if (known) continue;
      seen.push_back(family[i]);
      TableSource how;
      how.x_column = "segments";
      how.y_column = "count_mean";
      how.where_column = "family";
      how.where_value = family[i];
      // One colour per throw; the centre cut solid, the diagonal cut dashed with open points.
      const bool centre = counts.column("centre_cut")[i] > 0;
      const std::string colour = " lc " + fmt(thr[i] + 1, 4);
      series.push_back(table_series(throw_name(spin[i], attack[i]) + (centre ? ", centre cut" : ", diagonal cut"), m, "counts",
                                    how, centre ? "linespoints lw 2 pt 7" + colour : "linespoints dt 2 pt 6 ps 1.5" + colour));
    }
    // Ticks at the meshes' N, and a margin beyond the first and the last.
    std::string tics;
    double n_lo = segs.empty() ? 1 : segs[0], n_hi = n_lo;
    for (std::size_t k = 0; k < segs.size(); ++k) {
      if (tics.find("\"" + fmt(segs[k], 6) + "\"") == std::string::npos)
        tics += (tics.empty() ? "" : ", ") + ("\"" + fmt(segs[k], 6) + "\" " + fmt(segs[k], 6));
      n_lo = std::min(n_lo, segs[k]);
      n_hi = std::max(n_hi, segs[k]);
    }
    PlotAxes ax;
    ax.x_label = "rim segments N";
    ax.y_label = "mean bounce count of the ensemble";
    ax.log_x = true;
    ax.extra = "set key outside right\nset xtics (" + tics + ")\nset xrange [" + fmt(n_lo / 1.1, 6) + ":" + fmt(n_hi * 1.1, 6) +
               "]\nset yrange [0:*]";
    Figure f = line_figure("mesh_counts", "Mean bounce count of each throw's ensemble against the number of rim segments", ax,
                           series, "segments", "count_mean");
    f.data_path = m.path();
    w.figure(f);
    w.text("Means only: the table gives each ensemble's spread. Where a mesh's mirror pairs give the same counts, a "
           "spin's line and its mirror's lie on one another.");
  }
  w.subheading("Reasons");
  const auto& order = verdicts.strings("order");
  const auto& subjects = m.strings("subjects");
  for (std::size_t i = 0; i < order.size(); ++i) w.verdict(subjects[i], verdicts.at(order[i]));
  const auto& cut_subjects = m.strings("cut_subjects");
  for (std::size_t i = 0; i < cut_order.size(); ++i) w.verdict("cuts, " + cut_subjects[i], verdicts.at(cut_order[i]));
  const auto& mirror_order = verdicts.strings("mirror_order");
  const auto& mirror_subjects = m.strings("mirror_subjects");
  for (std::size_t i = 0; i < mirror_order.size(); ++i) w.verdict("mirror " + mirror_subjects[i], verdicts.at(mirror_order[i]));
  w.end_list();
  return w.finish();
}

}  // namespace stoneskip
