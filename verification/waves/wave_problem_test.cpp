#include "verification/waves/wave_problem.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>

namespace stoneskip {
namespace {

// A few roundings of the scaled sum (one ratio, one square and one root per value).
constexpr double kFewUlps = 8 * std::numeric_limits<double>::epsilon();

BOOST_AUTO_TEST_SUITE(wave_problem_)

BOOST_AUTO_TEST_CASE(rms_of_values_whose_squares_overflow_is_their_closed_form) {
  // Oracle: the 3-4-5 triangle. RMS(3e200, 4e200) = 5e200/√2, though 9e400 overflows a double
  // (the wave command printed "L2 (RMS) inf m" for a surface of 8.6e221 m). Relative to kFewUlps.
  const double rms = root_mean_square(std::vector<double>{3e200, -4e200});
  const double exact = 5e200 / std::sqrt(2.0);
  BOOST_TEST(std::abs(rms / exact - 1) <= kFewUlps, rms);
  // Zeros among large values count in n, not in the scale: RMS(0, 0, 0, 2e300) = 1e300.
  BOOST_TEST(std::abs(root_mean_square(std::vector<double>{0, 0, 0, 2e300}) / 1e300 - 1) <= kFewUlps);
}

BOOST_AUTO_TEST_CASE(rms_of_ordinary_values_is_the_plain_sum_to_the_bit_and_inf_stays_inf) {
  // Oracle: the plain formula √(Σx²/n), evaluated here in the same order, so the studies' numbers
  // do not move: equal exactly. A non-finite value is not hidden: the RMS is inf.
  const std::vector<double> v{0.1, -0.25, 3e-3, 7.5};
  double s = 0;
  for (double x : v) s += x * x;
  BOOST_TEST(root_mean_square(v) == std::sqrt(s / 4));
  BOOST_TEST(std::isinf(root_mean_square(std::vector<double>{1e300, INFINITY})));
  // field_error uses the same RMS on the difference: 0 against (3e200, −4e200).
  const FieldError e = field_error({3e200, -4e200}, {0, 0});
  BOOST_TEST(std::abs(e.l2_m / (5e200 / std::sqrt(2.0)) - 1) <= kFewUlps);
  BOOST_TEST(e.max_m == 4e200);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
