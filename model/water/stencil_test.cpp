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

BOOST_AUTO_TEST_CASE(courant_limits_are_exact_unbounded_without_coupling_and_zero_when_a_mode_grows) {
  // Oracle: Schur–Cohn on (1 + a) g² − (2 + σ² s) g + (1 − a) = 0, a = μΔt/2 ≥ 0 (model/README.md
  // §2.1–2.2): stable iff −4 ≤ σ² s ≤ 0 for every mode, so σ_max = 2/√(−min s) exactly. The corner
  // symbols are sums of exact weights × cos 0 = 1, cos π = −1, so the limits must equal the closed
  // forms to the rounding of one square root and one division (kRoundoff is ample). The bisection
  // reported 0.7071067811339 (five-point) and "stable up to 4" for a stencil of zeros.
  BOOST_TEST(leapfrog_courant_limit(named_stencil("five_point")) == 2 / std::sqrt(8.0));  // min s = −8 at (π, π)
  // Centre −1 alone: s = −1 for every mode, σ_max = 2.
  BOOST_TEST(std::abs(leapfrog_courant_limit(Stencil{"decay", -1, 0, 0}) - 2.0) <= kRoundoff);
  // No spatial coupling: s = 0 for every mode, roots 1 and (2 − μΔt)/(2 + μΔt) at any σ: unbounded.
  BOOST_TEST(std::isinf(leapfrog_courant_limit(Stencil{"zeros", 0, 0, 0})));
  // Anti-diffusive (centre 4, orth −1): s = 8 > 0 at (π, π), a mode that grows at every σ > 0.
  BOOST_TEST(leapfrog_courant_limit(Stencil{"anti", 4, -1, 0}) == 0);
  // The isotropic stencil's constant mode comes out as ±4e-16, not 0: round-off, not growth.
  BOOST_TEST(std::abs(named_stencil("nine_point_isotropic").weight_sum()) <= named_stencil("nine_point_isotropic").symbol_roundoff());
  BOOST_TEST(leapfrog_courant_limit(named_stencil("nine_point_isotropic")) > 0);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
