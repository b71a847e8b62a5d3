// The stones report's section on the two solvers' bounce counts compared on ensembles
// (verification/stones/count_ensembles.hpp), formatted from its stored record.
#include "reports/common/markdown.hpp"
#include "reports/stones/report_sections.hpp"

namespace stoneskip {

namespace {

std::string axis_name(const std::string& p) {
  if (p == "spin_rev_s") return "spin (rev/s)";
  if (p == "speed_m_s") return "speed (m/s)";
  if (p == "attack_angle_deg") return "attack angle (deg)";
  if (p == "path_angle_deg") return "path angle (deg)";
  return p;
}

std::string count_or_failed(double c) { return c < 0 ? std::string("failed") : fmt(c); }

// What the failed members were: runs that ran away (a thousandfold energy gain, which in the paper
// convention is its printed forces creating energy, spec §1.6: a stone that skips on, gaining speed,
// has no finished count) and runs that failed otherwise. Empty for data without the kinds stored.
std::string ran_away_tally(const Record& c) {
  if (!c.has_number("failed_runs") || !c.has_number("ran_away_runs") || c.number("failed_runs") == 0) return "";
  const double failed = c.number("failed_runs"), away = c.number("ran_away_runs");
  std::string s = " Of the " + fmt(failed, 6) + " failed members of all ensembles, " + fmt(away, 6) +
                  " ran away (their last energy over a thousand times the release energy";
  s += c.text("convention") == "paper" ? ": the printed forces create energy (model/README.md §1.6), so such a stone skips on "
                                         "with growing speed until the solver gives up)"
                                       : ": forces that only take energy away cannot do that, so the solver's steps did)";
  s += away == failed ? "." : "; " + fmt(failed - away, 6) + " failed otherwise (each throw's reason below says how many of each).";
  return s;
}

// How the throws are tested: records since the family correction store its levels; older ones
// were tested at 95 % each, and say so.
std::string test_sentence(const Record& c) {
  const std::string common =
      "a difference is established only where the interval excludes 0, and the verdict says \"no difference "
      "established\" where the ensembles cannot tell; where any run of either ensemble failed, nothing is decided. "
      "Where neither ensemble has any spread the interval is the difference itself, and an exact permutation test "
      "decides";
  if (c.has_number("comparison_confidence")) {
    const double each = c.number("comparison_confidence"), family = c.number("family_confidence");
    return "Test: Welch's t interval of the difference of the mean counts (real-time − reference), at " +
           fmt(100 * each, 4) + " % for each of the " + fmt(c.number("sampled"), 3) + " sampled throws, so that their " +
           "verdicts hold together at " + fmt(100 * family, 3) + " % (Bonferroni: a \"different\" anywhere in the table " +
           "is not a chance of many looks); " + common + " (p ≤ " + fmt(1 - each, 2) + ").";
  }
  return "Test: Welch's t interval (95 %) of the difference of the mean counts (real-time − reference); " + common +
         " (p ≤ 0.05). Each throw's interval is 95 % on its own, not jointly: over the " + fmt(c.number("sampled"), 3) +
         " throws, about " + fmt(0.05 * c.number("sampled"), 2) +
         " could read \"different\" by chance alone where the solvers agree on average (these data were written "
         "before the verdicts were held together).";
}

}  // namespace

SectionOutput count_ensembles_section(const Record& c) {
  SectionWriter w(c, "3b. Bounce counts of the two solvers, compared on ensembles");
  const std::string conv = c.text("convention");
  w.lead("What is measured.",
         "The sweeps above compare the real-time stepper and CVODE run against run at each grid value. In the `" + conv +
             "` convention the bounce count is chaotic (it can change under a 1e-9 relative change of the speed), so a "
             "single run of each solver shows nothing about whether they differ (model/README.md §2.4, \"Both\"). Here the "
             "sweeps' grid values (" + fmt(c.number("throws_per_axis"), 3) + " per sweep, evenly spaced) are thrown again as an ensemble of " +
             fmt(c.number("members"), 4) + " throws per solver, the speed multiplied by 1 ± ε with ε log-spaced from " +
             fmt(c.number("perturbation_smallest"), 2) + " to " + fmt(c.number("perturbation_largest"), 2) +
             ". " + test_sentence(c));
  const Table& t = c.table("throws");
  const auto& params = c.strings("parameters");
  const Record& verdicts = c.at("verdicts");
  const auto& keys = verdicts.strings("order");
  // Data written before the failures' kinds were stored have no ran-away columns: the failures
  // column then gives the failed members alone.
  const bool kinds = t.has_column("realtime_ran_away") && t.has_column("reference_ran_away");
  MarkdownTable m({"throw", "single runs (real-time / reference)", "real-time mean ± sd", "reference mean ± sd",
                   "difference [" + (c.has_number("comparison_confidence") ? fmt(100 * c.number("comparison_confidence"), 4) : std::string("95")) + " % interval]",
                   kinds ? "failed members (of them ran away): real-time / reference" : "failed members: real-time / reference",
                   "verdict"});
  const auto value = t.column("value"), rs = t.column("realtime_single"), fs = t.column("reference_single"),
             rm = t.column("realtime_mean"), rsd = t.column("realtime_sd"), fm = t.column("reference_mean"),
             fsd = t.column("reference_sd"), d = t.column("difference"), lo = t.column("difference_low"),
             hi = t.column("difference_high"), rf = t.column("realtime_failed"), ff = t.column("reference_failed");
  const std::vector<double> ra = kinds ? t.column("realtime_ran_away") : std::vector<double>(),
                            fa = kinds ? t.column("reference_ran_away") : std::vector<double>();
  for (std::size_t i = 0; i < t.rows(); ++i) {
    const auto failures = [&](const std::vector<double>& failed, const std::vector<double>& away) {
      return fmt(failed[i], 4) + (kinds ? " (" + fmt(away[i], 4) + ")" : std::string());
    };
    m.row({axis_name(params[i]) + " = " + fmt(value[i], 4), count_or_failed(rs[i]) + " / " + count_or_failed(fs[i]),
           fmt_or_dash(rm[i]) + " ± " + fmt_or_dash(rsd[i], 2), fmt_or_dash(fm[i]) + " ± " + fmt_or_dash(fsd[i], 2),
           fmt_or_dash(d[i]) + " [" + fmt_or_dash(lo[i]) + ", " + fmt_or_dash(hi[i]) + "]",
           failures(rf, ra) + " / " + failures(ff, fa), "**" + verdicts.at(keys[i]).text("verdict") + "**"});
  }
  w.table(m);
  w.text("Of " + fmt(c.number("sampled"), 4) + " sampled throws the single runs agree on " + fmt(c.number("single_agree"), 4) +
         "; on the ensembles a difference is established on " + fmt(c.number("different"), 4) + ", none is established on " +
         fmt(c.number("not_established"), 4) + ", and both ensembles give one and the same count on " +
         fmt(c.number("same"), 4) +
         (c.has_number("undecided_failed") && c.number("undecided_failed") > 0
              ? "; on " + fmt(c.number("undecided_failed"), 4) +
                    " nothing is decided because runs of an ensemble failed (a failed run has no count, and the runs "
                    "that fail are not a random sample of the ensemble, so the survivors' means are not the ensemble's)."
              : ".") +
         ran_away_tally(c));  // also where too few members ran to compare at all ("not measured")
  w.subheading("Reasons");
  for (std::size_t i = 0; i < keys.size(); ++i) w.verdict(axis_name(params[i]) + " = " + fmt(value[i], 4), verdicts.at(keys[i]));
  w.end_list();
  return w.finish();
}

}  // namespace stoneskip
