// How a stored order fit is written in a report. Oracle: fits written here by hand, read as a
// reader would read them: an interval only where the fit has one.
#include <boost/test/unit_test.hpp>

#include "reports/common/section.hpp"

using namespace stoneskip;

BOOST_AUTO_TEST_SUITE(section_)

BOOST_AUTO_TEST_CASE(an_order_fit_of_two_points_is_written_without_an_interval) {
  // A 2-point fit's stored bounds equal its slope (no degree of freedom is left for an interval):
  // "3.02 [3.02, 3.02]" would read as a certain order 3.02.
  Record fit;
  fit.set("valid", true).set("order", 3.0214).set("order_low", 3.0214).set("order_high", 3.0214).set("points", 2);
  BOOST_TEST(order_interval(fit) == "3.02 (2 pts: no interval)");
  fit.set("points", 3).set("order_low", 2.9).set("order_high", 3.1);
  BOOST_TEST(order_interval(fit) == "3.02 [2.9, 3.1]");
  Record old;  // written before fits stored their points: as before
  old.set("valid", true).set("order", 2.0).set("order_low", 1.99).set("order_high", 2.02);
  BOOST_TEST(order_interval(old) == "2 [1.99, 2.02]");
  old.set("valid", false);
  BOOST_TEST(order_interval(old) == "–");
}

BOOST_AUTO_TEST_SUITE_END()
