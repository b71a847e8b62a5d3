// Oracle: printf's own rounding, worked by hand for each pair.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdlib>

#include "tools/io/number_text.hpp"

using stoneskip::numbers_apart;

BOOST_AUTO_TEST_SUITE(number_text)

BOOST_AUTO_TEST_CASE(two_numbers_that_differ_are_printed_apart_and_equal_ones_as_asked) {
  // 0.70711 against 1/sqrt(2) = 0.7071067811865476: both 0.7071 at 4 digits, both 0.70711 at 5
  // (0.7071068 rounds up), apart at 6 (%g drops 0.707110's trailing zero).
  const auto [s, l] = numbers_apart(0.70711, 1 / std::sqrt(2.0), 4);
  BOOST_TEST(s == "0.70711");
  BOOST_TEST(l == "0.707107");
  // Already apart at the digits asked: unchanged.
  const auto [a, b] = numbers_apart(1.9, 2.05, 3);
  BOOST_TEST(a == "1.9");
  BOOST_TEST(b == "2.05");
  // Equal: the digits asked.
  const auto [e1, e2] = numbers_apart(0.5, 0.5, 4);
  BOOST_TEST(e1 == "0.5");
  BOOST_TEST(e2 == "0.5");
  // The next double: apart only at 17 digits.
  const auto [n1, n2] = numbers_apart(1.0, std::nextafter(1.0, 2.0), 4);
  BOOST_TEST(n1 != n2);
}

BOOST_AUTO_TEST_CASE(a_bound_is_printed_rounded_down) {
  // 0.0138598 s at 4 digits: 0.01386 rounds up past it, 0.01385 does not.
  BOOST_TEST(stoneskip::at_most(0.0138598, 4) == "0.01385");
  BOOST_TEST(stoneskip::at_most(0.5, 4) == "0.5");  // exact: unchanged
  BOOST_TEST(stoneskip::at_most(2.0 / 3.0, 3) == "0.666");
  BOOST_TEST(stoneskip::at_most(123456.0, 2) == "1.2e+05");
  // Just below a power of ten: printed to the nearest it reads as the power; the bound keeps all
  // its digits (0.099 and 9.99 would be true but a digit short).
  BOOST_TEST(stoneskip::at_most(0.09999, 3) == "0.0999");
  BOOST_TEST(stoneskip::at_most(9.9996, 4) == "9.999");
  BOOST_TEST(stoneskip::at_most(99.99, 2) == "99");
  for (double x : {1e-9, 0.09999, 9.9996, 0.0138598, 0.7071067811865476, 3.999999999, 12345.678})
    for (int d = 1; d <= 8; ++d) BOOST_TEST(std::strtod(stoneskip::at_most(x, d).c_str(), nullptr) <= x, x << " at " << d);
}

BOOST_AUTO_TEST_SUITE_END()
