// The power-law shape test against an independent computation (numpy's lstsq on the same points),
// a series that is a power law to within a deterministic 1 % scatter, and the cases with too little
// to test.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "verification/convergence/power_law_shape.hpp"

using namespace stoneskip;

BOOST_AUTO_TEST_SUITE(power_law_shape)

BOOST_AUTO_TEST_CASE(a_bending_series_is_called_curved_with_numpys_f_and_local_exponents) {
  // Oracle: numpy.linalg.lstsq of the line and of the centred quadratic in log–log coordinates on
  // these points (the stones report's contact times of the planing_uniform_free variant against
  // speed, 2.5–8 m/s, 8 significant digits): F = 101.96420751986766; local exponents −1.77403453
  // (first pair) to −0.67518751 (last); F_0.95(1, 5) = 6.6079 (tables). Tolerances: 1e-9 relative
  // for F (two least-squares solutions of a well-conditioned 8 × 3 system), 1e-8 for the locals
  // (numpy's printout), 1e-4 for the tabulated quantile.
  const std::vector<double> u = {3.0, 2.5, 3.5, 4.0, 5.0, 6.0, 7.0, 8.0};  // out of order on purpose
  const std::vector<double> t = {0.04909744, 0.06784676, 0.04017406, 0.03446301, 0.02753033, 0.02377738, 0.02123649, 0.01940561};
  const PowerLawShape s = test_power_law_shape(u, t);
  BOOST_TEST_REQUIRE(s.tested);
  BOOST_TEST(s.points == 8);
  BOOST_TEST(s.f_statistic == 101.96420751986766, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(s.f_critical == 6.6079, boost::test_tools::tolerance(1e-4));
  BOOST_TEST(s.curved);
  BOOST_TEST(s.local_min == -1.77403453, boost::test_tools::tolerance(1e-8));
  BOOST_TEST(s.local_max == -0.67518751, boost::test_tools::tolerance(1e-8));
}

BOOST_AUTO_TEST_CASE(a_power_law_with_scatter_is_not_called_curved) {
  // Oracle: y = 0.17 x^−1 e^(±0.01), the sign alternating: numpy gives F = 0.00377, far below
  // F_0.95(1, 5); every local exponent is −1 ± 0.02 / log(x₂/x₁).
  const std::vector<double> x = {2.5, 3, 3.5, 4, 5, 6, 7, 8};
  std::vector<double> y;
  for (std::size_t i = 0; i < x.size(); ++i) y.push_back(0.17 / x[i] * std::exp(i % 2 == 0 ? 0.01 : -0.01));
  const PowerLawShape s = test_power_law_shape(x, y);
  BOOST_TEST_REQUIRE(s.tested);
  BOOST_TEST(s.f_statistic == 0.0037722010117666543, boost::test_tools::tolerance(1e-6));
  BOOST_TEST(!s.curved);
}

BOOST_AUTO_TEST_CASE(too_few_points_or_no_residual_are_not_tested) {
  // Three usable points (the non-positive and NaN ones are left out): locals, no test.
  const PowerLawShape three = test_power_law_shape({1, 2, 4, -1, 8}, {1, 0.5, 0.25, 3, std::nan("")});
  BOOST_TEST(!three.tested);
  BOOST_TEST(three.points == 3);
  BOOST_TEST(three.local_min == -1.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(three.local_max == -1.0, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(!three.curved);
  // An exact power law: the line through every point, nothing to test against.
  std::vector<double> x, y;
  for (double v : {1.0, 2.0, 4.0, 8.0, 16.0}) {
    x.push_back(v);
    y.push_back(3 * std::pow(v, -1.5));
  }
  BOOST_TEST(!test_power_law_shape(x, y).tested);
}

BOOST_AUTO_TEST_CASE(an_exact_parabola_in_log_log_is_curved_and_its_local_exponents_drift) {
  // Oracle: log y = (log x)² exactly, so the quadratic has no residual and the line a large one:
  // curved, F infinite (it was "not tested", and the exponent rule then read an exponent off a
  // series that is no power law). Its local exponent 2 log x runs from 0 at x = 1 to 2 log 16 at
  // x = 16 (tolerance: the least-squares solution of a 5 × 3 system, 1e-9).
  std::vector<double> x, y;
  for (double v : {1.0, 2.0, 4.0, 8.0, 16.0}) {
    x.push_back(v);
    y.push_back(std::exp(std::pow(std::log(v), 2)));
  }
  const PowerLawShape s = test_power_law_shape(x, y);
  BOOST_TEST_REQUIRE(s.tested);
  BOOST_TEST(s.curved);
  BOOST_TEST(std::isinf(s.f_statistic));
  BOOST_TEST(std::abs(s.quadratic_slope_at_min_x) <= 1e-9);
  BOOST_TEST(std::abs(s.quadratic_slope_at_max_x - 2 * std::log(16.0)) <= 1e-9);
}

BOOST_AUTO_TEST_SUITE_END()
