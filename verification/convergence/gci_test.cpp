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

BOOST_AUTO_TEST_CASE(a_coarse_ratio_far_above_the_fine_one_still_gives_the_order) {
  // Oracle: φ(h) = 1 + 0.01 h² exactly on h = 1, 1.5, 4.5 (r21 = 1.5, r32 = 3), so p = 2 and
  // φ_ext = 1. Celik's fixed-point iteration runs away here (the map's slope at p = 2 is
  // (r21^p ln r21/(r21^p − 1) − r32^p ln r32/(r32^p − 1)) / ln r21 = −1.25) and called it
  // divergent; the bisection's tolerance is 1e-15 relative, amplified ~1e3 by Eq. 6.
  constexpr double kTol = 1e-9;
  auto phi = [](double h) { return 1 + 0.01 * h * h; };
  for (double h3 : {4.5, 1.5 * 1.25 * 4}) {
    GciResult g = grid_convergence_index(phi(1), phi(1.5), phi(h3), 1, 1.5, h3);
    BOOST_TEST(g.kind == ConvergenceKind::monotone);
    BOOST_TEST(std::abs(g.order - 2) <= kTol);
    BOOST_TEST(std::abs(g.extrapolated - 1) <= kTol);
  }
}

BOOST_AUTO_TEST_CASE(an_unreasonable_order_reverts_to_the_formal_one_with_a_safety_factor_of_3) {
  // Oracle: φ(h) = 1 + h³ on h = 1, 2, 4 has p = 3 exactly. Against a formal order of 2 with a band
  // of 0.1 it is not reasonable, so (Roache 2011) p_th = 2 and Fs = 3: GCI_fine = 3 |φ1 − φ2| /
  // |φ1| / (2² − 1) = 3 · 7/2 / 3 = 3.5, and the absolute band 3 · 7 / 3 = 7. Without a formal
  // order Celik's Fs = 1.25 and p = 3: 1.25 · 3.5 / 7 = 0.625.
  constexpr double kTol = 1e-12;
  GciOptions o;
  o.formal_order = 2;
  o.order_band = 0.1;
  GciResult g = grid_convergence_index(2, 9, 65, 1, 2, 4, o);
  BOOST_TEST(g.reverted);
  BOOST_TEST(std::abs(g.order - 3) <= 1e-9);
  BOOST_TEST(g.order_used == 2);
  BOOST_TEST(g.safety_factor == 3);
  BOOST_TEST(std::abs(g.gci_fine - 3.5) <= kTol);
  BOOST_TEST(std::abs(g.gci_fine_absolute - 7) <= kTol);
  GciResult plain = grid_convergence_index(2, 9, 65, 1, 2, 4);
  BOOST_TEST(!plain.reverted);
  BOOST_TEST(std::abs(plain.gci_fine - 0.625) <= 1e-9);
  // Within the band the apparent order stands: p = 2 against a formal 2.
  GciResult fine = grid_convergence_index(2, 5, 17, 1, 2, 4, o);  // φ = 1 + h²
  BOOST_TEST(!fine.reverted);
  BOOST_TEST(fine.safety_factor == 1.25);
}

BOOST_AUTO_TEST_CASE(a_fine_pair_at_round_off_gives_no_gci) {
  // Oracle: the two finest values agree to round-off while the coarse pair differs by 1e-3: any
  // band Eq. 9 drew from their difference would be of round-off size (it gave p = 35 and
  // GCI 1e-24 %), so there is none.
  GciResult g = grid_convergence_index(1 - 8e-15, 1, 1 + 1e-3, 1, 2, 4);
  BOOST_TEST(g.kind == ConvergenceKind::converged_to_roundoff);
}

BOOST_AUTO_TEST_CASE(the_absolute_band_is_defined_where_the_fine_value_is_zero) {
  // Oracle: φ(h) = h² − 1 on h = 1, 2, 4 (φ1 = 0): p = 2, φ_ext = −1; the relative GCI divides by
  // φ1 = 0, the absolute one is 1.25 · 3 / (2² − 1) = 1.25.
  GciResult g = grid_convergence_index(0, 3, 15, 1, 2, 4);
  BOOST_TEST(g.kind == ConvergenceKind::monotone);
  BOOST_TEST(std::abs(g.extrapolated + 1) <= 1e-9);
  BOOST_TEST(!std::isfinite(g.gci_fine));
  BOOST_TEST(std::abs(g.gci_fine_absolute - 1.25) <= 1e-9);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
