// The root search on a step's interpolant (dense_output.hpp): sign_change_fraction with and
// without a bound on the root wanted.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "solvers/realtime/dense_output.hpp"

using namespace stoneskip;

BOOST_AUTO_TEST_SUITE(dense_output)

BOOST_AUTO_TEST_CASE(a_search_told_the_root_wanted_lies_below_a_bound_gives_the_same_root_or_one_past_it) {
  // Oracle: the search without the bound. g(θ) = (θ − r)(1 + θ²) + 0.3 (θ − r)³ has one root r in
  // [0, 1], approached by Illinois from both sides (not a straight line: the secant alone would not
  // land on it). For a root below the bound the result must be the unbounded one bit for bit (the
  // same iterates); for a root at or past the bound, a θ ≥ the bound (the caller then keeps its
  // earlier root) after fewer evaluations.
  for (const double r : {0.05, 0.3, 0.61, 0.9}) {
    int calls = 0;
    auto g = [&](double t) {
      ++calls;
      const double x = t - r;
      return x * (1 + t * t) + 0.3 * x * x * x;
    };
    const double g0 = g(0), g1 = g(1);
    calls = 0;
    const double full = sign_change_fraction(g, g0, g1, 1e-13);
    const int full_calls = calls;
    BOOST_TEST(std::abs(full - r) <= 1e-12);  // the tolerance asked, and a few ulps
    for (const double bound : {0.2, 0.5, 0.7, 2.0}) {
      calls = 0;
      const double bounded = sign_change_fraction(g, g0, g1, 1e-13, bound);
      if (r < bound) {
        BOOST_TEST(bounded == full);
        BOOST_TEST(calls == full_calls);
      } else {
        BOOST_TEST(bounded >= bound);
        BOOST_TEST(calls < full_calls);
      }
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
