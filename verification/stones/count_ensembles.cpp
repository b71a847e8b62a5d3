#include "verification/stones/count_ensembles.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

#include "verification/study/verdict_rules.hpp"

namespace stoneskip {

bool CountEnsembleOptions::valid(std::string* why) const {
  auto fail = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (members < 2 || members % 2 != 0 || members > 1000) return fail("ensemble members must be even, in [2, 1000]");
  if (!(perturbation_smallest > 0) || !(perturbation_largest >= perturbation_smallest) || !(perturbation_largest < 1))
    return fail("ensemble perturbations must satisfy 0 < smallest <= largest < 1");
  if (throws_per_axis < 0 || throws_per_axis > 1000) return fail("ensemble throws_per_axis must be in [0, 1000]");
  if (!(family_confidence > 0 && family_confidence < 1)) return fail("ensemble family_confidence must be in (0, 1)");
  return true;
}

double comparison_confidence(const CountEnsembleOptions& o, std::size_t m) {
  return bonferroni_confidence(o.family_confidence, m);
}

std::vector<double> sampled_values(const std::vector<double>& grid, int count) {
  std::vector<double> out;
  const int n = static_cast<int>(grid.size());
  if (n == 0 || count <= 0) return out;
  if (count >= n) return grid;
  if (count == 1) return {grid[n / 2]};
  for (int k = 0; k < count; ++k) {
    const int i = static_cast<int>(std::lround(static_cast<double>(k) * (n - 1) / (count - 1)));
    if (out.empty() || grid[i] != out.back()) out.push_back(grid[i]);
  }
  return out;
}

namespace {

// The members that ran (a failed solve has no count).
std::vector<double> ran(const std::vector<double>& counts, int& failed) {
  std::vector<double> out;
  failed = 0;
  for (double c : counts) {
    if (c < 0) ++failed;
    else out.push_back(c);
  }
  return out;
}

}  // namespace

MeanDifference member_difference(const CountEnsembleThrow& t, double confidence) {
  int failed_a = 0, failed_b = 0;
  return welch_difference(ran(t.realtime, failed_a), ran(t.reference, failed_b), confidence);
}

std::vector<CountEnsembleThrow> run_count_ensembles(const ThrowProblem& base, const SolverChoice& realtime,
                                                   const SolverChoice& reference,
                                                   const std::vector<std::pair<SweepParameter, std::vector<double>>>& axes,
                                                   const CountEnsembleOptions& o, const ParallelOptions& parallel) {
  std::string why;
  if (!o.valid(&why)) throw std::invalid_argument("count ensembles: " + why);
  const ThrowProblem conv = with_convention(base, o.convention);
  const std::vector<double> factors = perturbation_factors(o.members, o.perturbation_smallest, o.perturbation_largest);
  std::vector<CountEnsembleThrow> out;
  std::vector<ThrowProblem> problems;
  for (const auto& [param, grid] : axes)
    for (double v : sampled_values(grid, o.throws_per_axis)) {
      CountEnsembleThrow t;
      t.parameter = param;
      t.value = v;
      t.factors = factors;
      t.realtime.assign(factors.size(), -1);
      t.reference.assign(factors.size(), -1);
      t.realtime_away.assign(factors.size(), 0);
      t.reference_away.assign(factors.size(), 0);
      out.push_back(t);
      ThrowParameters tp = conv.parameters;
      parameter_of(tp, param) = v;
      problems.push_back(with_parameters(conv, tp));
    }
  // Jobs: per throw, the single runs and each member, each solver.
  std::vector<std::function<void()>> jobs;
  for (std::size_t i = 0; i < out.size(); ++i) {
    CountEnsembleThrow& t = out[i];
    const ThrowProblem& p = problems[i];
    jobs.push_back([&t, &p, &realtime] { t.realtime_single = sweep_bounce_count(p, realtime); });
    jobs.push_back([&t, &p, &reference] { t.reference_single = sweep_bounce_count(p, reference); });
    for (std::size_t k = 0; k < factors.size(); ++k) {
      ThrowParameters tp = p.parameters;
      tp.speed_m_s *= factors[k];  // the speed, relatively; direction, attitude and spin kept
      const ThrowProblem q = with_parameters(p, tp);
      jobs.push_back([&t, q, k, &realtime] {
        const SweepCount c = sweep_count(q, realtime);
        t.realtime[k] = c.bounces;
        t.realtime_away[k] = c.ran_away;
      });
      jobs.push_back([&t, q, k, &reference] {
        const SweepCount c = sweep_count(q, reference);
        t.reference[k] = c.bounces;
        t.reference_away[k] = c.ran_away;
      });
    }
  }
  run_jobs(jobs, parallel);
  const double level = comparison_confidence(o, out.size());
  for (CountEnsembleThrow& t : out) {
    ran(t.realtime, t.realtime_failed);
    ran(t.reference, t.reference_failed);
    t.difference = member_difference(t, level);
    t.realtime_ran_away = static_cast<int>(std::count(t.realtime_away.begin(), t.realtime_away.end(), 1));
    t.reference_ran_away = static_cast<int>(std::count(t.reference_away.begin(), t.reference_away.end(), 1));
  }
  return out;
}

Record count_ensembles_findings(const std::vector<CountEnsembleThrow>& throws, const CountEnsembleOptions& o) {
  Record r;
  r.set("convention", std::string(to_string(o.convention)));
  r.set("members", o.members);
  r.set("perturbation_smallest", o.perturbation_smallest);
  r.set("perturbation_largest", o.perturbation_largest);
  r.set("throws_per_axis", o.throws_per_axis);
  const double level = comparison_confidence(o, throws.size());
  r.set("family_confidence", o.family_confidence);
  r.set("comparison_confidence", level);
  Table t{{"value", "realtime_single", "reference_single", "realtime_mean", "realtime_sd", "reference_mean", "reference_sd",
           "difference", "difference_low", "difference_high", "realtime_failed", "reference_failed", "single_agree",
           "established", "realtime_ran_away", "reference_ran_away"},
          {}};
  std::vector<std::string> params, keys;
  int single_agree = 0, established = 0, none_established = 0, same = 0, undecided = 0;
  int failed_runs = 0, ran_away_runs = 0;  // over every ensemble's members
  for (std::size_t i = 0; i < throws.size(); ++i) {
    const CountEnsembleThrow& c = throws[i];
    MeanDifference d = member_difference(c, level);  // from the members' counts, at the family's level
    if (!d.valid) {  // fewer than 2 members of a solver ran: no means to compare
      const double nan = std::nan("");
      d.mean_a = d.mean_b = d.sd_a = d.sd_b = d.difference = d.low = d.high = nan;
    }
    const bool agree = c.realtime_single >= 0 && c.realtime_single == c.reference_single;
    single_agree += agree ? 1 : 0;
    t.add_row({c.value, double(c.realtime_single), double(c.reference_single), d.mean_a, d.sd_a, d.mean_b, d.sd_b,
               d.difference, d.low, d.high, double(c.realtime_failed), double(c.reference_failed), agree ? 1.0 : 0.0,
               d.established() ? 1.0 : 0.0, double(c.realtime_ran_away), double(c.reference_ran_away)});
    failed_runs += c.realtime_failed + c.reference_failed;
    ran_away_runs += c.realtime_ran_away + c.reference_ran_away;
    params.push_back(to_string(c.parameter));
    char key[64];
    std::snprintf(key, sizeof key, "throw_%zu", i + 1);
    keys.push_back(key);
    Record in;
    in.set("valid", d.valid);
    in.set("difference_low", d.low);
    in.set("difference_high", d.high);
    in.set("count_spread", d.sd_a + d.sd_b);
    in.set("exact_p", d.exact_p);  // no spread: the exact permutation test (ensemble_difference.hpp)
    in.set("alpha", d.alpha);
    in.set("realtime_failed", c.realtime_failed);
    in.set("reference_failed", c.reference_failed);
    // Of the failed members, how many ran away (their energy over a thousandfold: the paper
    // convention's printed forces, spec §1.6) and how many failed otherwise.
    char away[200] = "";
    if (c.realtime_ran_away + c.reference_ran_away > 0)
      std::snprintf(away, sizeof away, ", of which %d and %d ran away (energy over a thousand times the release value)",
                    c.realtime_ran_away, c.reference_ran_away);
    char reason[900];
    std::snprintf(reason, sizeof reason,
                  "%s = %.4g %s: over %zu throws each (speed × 1 ± 1e%.3g … 1e%.3g) real-time %.3g ± %.2g, reference "
                  "%.3g ± %.2g bounces (mean ± sd; %d and %d failed%s); difference %.3g, %.4g %% interval [%.3g, %.3g] "
                  "(Welch; Bonferroni over the %zu sampled throws); the single runs gave %d and %d",
                  to_string(c.parameter), c.value, unit_of(c.parameter), c.factors.size(),
                  std::log10(o.perturbation_smallest), std::log10(o.perturbation_largest), d.mean_a, d.sd_a, d.mean_b,
                  d.sd_b, c.realtime_failed, c.reference_failed, away, d.difference, 100 * level, d.low, d.high,
                  throws.size(), c.realtime_single, c.reference_single);
    const Record& v = decide_verdict(r.child("verdicts"), key, "ensemble_bounce_agreement", in, reason);
    const std::string& phrase = v.text("verdict");
    if (phrase == "different bounce counts") ++established;
    else if (phrase == "no difference established") ++none_established;
    else if (phrase == "same bounce count") ++same;
    else if (phrase == "not decided: runs failed") ++undecided;
  }
  r.set_table("throws", t);
  r.set_strings("parameters", params);
  r.child("verdicts").set_strings("order", keys);
  r.set("sampled", throws.size());
  r.set("single_agree", single_agree);
  r.set("different", established);
  r.set("not_established", none_established);
  r.set("same", same);
  r.set("undecided_failed", undecided);
  r.set("failed_runs", failed_runs);
  r.set("ran_away_runs", ran_away_runs);
  return r;
}

}  // namespace stoneskip
