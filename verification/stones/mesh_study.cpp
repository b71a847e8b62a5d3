#include "verification/stones/mesh_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "verification/study/ensemble_difference.hpp"
#include "verification/study/verdict_rules.hpp"

namespace stoneskip {

bool MeshStudyOptions::valid(std::string* why) const {
  auto fail = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (meshes.size() < 2) return fail("the mesh study needs at least 2 meshes");
  for (std::size_t i = 0; i < meshes.size(); ++i)
    for (std::size_t j = i + 1; j < meshes.size(); ++j)
      if (meshes[i].segments == meshes[j].segments && meshes[i].split == meshes[j].split)
        return fail("the mesh study lists one mesh twice");
  if (spins_rev_s.empty() || attack_angles_deg.empty()) return fail("the mesh study needs at least one spin and one attack angle");
  for (const auto* list : {&spins_rev_s, &attack_angles_deg})
    for (std::size_t i = 0; i < list->size(); ++i)
      for (std::size_t j = i + 1; j < list->size(); ++j)
        if ((*list)[i] == (*list)[j]) return fail("the mesh study lists one throw twice");
  if (members < 2 || members % 2 != 0 || members > 1000) return fail("mesh study members must be even, in [2, 1000]");
  if (!(perturbation_smallest > 0) || !(perturbation_largest >= perturbation_smallest) || !(perturbation_largest < 1))
    return fail("mesh study perturbations must satisfy 0 < smallest <= largest < 1");
  if (!(family_confidence > 0 && family_confidence < 1)) return fail("mesh study family_confidence must be in (0, 1)");
  return true;
}

std::size_t MeshStudyOptions::reference_of(std::size_t m) const {
  std::size_t best = m;
  for (std::size_t i = 0; i < meshes.size(); ++i)
    if (meshes[i].split == meshes[m].split && meshes[i].segments > meshes[best].segments) best = i;
  return best;
}

namespace {

struct Summary {
  std::vector<double> ran;  // the members with a count
  int failed = 0;
  double mean = std::nan(""), sd = std::nan(""), low = std::nan(""), high = std::nan("");
};

Summary summary_of(const std::vector<double>& counts) {
  Summary s;
  for (double c : counts) {
    if (c < 0) ++s.failed;
    else s.ran.push_back(c);
  }
  if (s.ran.empty()) return s;
  double sum = 0;
  for (double c : s.ran) sum += c;
  s.mean = sum / s.ran.size();
  double ss = 0;
  for (double c : s.ran) ss += (c - s.mean) * (c - s.mean);
  s.sd = s.ran.size() > 1 ? std::sqrt(ss / (s.ran.size() - 1)) : std::nan("");
  s.low = *std::min_element(s.ran.begin(), s.ran.end());
  s.high = *std::max_element(s.ran.begin(), s.ran.end());
  return s;
}

const char* cut_name(RimSplit s) { return s == RimSplit::centre ? "centre cut" : "diagonal cut"; }

std::string mesh_name(const MeshVariant& m) {
  return "N = " + std::to_string(m.segments) + ", " + cut_name(m.split) + " (" +
         std::to_string(m.stone.body_mesh.triangles.size()) + " triangles)";
}

std::string throw_name(double spin, double attack) {
  char b[96];
  std::snprintf(b, sizeof b, "spin %.6g rev/s, attack %.6g°", spin, attack);
  return b;
}

// The two cuts' reference meshes (diagonal, centre; meshes.size() where a cut has none).
std::pair<std::size_t, std::size_t> cut_references(const MeshStudyOptions& o) {
  std::size_t ref_diagonal = o.meshes.size(), ref_centre = o.meshes.size();
  for (std::size_t m = 0; m < o.meshes.size(); ++m)
    if (o.reference_of(m) == m) (o.meshes[m].split == RimSplit::centre ? ref_centre : ref_diagonal) = m;
  return {ref_diagonal, ref_centre};
}

// Whether the two cuts' references share one N (then they are compared with each other).
bool shared_reference_n(const MeshStudyOptions& o) {
  const auto [d, c] = cut_references(o);
  return d < o.meshes.size() && c < o.meshes.size() && o.meshes[d].segments == o.meshes[c].segments;
}

// The verdict of two ensembles of one throw (a and b), with its reason, at the two-sided level
// `confidence`.
const Record& compare(Record& verdicts, const std::string& key, const std::vector<double>& a, const std::vector<double>& b,
                      const std::string& what, double confidence) {
  const Summary sa = summary_of(a), sb = summary_of(b);
  // The members pair up by their speed factor; those where either run failed leave the pairs (and
  // any failure leaves the verdict undecided).
  std::vector<double> pa, pb;
  int unequal = 0;
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k)
    if (a[k] >= 0 && b[k] >= 0) {
      pa.push_back(a[k]);
      pb.push_back(b[k]);
      unequal += a[k] != b[k] ? 1 : 0;
    }
  MeanDifference d = paired_difference(pa, pb, confidence);
  Record in;
  in.set("valid", d.valid);
  in.set("difference_low", d.valid ? d.low : std::nan(""));
  in.set("difference_high", d.valid ? d.high : std::nan(""));
  in.set("count_spread", d.valid ? d.sd_a + d.sd_b : std::nan(""));
  in.set("exact_p", d.exact_p);  // no spread: the exact sign-flip test (ensemble_difference.hpp)
  in.set("alpha", d.alpha);
  in.set("failed_runs", sa.failed + sb.failed);
  char reason[640];
  in.set("unequal_pairs", unequal);
  std::snprintf(reason, sizeof reason,
                "%s: %.3g ± %.2g against %.3g ± %.2g bounces (mean ± sd over %zu members each; %d and %d failed); "
                "%d of %zu pairs differ; mean difference %.3g, %.4g %% interval [%.3g, %.3g] (paired t)",
                what.c_str(), sa.mean, sa.sd, sb.mean, sb.sd, a.size(), sa.failed, sb.failed, unequal, pa.size(),
                d.valid ? d.difference : std::nan(""), 100 * confidence, d.valid ? d.low : std::nan(""),
                d.valid ? d.high : std::nan(""));
  std::string why = reason;
  if (d.valid && std::isfinite(d.exact_p)) {
    char exact[160];
    std::snprintf(exact, sizeof exact,
                  "; no pair's difference varies, so the exact sign-flip test decides: p = %.4g against α = %.4g", d.exact_p,
                  d.alpha);
    why += exact;
  }
  return decide_verdict(verdicts, key, "ensemble_count_difference", in, why);
}

}  // namespace

std::vector<MeshThrowRuns> run_mesh_study(const ThrowProblem& base, const SolverChoice& solver, const MeshStudyOptions& o,
                                          const ParallelOptions& parallel) {
  std::string why;
  if (!o.valid(&why)) throw std::invalid_argument("mesh study: " + why);
  if (!base.from_parameters) throw std::invalid_argument("mesh study: the base throw must give [throw] parameters");
  // The paper convention's forces gain energy and its counts are chaotic run by run: neither the
  // mirror premise nor a settled count holds there (model/README.md §1.6).
  if (base.environment.convention != Convention::physical)
    throw std::invalid_argument("mesh study: the base throw must be in the physical convention");
  const std::vector<double> factors = perturbation_factors(o.members, o.perturbation_smallest, o.perturbation_largest);
  std::vector<MeshThrowRuns> out;
  for (double attack : o.attack_angles_deg)
    for (double spin : o.spins_rev_s) {
      MeshThrowRuns r;
      r.spin_rev_s = spin;
      r.attack_angle_deg = attack;
      r.counts.assign(o.meshes.size(), std::vector<double>(factors.size(), -1.0));
      out.push_back(r);
    }
  // The problems: the base with each mesh's stone, each throw's parameters, each member's speed.
  std::vector<ThrowProblem> problems;
  std::vector<double*> slots;
  for (MeshThrowRuns& r : out)
    for (std::size_t m = 0; m < o.meshes.size(); ++m) {
      ThrowProblem p = base;
      p.stone = o.meshes[m].stone;
      for (std::size_t k = 0; k < factors.size(); ++k) {
        ThrowParameters tp = base.parameters;
        tp.spin_rev_s = r.spin_rev_s;
        tp.attack_angle_deg = r.attack_angle_deg;
        tp.speed_m_s *= factors[k];
        problems.push_back(with_parameters(p, tp));
        slots.push_back(&r.counts[m][k]);
      }
    }
  parallel_for(problems.size(), [&](std::size_t i) { *slots[i] = sweep_bounce_count(problems[i], solver); }, parallel);
  return out;
}

Record mesh_study_findings(const std::vector<MeshThrowRuns>& runs, const MeshStudyOptions& o, const std::string& solver_label) {
  Record r;
  r.set("solver", solver_label);
  r.set("members", o.members);
  r.set("perturbation_smallest", o.perturbation_smallest);
  r.set("perturbation_largest", o.perturbation_largest);
  // The levels (mesh_study.hpp): against the reference each verdict at 95 % on its own; the cuts'
  // and the mirror pairs' verdicts each a family held to family_confidence together (Bonferroni).
  const bool cuts_compared = shared_reference_n(o);
  std::size_t mirror_comparisons = 0;
  for (const MeshThrowRuns& t : runs)
    for (const MeshThrowRuns& u : runs)
      if (t.spin_rev_s > 0 && u.spin_rev_s == -t.spin_rev_s && u.attack_angle_deg == t.attack_angle_deg)
        mirror_comparisons += o.meshes.size();
  const double reference_level = 0.95,
               cut_level = bonferroni_confidence(o.family_confidence, cuts_compared ? runs.size() : 0),
               mirror_level = bonferroni_confidence(o.family_confidence, mirror_comparisons);
  r.set("family_confidence", o.family_confidence);
  r.set("reference_confidence", reference_level);
  r.set("cut_confidence", cut_level);
  r.set("mirror_confidence", mirror_level);
  Table meshes{{"segments", "centre_cut", "triangles", "mass_kg", "reference", "changed", "not_established", "same", "undecided",
                "mirror_pairs", "mirror_different", "mirror_not_established", "mirror_same", "mirror_undecided"},
               {}};
  std::vector<std::vector<double>> tally(o.meshes.size(), std::vector<double>(8, 0.0));
  // One row per throw and mesh; family = 2 × throw + centre cut: one line of the figure.
  Table counts{{"throw", "spin_rev_s", "attack_angle_deg", "mesh", "segments", "centre_cut", "family", "count_mean", "count_sd",
                "count_min", "count_max", "failed", "members"},
               {}};
  Record& verdicts = r.child("verdicts");
  std::vector<std::string> order, subjects;
  auto tally_of = [](const std::string& phrase) {
    if (phrase == "different bounce counts") return 0;
    if (phrase == "no difference established") return 1;
    if (phrase == "same bounce count") return 2;
    return 3;  // not decided: runs failed, not measured
  };
  // Per mesh: comparisons whose ensembles had no spread and differed, too few members for the exact
  // test to establish it (ensemble_difference.hpp): "no difference established", but not agreement,
  // so a cut does not settle across them.
  std::vector<int> too_few(o.meshes.size(), 0);
  for (std::size_t t = 0; t < runs.size(); ++t) {
    const MeshThrowRuns& run = runs[t];
    for (std::size_t m = 0; m < o.meshes.size(); ++m) {
      const Summary s = summary_of(run.counts[m]);
      const double centre = o.meshes[m].split == RimSplit::centre ? 1.0 : 0.0;
      counts.add_row({double(t), run.spin_rev_s, run.attack_angle_deg, double(m), double(o.meshes[m].segments), centre,
                      2.0 * double(t) + centre, s.mean, s.sd, s.low, s.high, double(s.failed), double(run.counts[m].size())});
      const std::size_t ref = o.reference_of(m);
      if (ref == m) continue;
      char key[64];
      std::snprintf(key, sizeof key, "throw_%zu_mesh_%zu", t + 1, m + 1);
      const Record& v = compare(verdicts, key, run.counts[m], run.counts[ref],
                                mesh_name(o.meshes[m]) + " against " + mesh_name(o.meshes[ref]), reference_level);
      ++tally[m][tally_of(v.text("verdict"))];
      if (v.text("verdict") == "no difference established" && v.has_number("exact_p") && std::isfinite(v.number("exact_p")))
        ++too_few[m];
      order.push_back(key);
      subjects.push_back(throw_name(run.spin_rev_s, run.attack_angle_deg) + ", " + mesh_name(o.meshes[m]));
    }
  }
  // The two cuts' references against each other, where they share one N (the cut alone).
  const auto [ref_diagonal, ref_centre] = cut_references(o);
  std::vector<std::string> cut_order, cut_subjects;
  if (cuts_compared)
    for (std::size_t t = 0; t < runs.size(); ++t) {
      char key[64];
      std::snprintf(key, sizeof key, "cuts_throw_%zu", t + 1);
      compare(verdicts, key, runs[t].counts[ref_diagonal], runs[t].counts[ref_centre],
              mesh_name(o.meshes[ref_diagonal]) + " against " + mesh_name(o.meshes[ref_centre]), cut_level);
      cut_order.push_back(key);
      cut_subjects.push_back(throw_name(runs[t].spin_rev_s, runs[t].attack_angle_deg));
    }
  // Mirror pairs: spin s > 0 and −s at one attack angle.
  std::vector<std::string> mirror_order, mirror_subjects;
  for (std::size_t t = 0; t < runs.size(); ++t)
    for (std::size_t u = 0; u < runs.size(); ++u) {
      if (!(runs[t].spin_rev_s > 0) || runs[u].spin_rev_s != -runs[t].spin_rev_s ||
          runs[u].attack_angle_deg != runs[t].attack_angle_deg)
        continue;
      for (std::size_t m = 0; m < o.meshes.size(); ++m) {
        char key[96];
        std::snprintf(key, sizeof key, "mirror_%zu_%zu_mesh_%zu", t + 1, u + 1, m + 1);
        const Record& v = compare(verdicts, key, runs[t].counts[m], runs[u].counts[m],
                                  mesh_name(o.meshes[m]) + ": " + throw_name(runs[t].spin_rev_s, runs[t].attack_angle_deg) +
                                      " against its mirror image",
                                  mirror_level);
        ++tally[m][4 + tally_of(v.text("verdict"))];
        mirror_order.push_back(key);
        char subject[128];
        std::snprintf(subject, sizeof subject, "±%.6g rev/s, attack %.6g°, ", runs[t].spin_rev_s, runs[t].attack_angle_deg);
        mirror_subjects.push_back(subject + mesh_name(o.meshes[m]));
      }
    }
  const std::size_t pairs = o.meshes.empty() ? 0 : mirror_order.size() / o.meshes.size();
  for (std::size_t m = 0; m < o.meshes.size(); ++m) {
    const MeshVariant& v = o.meshes[m];
    const std::vector<double>& c = tally[m];
    meshes.add_row({double(v.segments), v.split == RimSplit::centre ? 1.0 : 0.0, double(v.stone.body_mesh.triangles.size()),
                    v.stone.mass.mass_kg, double(o.reference_of(m)), c[0], c[1], c[2], c[3], double(pairs), c[4], c[5], c[6],
                    c[7]});
  }
  // Per cut: the smallest N from which on no mesh of that cut differs from its reference, nor is
  // undecided, nor differs in every member with too few members to tell, at any throw (NaN: not
  // even the mesh below the reference, or the cut has one mesh).
  Table cuts{{"centre_cut", "reference_segments", "meshes", "settled_segments"}, {}};
  for (RimSplit split : {RimSplit::diagonal, RimSplit::centre}) {
    std::vector<std::size_t> of;
    for (std::size_t m = 0; m < o.meshes.size(); ++m)
      if (o.meshes[m].split == split) of.push_back(m);
    if (of.empty()) continue;
    std::sort(of.begin(), of.end(), [&](std::size_t a, std::size_t b) { return o.meshes[a].segments > o.meshes[b].segments; });
    double settled = o.meshes[of.front()].segments;  // the reference
    for (std::size_t k = 1; k < of.size(); ++k) {
      if (tally[of[k]][0] > 0 || tally[of[k]][3] > 0 || too_few[of[k]] > 0) break;
      settled = o.meshes[of[k]].segments;
    }
    if (settled == o.meshes[of.front()].segments) settled = std::nan("");
    cuts.add_row({split == RimSplit::centre ? 1.0 : 0.0, double(o.meshes[of.front()].segments), double(of.size()), settled});
  }
  r.set_table("meshes", meshes);
  r.set_table("counts", counts);
  r.set_table("cuts", cuts);
  r.set("throws", runs.size());
  r.set("verdict_count", order.size() + cut_order.size() + mirror_order.size());
  verdicts.set_strings("order", order);
  r.set_strings("subjects", subjects);
  verdicts.set_strings("cut_order", cut_order);
  r.set_strings("cut_subjects", cut_subjects);
  verdicts.set_strings("mirror_order", mirror_order);
  r.set_strings("mirror_subjects", mirror_subjects);
  return r;
}

}  // namespace stoneskip
