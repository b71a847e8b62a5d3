#include "verification/waves/isotropy.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>

namespace stoneskip {
namespace {

BOOST_AUTO_TEST_SUITE(isotropy_)

BOOST_AUTO_TEST_CASE(isotropic_stencil_spreads_ten_times_less_than_five_point_at_kd_pi_over_8) {
  // Oracle: model/README.md §2.2 — 5-point error −(kd)²(3 + cos 4θ)/96 spreads by (kd)²/48 ≈ 3.2e-3 over θ;
  // γ = 1/3 is −(kd)²/24 at every θ to leading order. The issue asks for ≥ 10× less.
  const double kd = M_PI / 8;
  const double five = phase_error_spread(named_stencil("five_point"), kd);
  const double iso = phase_error_spread(named_stencil("nine_point_isotropic"), kd);
  BOOST_TEST(std::abs(five - kd * kd / 48) <= 0.1 * kd * kd / 48);  // leading order, to 10 %
  BOOST_TEST(iso * 10 <= five, "spread " << iso << " vs " << five);
}

BOOST_AUTO_TEST_CASE(simulated_phase_speed_agrees_with_the_discrete_dispersion_relation) {
  // Oracle: the fully discrete relation cos ωΔt = 1 + σ²s/2 of a single Fourier mode; Prony's
  // estimate from 400 exact-recurrence samples is exact up to round-off (1e-10 in c/c).
  for (const char* name : {"five_point", "nine_point_isotropic"}) {
    MeasuredPhaseSpeed m = measure_phase_speed(named_stencil(name), M_PI / 8, 0.3, 64, 0.1, 400);
    BOOST_TEST(std::abs(m.measured_error - m.fully_discrete_error) <= 1e-10);
    // At σ = 0.1 the time error (σ kd)²/24 ≈ 6e-5 is all that separates it from the symbol.
    BOOST_TEST(std::abs(m.measured_error - m.semi_discrete_error) <= 1e-4);
  }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
