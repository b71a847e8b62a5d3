#include "verification/convergence/gci.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <ostream>

namespace stoneskip {

// Lets Boost.Test print the enum in a failure message.
inline std::ostream& operator<<(std::ostream& o, ConvergenceKind k) { return o << to_string(k); }

namespace {

BOOST_AUTO_TEST_SUITE(grid_convergence_index_)

BOOST_AUTO_TEST_CASE(celik_worked_example_is_reproduced) {
  // Oracle: Celik et al., J. Fluids Eng. 130 (2008) 078001, Table 1, column φ = 6.063, 5.972,
  // 5.863 on 18 000, 8 000, 4 500 cells in 2-D: p = 1.53, φ_ext = 6.1685, e_a = 1.5 %,
  // e_ext = 1.7 %, GCI_fine = 2.2 %. The paper prints 3–5 significant digits, so each comparison
  // is at half a unit of the last printed digit.
  auto h = [](double cells) { return std::sqrt(1.0 / cells); };
  GciResult g = grid_convergence_index(6.063, 5.972, 5.863, h(18000), h(8000), h(4500));
  BOOST_TEST(g.kind == ConvergenceKind::monotone);
  BOOST_TEST(std::abs(g.order - 1.53) <= 0.005);
  BOOST_TEST(std::abs(g.extrapolated - 6.1685) <= 0.00005);
  BOOST_TEST(std::abs(100 * g.relative_error - 1.5) <= 0.05);
  BOOST_TEST(std::abs(100 * g.extrapolated_relative_error - 1.7) <= 0.05);
  BOOST_TEST(std::abs(100 * g.gci_fine - 2.2) <= 0.05);
  BOOST_TEST(std::abs(g.ratio_21 - 1.5) <= 1e-12);
}

BOOST_AUTO_TEST_CASE(exact_power_law_on_unequal_ratios_gives_its_order_and_limit) {
  // Oracle: φ(h) = 1 + 0.5 h^1.7 exactly, so p = 1.7 and φ_ext = 1 up to the fixed-point
  // tolerance (1e-12) amplified by the conditioning of the extrapolation (~1e3).
  constexpr double kTol = 1e-9;
  auto phi = [](double h) { return 1 + 0.5 * std::pow(h, 1.7); };
  GciResult g = grid_convergence_index(phi(0.1), phi(0.13), phi(0.19), 0.1, 0.13, 0.19);
  BOOST_TEST(g.kind == ConvergenceKind::monotone);
  BOOST_TEST(std::abs(g.order - 1.7) <= kTol);
  BOOST_TEST(std::abs(g.extrapolated - 1.0) <= kTol);
}

BOOST_AUTO_TEST_CASE(alternating_differences_are_classified_oscillatory) {
  // Oracle: with equal ratios r = 2, q(p) = 0 and Celik Eq. 3 gives p = ln|ε32/ε21| / ln 2;
  // ε21 = −0.05, ε32 = 0.2 → p = 2 exactly, and s = −1 means oscillatory convergence.
  constexpr double kTol = 1e-12;
  GciResult g = grid_convergence_index(1.01, 0.96, 1.16, 1, 2, 4);
  BOOST_TEST(g.kind == ConvergenceKind::oscillatory);
  BOOST_TEST(std::abs(g.order - 2.0) <= kTol);
}

BOOST_AUTO_TEST_CASE(differences_growing_under_refinement_are_classified_divergent) {
  // Oracle: |φ1 − φ2| = 0.1 > |φ2 − φ3| = 0.01 on r = 2: the apparent order is
  // ln(0.1)/ln 2 < 0, i.e. the solution moves further under refinement — divergence.
  GciResult g = grid_convergence_index(1.0, 1.1, 1.11, 1, 2, 4);
  BOOST_TEST(g.kind == ConvergenceKind::divergent);
  GciResult osc = grid_convergence_index(1.0, 1.1, 1.09, 1, 2, 4);  // oscillating and growing
  BOOST_TEST(osc.kind == ConvergenceKind::divergent);
}

BOOST_AUTO_TEST_CASE(identical_solutions_are_converged_to_roundoff) {
  // Oracle: three equal values carry no order information; they must not be called divergent.
  GciResult g = grid_convergence_index(2.5, 2.5, 2.5, 1, 2, 4);
  BOOST_TEST(g.kind == ConvergenceKind::converged_to_roundoff);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
