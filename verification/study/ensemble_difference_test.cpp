// Welch's interval and the perturbation ensemble of verification/study/ensemble_difference.hpp.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "verification/study/ensemble_difference.hpp"

using namespace stoneskip;

BOOST_AUTO_TEST_SUITE(ensemble_difference)

BOOST_AUTO_TEST_CASE(welch_reproduces_the_published_example) {
  // Oracle: the worked example of Welch's t-test (two samples of 15, unequal variances; e.g. the
  // Wikipedia article's first example): t = −2.46, ν = 25.0 (to the digits printed there), p =
  // 0.021, so the 95 % interval excludes 0. Tolerances: the printed digits.
  const std::vector<double> a{27.5, 21.0, 19.0, 23.6, 17.0, 17.9, 16.9, 20.1, 21.9, 22.6, 23.1, 19.6, 19.0, 21.7, 21.4};
  const std::vector<double> b{27.1, 22.0, 20.8, 23.4, 23.4, 23.5, 25.8, 22.0, 24.8, 20.2, 21.9, 22.1, 22.9, 20.5, 24.4};
  const MeanDifference d = welch_difference(a, b);
  BOOST_REQUIRE(d.valid);
  BOOST_TEST(std::abs(d.difference / d.standard_error - (-2.46)) <= 0.005);
  BOOST_TEST(std::abs(d.dof - 25.0) <= 0.05);
  BOOST_TEST(d.established());
  BOOST_TEST(d.high < 0.0);
}

BOOST_AUTO_TEST_CASE(ensembles_without_spread_give_the_difference_itself) {
  // Oracle: definition — counts that never change under the perturbation compare exactly.
  const MeanDifference same = welch_difference({8, 8, 8}, {8, 8, 8});
  BOOST_TEST(!same.established());
  BOOST_TEST(same.low == 0.0);
  // Without spread the interval is the difference itself, and the exact permutation test decides:
  // {9, 9} against {8, 8, 8} puts both 9s in the first ensemble in 1 of C(5, 2) = 10 relabellings
  // (and no other relabelling differs as much), p = 0.1 > 0.05: not established (it was, on the
  // zero-width interval). Eight against eight: p = 2 / C(16, 8) = 2/12870 (both extremes).
  const MeanDifference other = welch_difference({9, 9}, {8, 8, 8});
  BOOST_TEST(other.low == 1.0);
  BOOST_TEST(std::abs(other.exact_p - 0.1) <= 1e-12);
  BOOST_TEST(!other.established());
  const MeanDifference eight = welch_difference(std::vector<double>(8, 9.0), std::vector<double>(8, 8.0));
  BOOST_TEST(std::abs(eight.exact_p - 2.0 / 12870) <= 1e-15);
  BOOST_TEST(eight.established());
  BOOST_TEST(std::isnan(same.exact_p));  // no difference: nothing to test
  BOOST_TEST(!welch_difference({8}, {8, 9}).valid);  // one member has no spread to estimate
}

BOOST_AUTO_TEST_CASE(overlapping_counts_establish_nothing) {
  // Oracle: two draws of the same spread of counts (8, 10, 10, 7, 12 — the paper throw's counts
  // under perturbations of 1e-9 … 1e-4) differ by one member; their interval must contain 0.
  const MeanDifference d = welch_difference({8, 10, 10, 7, 12}, {8, 10, 11, 7, 12});
  BOOST_TEST(d.valid);
  BOOST_TEST(!d.established());
}

BOOST_AUTO_TEST_CASE(the_paired_interval_is_student_s_on_the_differences) {
  // Oracle: Student's (1908) sleep data, the classic paired example (extra hours of sleep under
  // two drugs, 10 patients): mean difference −1.58, t = −4.062, ν = 9, 95 % interval
  // [−2.4599, −0.7001] (as R's t.test(paired = TRUE) prints it). Tolerances: the printed digits.
  const std::vector<double> a{0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0};
  const std::vector<double> b{1.9, 0.8, 1.1, 0.1, -0.1, 4.4, 5.5, 1.6, 4.6, 3.4};
  const MeanDifference d = paired_difference(a, b);
  BOOST_REQUIRE(d.valid);
  BOOST_TEST(std::abs(d.difference - (-1.58)) <= 1e-12);
  BOOST_TEST(std::abs(d.difference / d.standard_error - (-4.062)) <= 0.0005);
  BOOST_TEST(d.dof == 9.0);
  BOOST_TEST(std::abs(d.low - (-2.4599)) <= 0.00005);
  BOOST_TEST(std::abs(d.high - (-0.7001)) <= 0.00005);
  // The same samples unpaired: Welch's interval is wider and holds 0 (t = −1.861): pairing is
  // what shows the difference.
  BOOST_TEST(!welch_difference(a, b).established());
  // Pairs that differ by one and the same count: the interval is that count.
  // Decided by the exact sign-flip test: all 3 differences of one sign has p = 2/2³ = 0.25 under
  // the null, not established; 6 pairs, 2/2⁶ = 0.03125, established.
  const MeanDifference shift = paired_difference({9, 10, 12}, {8, 9, 11});
  BOOST_TEST(shift.low == 1.0);
  BOOST_TEST(shift.high == 1.0);
  BOOST_TEST(shift.exact_p == 0.25);
  BOOST_TEST(!shift.established());
  BOOST_TEST(paired_difference({9, 10, 12, 9, 10, 12}, {8, 9, 11, 8, 9, 11}).established());
  // At 99 % (a family's level): the same 6 pairs' p = 0.031 no longer establishes it, and the
  // sleep pairs' interval widens by t_{0.995, 9} = 3.2498 (a t table's 4 decimals) standard errors.
  BOOST_TEST(!paired_difference({9, 10, 12, 9, 10, 12}, {8, 9, 11, 8, 9, 11}, 0.99).established());
  const MeanDifference d99 = paired_difference(a, b, 0.99);
  BOOST_TEST(std::abs(d99.low - (d.difference - 3.2498 * d.standard_error)) <= 0.00005 * d.standard_error + 1e-12);
  BOOST_TEST(std::abs(d99.high - (d.difference + 3.2498 * d.standard_error)) <= 0.00005 * d.standard_error + 1e-12);
  BOOST_TEST(d99.alpha == 0.01, boost::test_tools::tolerance(1e-12));
  // Bonferroni's level for each of m comparisons: 1 − 0.05/m; a single comparison, or none, keeps 95 %.
  BOOST_TEST(bonferroni_confidence(0.95, 4) == 0.9875, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(bonferroni_confidence(0.95, 1) == 0.95, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(bonferroni_confidence(0.95, 0) == 0.95, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(!paired_difference({8, 9}, {8}).valid);  // members must pair up
}

BOOST_AUTO_TEST_CASE(perturbations_are_log_spaced_of_both_signs) {
  // Oracle: the definition, 1 ± 10^-9, …, 1 ± 10^-4 for 12 members.
  const std::vector<double> f = perturbation_factors(12, 1e-9, 1e-4);
  BOOST_REQUIRE_EQUAL(f.size(), 12u);
  BOOST_TEST(std::abs(f[0] - (1 + 1e-9)) <= 1e-15);
  BOOST_TEST(std::abs(f[1] - (1 - 1e-9)) <= 1e-15);
  BOOST_TEST(std::abs(f[10] - (1 + 1e-4)) <= 1e-15);
  BOOST_TEST(std::abs(f[3] - (1 - 1e-8)) <= 1e-15);
}

BOOST_AUTO_TEST_SUITE_END()
