#include "model/water/stencil.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>

namespace stoneskip {
namespace {

constexpr double kRoundoff = 1e-14;  // a few ulps of O(1) weights

BOOST_AUTO_TEST_SUITE(stencil_)

BOOST_AUTO_TEST_CASE(named_stencils_have_the_weights_of_the_spec_table) {
  // Oracle: model/README.md §2.2 table (centre, orth, diag) × 1/d².
  struct Row { const char* name; double c, o, d; };
  for (Row r : {Row{"five_point", -4, 1, 0}, Row{"nine_point_half", -3, 0.5, 0.25},
                Row{"nine_point_isotropic", -10.0 / 3, 2.0 / 3, 1.0 / 6}, Row{"paper_eq11", -10.0 / 3, 0.5, 0.25}}) {
    Stencil s = named_stencil(r.name);
    BOOST_TEST(std::abs(s.centre - r.c) <= kRoundoff);
    BOOST_TEST(std::abs(s.orth - r.o) <= kRoundoff);
    BOOST_TEST(std::abs(s.diag - r.d) <= kRoundoff);
  }
  BOOST_CHECK_THROW(named_stencil("seven_point"), std::invalid_argument);
}

BOOST_AUTO_TEST_CASE(symbol_equals_the_stencil_applied_to_a_fourier_mode) {
  // Oracle: direct application of the 3×3 weights to cos(a i + b j) at the origin.
  Stencil s = named_stencil("nine_point_isotropic");
  const double a = 0.7, b = -1.3;
  auto f = [&](int i, int j) { return std::cos(a * i + b * j); };
  double direct = s.centre * f(0, 0) + s.orth * (f(1, 0) + f(-1, 0) + f(0, 1) + f(0, -1)) +
                  s.diag * (f(1, 1) + f(1, -1) + f(-1, 1) + f(-1, -1));
  BOOST_TEST(std::abs(s.symbol(a, b) - direct) <= kRoundoff);
}

BOOST_AUTO_TEST_CASE(courant_limits_are_the_spec_values) {
  // Oracle: model/README.md §2.2 stability limits 1/√2 (5-point), √3/2 (γ = 1/3), 1 (γ = 1/2), found there by
  // von Neumann analysis; paper_eq11's most negative symbol is −13/3 at (0, π), so 2/√(13/3).
  BOOST_TEST(std::abs(leapfrog_courant_limit(named_stencil("five_point")) - 1 / std::sqrt(2.0)) <= kRoundoff);
  BOOST_TEST(std::abs(leapfrog_courant_limit(named_stencil("nine_point_isotropic")) - std::sqrt(3.0) / 2) <= kRoundoff);
  BOOST_TEST(std::abs(leapfrog_courant_limit(named_stencil("nine_point_half")) - 1.0) <= kRoundoff);
  BOOST_TEST(std::abs(leapfrog_courant_limit(named_stencil("paper_eq11")) - 2 / std::sqrt(13.0 / 3)) <= kRoundoff);
  // A stencil whose weights sum above zero has a growing mode for every σ: limit 0.
  BOOST_TEST(leapfrog_courant_limit(Stencil{"raised", -3.5, 1, 0}) == 0);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
