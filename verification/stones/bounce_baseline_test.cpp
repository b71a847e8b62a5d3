// The regression rules of verification/stones/bounce_baseline.hpp on baselines built here, whose
// verdicts are known by construction: ensembles without spread compared exactly, ensembles with
// spread by Welch's interval held to 95 % over the sensitive values (Bonferroni), thresholds in a
// cell with a sensitive end tolerated, and the count just past a change not held run against run.
#include <boost/test/unit_test.hpp>

#include <string>
#include <vector>

#include "verification/stones/bounce_baseline.hpp"
#include "verification/study/ensemble_difference.hpp"

namespace stoneskip {
namespace {

// A grid 0, 10, 20, 30 (spin) with counts and ensembles of 8, no thresholds.
struct Pair {
  BounceBaseline stored;
  BounceSweepResult now;
  Pair(std::vector<int> counts, std::vector<std::vector<int>> stored_ens, std::vector<int> now_counts,
       std::vector<std::vector<int>> now_ens) {
    stored.name = "test";
    stored.values = {0, 10, 20, 30};
    stored.has_result = true;
    stored.counts = std::move(counts);
    stored.ensemble_members = 8;
    stored.ensembles = std::move(stored_ens);
    stored.threshold_tolerance = 0.25;
    stored.compare_tolerance = 0.5;
    now.counts = std::move(now_counts);
    now.failures.assign(4, "");
    now.ensembles = std::move(now_ens);
  }
};

const std::vector<int> kOne(8, 1), kTwo(8, 2), kThree(8, 3);
const std::vector<int> kMixed{1, 2, 1, 2, 1, 2, 1, 2};   // mean 1.5, sd 0.535
const std::vector<int> kMixed2{2, 1, 2, 1, 2, 1, 2, 1};  // the same values, another order
const std::vector<int> kHigh{5, 6, 5, 6, 5, 6, 5, 6};    // mean 5.5, sd 0.535

bool mentions(const std::vector<std::string>& lines, const std::string& what) {
  for (const auto& l : lines)
    if (l.find(what) != std::string::npos) return true;
  return false;
}

BOOST_AUTO_TEST_SUITE(bounce_baseline_)

BOOST_AUTO_TEST_CASE(a_robust_count_that_changes_is_a_regression) {
  // Oracle: ensembles without spread on both sides; their difference is exact (1 → 2).
  Pair p({1, 1, 2, 3}, {kOne, kOne, kTwo, kThree}, {1, 2, 2, 3}, {kOne, kTwo, kTwo, kThree});
  const BaselineComparison c = compare_with_baseline(p.stored, p.now);
  BOOST_TEST(!c.passed);
  BOOST_TEST(c.sensitive_points == 0);
  BOOST_TEST(mentions(c.regressions, "count at spin_rev_s = 10 rev/s: stored 1, now 2"));
}

BOOST_AUTO_TEST_CASE(a_sensitive_count_is_judged_on_its_ensembles) {
  // Same distribution, other single count: tolerated (the interval contains 0).
  Pair same({1, 1, 2, 3}, {kOne, kMixed, kTwo, kThree}, {1, 2, 2, 3}, {kOne, kMixed2, kTwo, kThree});
  BaselineComparison c = compare_with_baseline(same.stored, same.now);
  BOOST_TEST(c.passed);
  BOOST_TEST(c.sensitive_points == 1);
  BOOST_TEST(mentions(c.tolerated, "the count is sensitive here"));
  // Shifted by 4 with the same spread: Welch's interval 4 ± t·0.267 (ν = 14) excludes 0 at any
  // Bonferroni level here (one sensitive value: 95 %).
  Pair shifted({1, 1, 2, 3}, {kOne, kMixed, kTwo, kThree}, {1, 5, 2, 3}, {kOne, kHigh, kTwo, kThree});
  c = compare_with_baseline(shifted.stored, shifted.now);
  BOOST_TEST(!c.passed);
  BOOST_TEST(mentions(c.regressions, "stored 1, now 5"));
  const MeanDifference d = welch_difference({5, 6, 5, 6, 5, 6, 5, 6}, {1, 2, 1, 2, 1, 2, 1, 2});
  BOOST_TEST(d.low > 3.0);
}

BOOST_AUTO_TEST_CASE(the_family_of_sensitive_values_widens_each_interval) {
  // Oracle: Bonferroni. Two ensembles whose 95 % interval just excludes 0 but whose 1 − 0.05/m
  // interval does not: m = 1 establishes a difference, m = 3 (three sensitive values) does not.
  // a: mean 1.5, sd 0.535; b: 2 throughout. Difference 0.5, se 0.189, ν = 7: t = 2.36 at 95 %
  // (half-width 0.447), about 3.1 at 98.3 % (0.59).
  const std::vector<double> a{1, 2, 1, 2, 1, 2, 1, 2}, b{2, 2, 2, 2, 2, 2, 2, 2};
  const MeanDifference at95 = welch_difference(b, a), wide = welch_difference(b, a, 1 - 0.05 / 3);
  BOOST_REQUIRE(at95.established());
  BOOST_REQUIRE(!wide.established());
  auto ints = [](const std::vector<double>& v) { return std::vector<int>(v.begin(), v.end()); };
  Pair one({1, 1, 2, 3}, {kOne, ints(a), kTwo, kThree}, {1, 2, 2, 3}, {kOne, ints(b), kTwo, kThree});
  BOOST_TEST(!compare_with_baseline(one.stored, one.now).passed);
  Pair three({1, 1, 1, 1}, {kOne, ints(a), kMixed, kMixed}, {1, 2, 1, 1}, {kOne, ints(b), kMixed2, kMixed2});
  const BaselineComparison c = compare_with_baseline(three.stored, three.now);
  BOOST_TEST(c.sensitive_points == 3);
  BOOST_TEST(c.passed);
}

BOOST_AUTO_TEST_CASE(thresholds_in_a_sensitive_cell_are_tolerated_elsewhere_held) {
  // Stored: changes 1 → 2 in [10, 20] (robust ends) and 2 → 3 in [20, 30] (a sensitive end at 30).
  Pair p({1, 1, 2, 3}, {kOne, kOne, kTwo, kMixed}, {1, 1, 2, 3}, {kOne, kOne, kTwo, kMixed2});
  p.stored.thresholds = {{14.0, 14.25, 1, 2}, {25.0, 25.25, 2, 3}};
  p.now.thresholds = {{17.0, 17.25, 1, 2}, {28.0, 28.25, 2, 3}};  // both moved by 3 (tolerance 0.5)
  const BaselineComparison c = compare_with_baseline(p.stored, p.now);
  BOOST_TEST(!c.passed);
  BOOST_TEST(mentions(c.regressions, "threshold 1 -> 2 bounces stored at spin_rev_s = 14.125"));
  BOOST_TEST(!mentions(c.regressions, "threshold 2 -> 3"));
  BOOST_TEST(mentions(c.tolerated, "threshold 2 -> 3 bounces stored at spin_rev_s = 25.125"));
}

BOOST_AUTO_TEST_CASE(the_count_past_a_change_is_not_held_run_against_run_with_ensembles) {
  // The same change (1 → ...) at the same place, another count past it: tolerated with ensembles,
  // a regression without (single runs, the rule before ensembles).
  Pair p({1, 1, 2, 3}, {kOne, kOne, kTwo, kThree}, {1, 1, 2, 3}, {kOne, kOne, kTwo, kThree});
  p.stored.thresholds = {{14.0, 14.25, 1, 6}};
  p.now.thresholds = {{14.25, 14.5, 1, 4}};
  BaselineComparison c = compare_with_baseline(p.stored, p.now);
  BOOST_TEST(c.passed);
  BOOST_TEST(mentions(c.tolerated, "the count just past a change is one run"));
  p.stored.ensemble_members = 0;
  p.stored.ensembles.clear();
  p.now.ensembles.clear();
  c = compare_with_baseline(p.stored, p.now);
  BOOST_TEST(!c.passed);
}

BOOST_AUTO_TEST_CASE(on_a_robust_value_the_single_count_and_the_failures_are_held_too) {
  // The stored ensemble at 10 had no spread: a changed single count alone, or a new solver failure
  // of the grid throw, is a regression though the ensembles agree (it was tolerated as "sensitive").
  Pair single({1, 1, 2, 3}, {kOne, kOne, kTwo, kThree}, {1, 2, 2, 3}, {kOne, kOne, kTwo, kThree});
  BaselineComparison c = compare_with_baseline(single.stored, single.now);
  BOOST_TEST(!c.passed);
  BOOST_TEST(mentions(c.regressions, "count at spin_rev_s = 10 rev/s: stored 1, now 2"));
  Pair failed({1, 1, 2, 3}, {kOne, kOne, kTwo, kThree}, {1, -1, 2, 3}, {kOne, kOne, kTwo, kThree});
  failed.now.failures[1] = "step size collapsed";
  c = compare_with_baseline(failed.stored, failed.now);
  BOOST_TEST(mentions(c.regressions, "now -1 (solver failed: step size collapsed)"));
  // Nudged throws that fail where none did: 2 of 8 now.
  std::vector<int> two_failed = kThree;
  two_failed[0] = two_failed[5] = -1;
  Pair members({1, 1, 2, 3}, {kOne, kOne, kTwo, kThree}, {1, 1, 2, 3}, {kOne, kOne, kTwo, two_failed});
  c = compare_with_baseline(members.stored, members.now);
  BOOST_TEST(mentions(c.regressions, "2 of its 8 nudged throws failed now, 0 stored"));
  // Sensitivity is the stored run's: noise that appears only now does not loosen the value.
  Pair noisy({1, 1, 2, 3}, {kOne, kOne, kTwo, kThree}, {1, 2, 2, 3}, {kOne, kMixed, kTwo, kThree});
  c = compare_with_baseline(noisy.stored, noisy.now);
  BOOST_TEST(c.sensitive_points == 0);
  BOOST_TEST(mentions(c.regressions, "stored 1, now 2"));
}

BOOST_AUTO_TEST_CASE(a_lone_changes_count_past_it_is_held) {
  // In [10, 20] the grid goes 1 → 2 and the stored change is 1 → 2: a lone change, so 1 → 3 now
  // is a regression (the loosening is for cells holding more changes, or with a sensitive end).
  Pair p({1, 1, 2, 3}, {kOne, kOne, kTwo, kThree}, {1, 1, 2, 3}, {kOne, kOne, kTwo, kThree});
  p.stored.thresholds = {{14.0, 14.25, 1, 2}};
  p.now.thresholds = {{14.25, 14.5, 1, 3}};
  const BaselineComparison c = compare_with_baseline(p.stored, p.now);
  BOOST_TEST(!c.passed);
}

BOOST_AUTO_TEST_CASE(near_a_threshold_only_its_own_counts_are_tolerated) {
  // Stored: 1 -> 2 at 9.9 (within the 0.5 compare tolerance of the grid value 10, whose count is 2).
  // The threshold moving past 10 makes 10's count 1, every member agreeing: tolerated. A count of 5
  // there, every member agreeing, is no threshold's doing: a regression (it was tolerated as
  // "within 0.5 of a stored threshold" until December 5). So is a nudged throw that fails now.
  Pair moved({1, 2, 2, 3}, {kOne, kTwo, kTwo, kThree}, {1, 1, 2, 3}, {kOne, kOne, kTwo, kThree});
  moved.stored.thresholds = {{9.8, 10.0, 1, 2}};
  moved.now.thresholds = {{10.0, 10.25, 1, 2}};
  BaselineComparison c = compare_with_baseline(moved.stored, moved.now);
  BOOST_TEST(c.passed);
  BOOST_TEST(mentions(c.tolerated, "stored 2, now 1"));
  const std::vector<int> kFive(8, 5);
  Pair jumped({1, 2, 2, 3}, {kOne, kTwo, kTwo, kThree}, {1, 5, 2, 3}, {kOne, kFive, kTwo, kThree});
  jumped.stored.thresholds = {{9.8, 10.0, 1, 2}};
  jumped.now.thresholds = {{9.8, 10.0, 1, 5}};
  c = compare_with_baseline(jumped.stored, jumped.now);
  BOOST_TEST(!c.passed);
  BOOST_TEST(mentions(c.regressions, "count at spin_rev_s = 10 rev/s: stored 2, now 5"));
  std::vector<int> two_failed = kTwo;
  two_failed[1] = two_failed[6] = -1;
  Pair failing({1, 2, 2, 3}, {kOne, kTwo, kTwo, kThree}, {1, 2, 2, 3}, {kOne, two_failed, kTwo, kThree});
  failing.stored.thresholds = failing.now.thresholds = {{9.8, 10.0, 1, 2}};
  c = compare_with_baseline(failing.stored, failing.now);
  BOOST_TEST(mentions(c.regressions, "2 of its 8 nudged throws failed now, 0 stored"));
}

BOOST_AUTO_TEST_CASE(on_a_sensitive_value_failure_rates_that_differ_beyond_chance_are_a_regression) {
  // The sensitive value 20 (stored members 1, 2, 1, 2, ...): its one sensitive value makes the
  // family's level 95 %. Fisher's exact test (two-sided, computed apart in Python from the
  // hypergeometric law): 6 of 8 failed against 0 of 8, p = 0.0070: a regression (tolerated as
  // "sensitive" until December 5); 1 of 8 against 0 of 8, p = 1: tolerated.
  std::vector<int> six_failed{1, -1, -1, -1, 2, -1, -1, -1};
  Pair many({1, 1, 1, 3}, {kOne, kOne, kMixed, kThree}, {1, 1, 1, 3}, {kOne, kOne, six_failed, kThree});
  BaselineComparison c = compare_with_baseline(many.stored, many.now);
  BOOST_TEST(c.sensitive_points == 1);
  BOOST_TEST(!c.passed);
  BOOST_TEST(mentions(c.regressions, "6 of its 8 nudged throws failed now, 0 stored"));
  std::vector<int> one_failed = kMixed2;
  one_failed[3] = -1;
  Pair one({1, 1, 1, 3}, {kOne, kOne, kMixed, kThree}, {1, 1, 1, 3}, {kOne, kOne, one_failed, kThree});
  c = compare_with_baseline(one.stored, one.now);
  BOOST_TEST(c.passed);
  BOOST_TEST(mentions(c.tolerated, "1 of its 8 nudged throws failed now, 0 stored"));
  // 6 of 8 against 1 of 8: p = 0.0406 ≤ 0.05, a regression; the Wilson intervals ([0.41, 0.93]
  // and [0.02, 0.47]) overlap, which let it pass until December 6.
  std::vector<int> stored_one_failed = kMixed;
  stored_one_failed[0] = -1;
  Pair six_one({1, 1, 1, 3}, {kOne, kOne, stored_one_failed, kThree}, {1, 1, 1, 3}, {kOne, kOne, six_failed, kThree});
  c = compare_with_baseline(six_one.stored, six_one.now);
  BOOST_TEST(!c.passed);
  BOOST_TEST(mentions(c.regressions, "Fisher's exact test of the failure rates: p = 0.041"));
}

BOOST_AUTO_TEST_CASE(a_single_count_outside_every_member_is_a_regression_even_where_sensitive) {
  // Oracle: by construction: at the sensitive value 20 both ensembles hold 1s and 2s (the same
  // distribution: no difference of means); a single count of 2 among them is tolerated, one of
  // 1000 is no nudge's count and is a regression (it passed as "sensitive").
  Pair ok({1, 1, 1, 3}, {kOne, kOne, kMixed, kThree}, {1, 1, 2, 3}, {kOne, kOne, kMixed2, kThree});
  BOOST_TEST(compare_with_baseline(ok.stored, ok.now).passed);
  Pair absurd({1, 1, 1000, 3}, {kOne, kOne, kMixed, kThree}, {1, 1, 2, 3}, {kOne, kOne, kMixed2, kThree});
  const BaselineComparison c = compare_with_baseline(absurd.stored, absurd.now);
  BOOST_TEST(!c.passed);
  BOOST_TEST(mentions(c.regressions, "a single count outside every member's range, 1–2"));
  // And the check's coarseness is said for the sensitive value: t(14) at 97.5 % = 2.1448 times
  // sd 0.5345 √(2/8) = 0.573 bounces.
  BOOST_REQUIRE(c.resolution.size() == 1u);
  BOOST_TEST(c.resolution[0].find("below about 0.57 ") != std::string::npos, c.resolution[0]);
}

BOOST_AUTO_TEST_CASE(constant_ensembles_say_the_exact_test_decided) {
  // Oracle: the robust value 10 went from eight 1s to eight 2s: no spread, so the exact
  // permutation test decides (p = 2 / C(16, 8) = 1.6e-4), and the line says so, not "Welch".
  Pair p({1, 1, 2, 3}, {kOne, kOne, kTwo, kThree}, {1, 2, 2, 3}, {kOne, kTwo, kTwo, kThree});
  const BaselineComparison c = compare_with_baseline(p.stored, p.now);
  BOOST_TEST(mentions(c.regressions, "exact permutation test p = 0.00016"));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
