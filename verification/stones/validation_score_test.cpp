// Tests of the distance between a model and the measurements (validation_score.hpp).
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "verification/stones/validation_score.hpp"

namespace stoneskip {
namespace {

constexpr double kRoundoff = 1e-14;  // a few ulps of numbers of order 1
const double kMiss = std::log(10.0);

ScoredValue value(double m) { return ScoredValue{"q", true, m, false, ""}; }

BOOST_AUTO_TEST_SUITE(validation_score)

BOOST_AUTO_TEST_CASE(distances_match_a_hand_computation) {
  // Oracle: by hand. Clanet's minimum speed [2.5, 2.6] m/s and a model at 3.62 m/s: ln(3.62/2.6) =
  // 0.330963…; a contact time of 55 ms against 32 ms: ln(55/32) = 0.541597…; an exponent −1.2
  // against −1: ln 1.2 = 0.182322…; a value inside its range: 0; no value: ln 10 = 2.302585…; a
  // value of the other sign (an exponent +0.5 against −1): ln 10. Mean of the six: 0.943342….
  const std::vector<ScoredValue> v{value(3.62), value(0.055), value(-1.2), value(2.55),
                                   ScoredValue{"q", false, 0, false, "no bounce up to 8 m/s"}, value(0.5)};
  const std::vector<MeasuredRange> r{{2.5, 2.6}, {0.032, 0.032}, {-1, -1}, {2.5, 2.6}, {2.5, 2.6}, {-1, -1}};
  const ModelDistance d = model_distance(v, r, kMiss);
  const double expected[] = {0.330962580810243, 0.541597282432744, 0.182321556793955, 0.0, 2.302585092994046,
                             2.302585092994046};
  for (int i = 0; i < 6; ++i) BOOST_TEST(std::abs(d.distances[i] - expected[i]) < kRoundoff);
  BOOST_TEST(std::abs(d.mean - 0.943341934337506) < kRoundoff);
}

BOOST_AUTO_TEST_CASE(a_factor_too_high_and_too_low_are_equally_far_and_capped) {
  // Oracle: |ln 2| either way; a factor of 100 is capped at the miss distance ln 10.
  const MeasuredRange r{2.0, 4.0};
  BOOST_TEST(std::abs(quantity_distance(value(8.0), r, kMiss) - std::log(2.0)) < kRoundoff);
  BOOST_TEST(std::abs(quantity_distance(value(1.0), r, kMiss) - std::log(2.0)) < kRoundoff);
  BOOST_TEST(quantity_distance(value(400.0), r, kMiss) == kMiss);
  BOOST_TEST(quantity_distance(value(4.0), r, kMiss) == 0.0);  // the ends belong to the range
  BOOST_TEST(quantity_distance(value(std::nan("")), r, kMiss) == kMiss);
  BOOST_TEST(std::isnan(model_distance({}, {}, kMiss).mean));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
