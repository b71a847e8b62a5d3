#include "verification/convergence/order_fit.hpp"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <random>

namespace stoneskip {

// Lets Boost.Test print the enum in a failure message.
inline std::ostream& operator<<(std::ostream& o, OrderVerdict k) { return o << to_string(k); }

namespace {

BOOST_AUTO_TEST_SUITE(order_fit_)

BOOST_AUTO_TEST_CASE(exact_power_law_is_recovered) {
  // Oracle: e = 3 h² exactly; the fit's slope and constant are 2 and 3 to round-off of the
  // logarithms (a few ulps times the condition of the 4-point regression).
  constexpr double kRoundoff = 1e-12;
  std::vector<double> h{0.1, 0.05, 0.025, 0.0125}, e;
  for (double x : h) e.push_back(3 * x * x);
  OrderFit f = fit_order(h, e);
  BOOST_TEST(f.valid);
  BOOST_TEST(std::abs(f.order - 2) <= kRoundoff);
  BOOST_TEST(std::abs(f.constant - 3) <= 1e-11);
  BOOST_TEST(std::abs(f.order_high - f.order_low) <= kRoundoff);
  BOOST_TEST(f.pairwise.size() == 3u);
  for (double p : f.pairwise) BOOST_TEST(std::abs(p - 2) <= kRoundoff);
  BOOST_TEST(judge_order(f).verdict == OrderVerdict::converges_at_expected_order);
}

BOOST_AUTO_TEST_CASE(first_order_data_is_not_judged_second_order) {
  // Oracle: e = h exactly has slope 1 with a zero-width interval; a judgement expecting 2 ± 0.1
  // must say "other order": the interval excludes both 2 and no convergence.
  std::vector<double> h{0.1, 0.05, 0.025}, e{0.1, 0.05, 0.025};
  OrderFit f = fit_order(h, e);
  BOOST_TEST(std::abs(f.order - 1) <= 1e-12);
  BOOST_TEST(judge_order(f).verdict == OrderVerdict::converges_at_other_order);
}

BOOST_AUTO_TEST_CASE(error_growing_under_refinement_does_not_converge) {
  // Oracle: e = 1/h has slope −1 < 0: the error grows as h shrinks, and the interval (zero width)
  // lies entirely below the minimum slope.
  std::vector<double> h{0.1, 0.05, 0.025}, e{10, 20, 40};
  OrderFit f = fit_order(h, e);
  BOOST_TEST(std::abs(f.order + 1) <= 1e-12);
  BOOST_TEST(judge_order(f).verdict == OrderVerdict::does_not_converge);
}

BOOST_AUTO_TEST_CASE(a_flat_error_with_a_narrow_interval_does_not_converge) {
  // Oracle: e = 0.01 (1 ± 1 %) over a factor 8 in h: slope ≈ 0 with an interval well inside
  // (−0.25, 0.25): the data show that the error does not fall.
  std::vector<double> h{0.1, 0.05, 0.025, 0.0125}, e{0.0101, 0.0099, 0.0101, 0.0099};
  OrderFit f = fit_order(h, e);
  BOOST_TEST(f.order_high <= 0.25);
  BOOST_TEST(judge_order(f).verdict == OrderVerdict::does_not_converge);
}

BOOST_AUTO_TEST_CASE(too_few_points_give_no_fit) {
  // Oracle: one usable point (the zero error is dropped) cannot define a slope.
  OrderFit f = fit_order({0.1, 0.05}, {0.01, 0.0});
  BOOST_TEST(!f.valid);
  BOOST_TEST(judge_order(f).verdict == OrderVerdict::insufficient_data);
}

BOOST_AUTO_TEST_CASE(two_points_never_establish_an_order) {
  // Oracle: a two-point fit has no residual, hence no confidence interval (its "interval" is the
  // point itself): e = 3 h² at two steps is exactly second order, yet the order is not established.
  OrderFit f = fit_order({0.1, 0.05}, {0.03, 0.0075});
  BOOST_TEST(f.valid);
  BOOST_TEST(std::abs(f.order - 2) <= 1e-12);
  const OrderDecision d = judge_order(f);
  BOOST_TEST(d.verdict == OrderVerdict::insufficient_data);
  BOOST_TEST(d.reason == "only 2 points: a fit needs 3 for a confidence interval");
}

BOOST_AUTO_TEST_CASE(an_interval_too_wide_to_decide_establishes_nothing) {
  // Oracle: the intervals, computed by hand from the Student t of 2 degrees of freedom (4.303):
  // p = 1.80 [0.84, 2.76] holds the expected 2 and much else; p = 0.297 [−1.44, 2.04] holds 2 and
  // no convergence; p = 0.312 [−0.87, 1.49] excludes 2 but holds no convergence. None decides.
  const std::vector<double> h{0.1, 0.05, 0.025, 0.0125};
  for (const std::vector<double>& e : {std::vector<double>{1e-2, 2.0e-3, 1.1e-3, 1.9e-4},
                                       std::vector<double>{1e-2, 1.6e-2, 4e-3, 8e-3},
                                       std::vector<double>{1e-2, 5e-3, 9e-3, 4e-3}}) {
    const OrderFit f = fit_order(h, e);
    const OrderDecision d = judge_order(f, OrderJudgement{2, 0.2, 0.25});
    BOOST_TEST(d.verdict == OrderVerdict::order_not_established, f.brief() << ": " << d.reason);
  }
}

BOOST_AUTO_TEST_CASE(another_order_needs_an_interval_that_excludes_both_the_expected_order_and_zero) {
  // Oracle: p = 1.58 [1.28, 1.88] (by hand, as above) lies wholly below 2 − 0.1 and above 0.25.
  const OrderFit f = fit_order({0.1, 0.05, 0.025, 0.0125}, {1e-2, 4e-3, 1.1e-3, 4e-4});
  const OrderDecision d = judge_order(f);
  BOOST_TEST(d.verdict == OrderVerdict::converges_at_other_order, f.brief());
  BOOST_TEST(d.reason == "p = 1.58 [1.28, 1.88] excludes the expected 2");
}

BOOST_AUTO_TEST_CASE(an_error_that_grows_at_some_refinement_claims_no_order) {
  // Oracle: errors built from the stones report's rk4 row "state after an interval holding the
  // whole first contact", whose pairwise orders were -0.0243, 2.15, 2, 0.167, -0.482, 4.11, -0.833
  // and fit 1.13 [0.728, 1.52]: an interval that excludes both 4 and 0, which the interval alone
  // called "converges, not at the expected order" although the error grows at 3 of 7 halvings.
  const std::vector<double> pairwise{-0.0243, 2.15, 2, 0.167, -0.482, 4.11, -0.833};
  std::vector<double> h{0.01}, e{1e-3};
  for (double p : pairwise) {
    h.push_back(h.back() / 2);
    e.push_back(e.back() / std::pow(2.0, p));
  }
  const OrderFit f = fit_order(h, e);
  BOOST_TEST(f.order == 1.13, boost::test_tools::tolerance(0.01));  // the report's fit, rounded
  BOOST_TEST(f.order_low > 0.25);
  BOOST_TEST(f.order_high < 3.8);
  OrderJudgement j{4, 0.25, 0.25};
  j.expected_name = "formal";
  const OrderDecision d = judge_order(f, j);
  BOOST_TEST(d.verdict == OrderVerdict::order_not_established, d.reason);
  BOOST_TEST(d.reason.find("does not fall at 3 of 7 refinements") != std::string::npos, d.reason);
  // An interval too wide to decide says so, and why where the data show it: the CVODE tolerance
  // study of the stones report (rtol 1e-6 … 1e-10, bounce-position error against expected 1), whose
  // error stops falling at its last two refinements, p = 0.445 [−0.042, 0.933].
  {
    const std::vector<double> rtol{1e-6, 1e-7, 1e-8, 1e-9, 1e-10}, err{4.979e-05, 4.015e-05, 1.342e-06, 1.367e-06, 1.6e-06};
    OrderJudgement one{1, 0.25, 0.25};
    const OrderDecision w = judge_order(fit_order(rtol, err), one);
    BOOST_TEST(w.verdict == OrderVerdict::order_not_established, w.reason);
    BOOST_TEST(w.reason.find("too wide to decide; the error does not fall at 2 of 4 refinements") != std::string::npos, w.reason);
  }
  // The same series with every halving lowering the error keeps its verdict: only growth vetoes.
  std::vector<double> e2{1e-3};
  for (double p : pairwise) e2.push_back(e2.back() / std::pow(2.0, std::max(p, 0.5)));
  BOOST_TEST(judge_order(fit_order(h, e2), j).verdict == OrderVerdict::converges_at_other_order);
}

BOOST_AUTO_TEST_CASE(an_error_running_onto_a_floor_claims_no_order) {
  // Oracle: e = 3 h² + 3e-5 on h = 0.1/2^k, k = 0…7: second order running onto a floor, pairwise
  // orders 2.00, 1.98, 1.93, 1.76, 1.31, 0.67, 0.23 (computed apart, in Python). A line through it
  // gives p ≈ 1.48 [1.16, 1.80], which excludes 2 and 0 and was called "converges, not at the
  // expected order". The quadratic in log h is significant (F ≈ 58 against F_0.95(1, 5) = 6.61)
  // and its local order runs from about 2.5 to 0.4, far more than the band's width 0.2.
  std::vector<double> h, e;
  for (int k = 0; k < 8; ++k) {
    h.push_back(0.1 / std::pow(2.0, k));
    e.push_back(3 * h.back() * h.back() + 3e-5);
  }
  const OrderFit f = fit_order(h, e);
  BOOST_TEST(f.order == 1.48, boost::test_tools::tolerance(0.01));
  BOOST_TEST(f.shape_tested);
  BOOST_TEST(f.curved);
  BOOST_TEST(f.local_order_coarse - f.local_order_fine > 1.5);
  const OrderDecision d = judge_order(f);
  BOOST_TEST(d.verdict == OrderVerdict::order_not_established, d.reason);
  BOOST_TEST(d.reason.find("local order drifts from") != std::string::npos, d.reason);
  // Without the floor the same steps are an exact power law: no drift, the order stands.
  std::vector<double> e0;
  for (double x : h) e0.push_back(3 * x * x);
  BOOST_TEST(judge_order(fit_order(h, e0)).verdict == OrderVerdict::converges_at_expected_order);
}

BOOST_AUTO_TEST_CASE(a_failed_run_is_a_result_not_a_gap) {
  // Oracle: e = 3 h² on 7 halvings with the finest run NaN (it blew up): the other 6 fit p = 2
  // exactly, which was called "converges at the expected order" with no word of the failure.
  std::vector<double> h, e;
  for (int k = 0; k < 7; ++k) {
    h.push_back(0.1 / std::pow(2.0, k));
    e.push_back(3 * h.back() * h.back());
  }
  e.back() = std::nan("");
  const OrderFit f = fit_order(h, e);
  BOOST_TEST(f.points == 6);
  BOOST_TEST(f.failed_points == 1);
  const OrderDecision d = judge_order(f);
  BOOST_TEST(d.verdict == OrderVerdict::order_not_established, d.reason);
  BOOST_TEST(d.reason.find("1 of 7 runs gave no finite error") != std::string::npos, d.reason);
  // An exact (zero) error is left out and said, not a failure.
  e.back() = 0;
  const OrderDecision z = judge_order(fit_order(h, e));
  BOOST_TEST(z.verdict == OrderVerdict::converges_at_expected_order, z.reason);
  BOOST_TEST(z.reason.find("1 run with an error ≤ 0 left out") != std::string::npos, z.reason);
}

BOOST_AUTO_TEST_CASE(a_slow_but_falling_error_is_not_said_not_to_fall) {
  // Oracle: e = h^0.18 exactly: the interval [0.18, 0.18] lies below the minimum 0.25, so the rule
  // says "does not converge", but the error provably falls, and the reason says so.
  std::vector<double> h{0.1, 0.05, 0.025, 0.0125}, e;
  for (double x : h) e.push_back(std::pow(x, 0.18));
  const OrderDecision d = judge_order(fit_order(h, e));
  BOOST_TEST(d.verdict == OrderVerdict::does_not_converge);
  BOOST_TEST(d.reason.find("the error falls, but no faster than h^0.25") != std::string::npos, d.reason);
}

BOOST_AUTO_TEST_CASE(a_narrow_interval_across_the_bands_edge_is_not_called_too_wide) {
  // Oracle: the rule on a stated fit: [1.894, 1.908] is 0.014 wide, the band 2 ± 0.1 is 0.2 wide;
  // the interval straddles the band's lower edge 1.9, neither within nor outside it.
  OrderFit f;
  f.valid = true;
  f.points = 5;
  f.order = 1.901;
  f.order_low = 1.894;
  f.order_high = 1.908;
  f.pairwise = {1.9, 1.9, 1.9, 1.9};
  const OrderDecision d = judge_order(f);
  BOOST_TEST(d.verdict == OrderVerdict::order_not_established);
  BOOST_TEST(d.reason.find("straddles the edge") != std::string::npos, d.reason);
  BOOST_TEST(d.reason.find("too wide") == std::string::npos, d.reason);
}

BOOST_AUTO_TEST_CASE(the_reason_names_the_interval_and_what_it_excludes) {
  // Oracle: the issue's own numbers — RK4 through a contact, p = 2.41 [1.74, 3.08] over 6 points,
  // judged against its formal order 4 ± 0.2.
  OrderFit f;
  f.valid = true;
  f.points = 6;
  f.order = 2.41;
  f.order_low = 1.74;
  f.order_high = 3.08;
  OrderJudgement j{4, 0.2, 0.25};
  j.expected_name = "formal";
  const OrderDecision d = judge_order(f, j);
  BOOST_TEST(d.verdict == OrderVerdict::converges_at_other_order);
  BOOST_TEST(d.reason == "p = 2.41 [1.74, 3.08] excludes the formal 4");
  f.order = 3.98;
  f.order_low = 3.9;
  f.order_high = 4.1;
  BOOST_TEST(judge_order(f, j).reason == "p = 3.98 [3.9, 4.1] lies within 0.2 of the formal 4");
}

BOOST_AUTO_TEST_CASE(confidence_interval_covers_the_true_order_about_95_percent_of_the_time) {
  // Oracle: for log-normal noise the Student-t interval of the slope has exact 95 % coverage.
  // Over 400 independent noisy data sets the number of misses is Binomial(400, 0.05):
  // mean 20, sd 4.4; we accept 7..36 (about ±3 sd) so the test fails only if the interval is
  // wrong, not by chance (the generator is seeded, so the test is deterministic anyway).
  std::mt19937_64 rng(12345);
  auto normal = [&rng] {  // Box–Muller on the (portable) raw generator output
    double u1 = (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53;
    double u2 = (static_cast<double>(rng() >> 11) + 0.5) * 0x1.0p-53;
    return std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2);
  };
  const std::vector<double> h{0.2, 0.1, 0.05, 0.025, 0.0125, 0.00625};
  int misses = 0, trials = 400;
  for (int t = 0; t < trials; ++t) {
    std::vector<double> e;
    for (double x : h) e.push_back(2 * x * x * std::exp(0.1 * normal()));
    OrderFit f = fit_order(h, e);
    if (!(f.order_low <= 2 && 2 <= f.order_high)) ++misses;
  }
  BOOST_TEST(misses >= 7);
  BOOST_TEST(misses <= 36);
}

BOOST_AUTO_TEST_CASE(richardson_extrapolation_removes_the_leading_term) {
  // Oracle: φ(h) = 5 + 2 h² exactly; two values with r = 2, p = 2 extrapolate to 5.
  BOOST_TEST(std::abs(richardson_extrapolate(5 + 2 * 0.01, 5 + 2 * 0.04, 2, 2) - 5) <= 1e-13);
}

BOOST_AUTO_TEST_CASE(the_correction_term_recovers_the_order_that_a_second_term_hides) {
  // Oracle: e = 3 h⁴ (1 − 0.6 h/h_max), the leading term of a fourth-order method plus the next
  // one (order_fit.hpp), over six halvings: the true order is 4. A single power bends to 3.77 with
  // an interval that excludes 4 (the pre-asymptotic trap); with the correction term the F test
  // finds the term (F ≈ 210 against the 95 % quantile 10.1 of F(1, 3)) and the interval holds 4.
  // The fit is log-linear in h while the term is log(1 − 0.6 h/h_max): the O(h²) rest widens and
  // shifts the interval a little (computed independently: 4.06 [3.99, 4.13]).
  std::vector<double> h, e;
  for (int k = 0; k < 6; ++k) {
    const double x = 0.1 / std::pow(2.0, k);
    h.push_back(x);
    e.push_back(3 * std::pow(x, 4) * (1 - 0.6 * x / 0.1));
  }
  const OrderFit single = fit_order(h, e);
  BOOST_TEST(!single.corrected);
  BOOST_TEST(single.order_high < 4.0);
  OrderFitOptions with;
  with.correction_term = true;
  const OrderFit f = fit_order(h, e, with);
  BOOST_TEST(f.corrected);
  BOOST_TEST(std::abs(f.f_critical - 10.128) <= 1e-3);  // F(1, 3), 95 %: statistical tables
  BOOST_TEST(f.f_statistic > 100);
  BOOST_TEST(f.order_low <= 4.0);
  BOOST_TEST(f.order_high >= 4.0);
  BOOST_TEST(std::abs(f.order - 4.059) <= 0.005);
  BOOST_TEST(std::abs(f.single_order - single.order) <= 1e-12);  // the single power is kept beside it
  OrderJudgement j;
  j.expected_order = 4;
  j.tolerance = 0.25;
  BOOST_TEST(judge_order(single, j).verdict == OrderVerdict::order_not_established);  // [3.58, 3.96] straddles 3.75
  BOOST_TEST(judge_order(f, j).verdict == OrderVerdict::converges_at_expected_order);
}

BOOST_AUTO_TEST_CASE(scatter_without_a_trend_keeps_the_single_power) {
  // Oracle: e = 3 h² (1 ± 5 %), the sign alternating: scatter with no trend in h. The extra term
  // explains almost none of it (F ≈ 0.06 ≪ 10.1), so the single power stands, unchanged; and
  // with 3 points the term is not tried at all (no degree of freedom would be left).
  std::vector<double> h, e;
  for (int k = 0; k < 6; ++k) {
    const double x = 0.1 / std::pow(2.0, k);
    h.push_back(x);
    e.push_back(3 * x * x * (1 + 0.05 * (k % 2 == 0 ? 1 : -1)));
  }
  OrderFitOptions with;
  with.correction_term = true;
  const OrderFit f = fit_order(h, e, with), single = fit_order(h, e);
  BOOST_TEST(!f.corrected);
  BOOST_TEST(f.f_statistic < 1);
  BOOST_TEST(f.order == single.order);
  BOOST_TEST(f.order_low == single.order_low);
  const OrderFit three = fit_order({0.1, 0.05, 0.025}, {1e-2, 2e-3, 5e-4}, with);
  BOOST_TEST(!three.corrected);
  BOOST_TEST(three.f_critical == 0);
  // An error that rises once as h shrinks (pairwise order < 0) is not an approach to C h^p: the
  // term is not tried, whatever F would say.
  const OrderFit rises = fit_order({0.1, 0.05, 0.025, 0.0125, 0.00625}, {2e-6, 4e-8, 7e-9, 3e-8, 8e-9}, with);
  BOOST_TEST(!rises.corrected);
  BOOST_TEST(rises.f_critical == 0);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
