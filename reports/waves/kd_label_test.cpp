// The waves report's kd labels. Oracle: the values themselves (π/n written as such where kd is π
// over a whole number, otherwise the decimal multiple of π that data.h5 holds).
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "reports/waves/kd_label.hpp"

using namespace stoneskip;

BOOST_AUTO_TEST_SUITE(kd_label)

BOOST_AUTO_TEST_CASE(pi_over_a_whole_number_is_written_as_a_fraction) {
  BOOST_TEST(pi_fraction(M_PI) == "π");
  BOOST_TEST(pi_fraction(M_PI / 8) == "π/8");
  BOOST_TEST(pi_fraction(M_PI / 3) == "π/3");
}

BOOST_AUTO_TEST_CASE(other_wavenumbers_keep_their_value) {
  // 0.3π and 0.7π were written "π/3" (11 % off) and "π" (43 % off).
  BOOST_TEST(pi_fraction(0.3 * M_PI) == "0.3π");
  BOOST_TEST(pi_fraction(0.7 * M_PI) == "0.7π");
  BOOST_TEST(pi_fraction(2 * M_PI / 3) == "0.6667π");
}

BOOST_AUTO_TEST_SUITE_END()
