#include "verification/waves/precision_error.hpp"

#include <boost/test/unit_test.hpp>

namespace stoneskip {

BOOST_AUTO_TEST_SUITE(precision_error_)

BOOST_AUTO_TEST_CASE(float_storage_errs_at_float_round_off_far_below_the_discretisation) {
  // Oracle: float32 keeps 24 bits, so each step rounds every value by ~6e-8 of the amplitude; the
  // leapfrog is neutrally stable, so over N steps the difference grows at most ~N·6e-8 (linearly,
  // a bound) — 64 steps on a 64² grid: ≤ 64 · 6e-8 · 1 cm ≈ 4e-8 m. The discretisation error of
  // that grid is ~1e-4 m, over a thousand times larger.
  PrecisionErrorOptions o;
  o.n = 64;
  const PrecisionError e = measure_precision_error(o);
  BOOST_TEST(e.float_vs_double_max_m > 0);
  BOOST_TEST(e.float_vs_double_max_m <= e.steps * 6e-8 * 0.01, e.brief());
  BOOST_TEST(e.ratio() < 1e-3, e.brief());
  BOOST_TEST_MESSAGE(e.brief());
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace stoneskip
