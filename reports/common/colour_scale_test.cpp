// robust_scale against a field counted by hand. Oracle: 10000 still cells, 1000 ripples of
// |z| = k µm (k = 1 … 1000, alternating sign) and 5 splash cells of ±2 mm. The largest is 2 mm, so
// the disturbed cells are those above 20 µm: k = 21 … 1000 (980) and the splashes, 985; the 99th
// percentile by nearest rank is the ⌈0.99 · 985⌉ = 976th smallest, k = 996 µm; beyond it lie
// k = 997 … 1000 and the splashes, 9 cells. Exact: the scale is one of the stored values.
#include <boost/test/unit_test.hpp>

#include "reports/common/colour_scale.hpp"

using namespace stoneskip;

BOOST_AUTO_TEST_SUITE(colour_scale)

BOOST_AUTO_TEST_CASE(a_splash_does_not_set_the_scale_and_the_ripples_are_not_saturated) {
  std::vector<double> z(10000, 0.0);
  for (int k = 1; k <= 1000; ++k) z.push_back((k % 2 ? 1 : -1) * k * 1e-6);
  for (int k = 0; k < 5; ++k) z.push_back(k % 2 ? 2e-3 : -2e-3);
  const RobustScale r = robust_scale(z);
  BOOST_TEST(r.largest == 2e-3);
  BOOST_TEST(r.disturbed == 985u);
  BOOST_TEST(r.scale == 996 * 1e-6);  // the stored value itself, computed as the field was
  BOOST_TEST(r.beyond == 9u);
}

BOOST_AUTO_TEST_CASE(a_flat_field_has_no_scale) {
  const RobustScale r = robust_scale(std::vector<double>(100, 0.0));
  BOOST_TEST(r.scale == 0.0);
  BOOST_TEST(r.disturbed == 0u);
}

BOOST_AUTO_TEST_SUITE_END()
