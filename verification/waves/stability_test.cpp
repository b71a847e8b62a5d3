#include "verification/waves/stability.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>

namespace stoneskip {
namespace {

// The bisection runs to 1e-10 and the wavenumber grid contains the worst modes, so the computed
// limits sit far inside the 1e-3; we test at 1e-3 as asked.
constexpr double kLimit = 1e-3;

BOOST_AUTO_TEST_SUITE(stability_)

BOOST_AUTO_TEST_CASE(computed_limits_match_the_spec_and_do_not_grow_with_damping) {
  // Oracle: model/README.md §2.2 (derived independently): σ ≤ 1/√2, √3/2, 1 for γ = 0, 1/3, 1/2, for every μΔt.
  struct Row { const char* name; double limit; };
  for (Row r : {Row{"five_point", 1 / std::sqrt(2.0)}, Row{"nine_point_isotropic", std::sqrt(3.0) / 2},
                Row{"nine_point_half", 1.0}})
    for (double mu_dt : {0.0, 0.1, 0.5, 1.0, 1.9}) {
      const double s = stability_limit(named_stencil(r.name), mu_dt);
      BOOST_TEST(std::abs(s - r.limit) <= kLimit, r.name << " at μΔt = " << mu_dt << ": " << s);
    }
}

BOOST_AUTO_TEST_CASE(the_limit_is_independent_of_damping_down_to_round_off_damping) {
  // Oracle: model/water/stencil.hpp (Schur–Cohn) — σ_max = 2/√(−min s) for every μΔt ≥ 0 (checked here on [0, 1]),
  // so 1/√2, √3/2, 1 at every μΔt of [0, 1], including 1e-11 … 1e-7 where the discriminant's
  // μΔt² is below the round-off of 16 (the limit came out 0 there). Tolerance kLimit as above.
  const double dampings[] = {0.0,  1e-14, 1e-12, 1e-11, 1.8e-11, 5e-11, 1e-10, 1e-9, 5.12e-9,
                             1e-8, 5e-8,  1e-7,  1e-6,  1e-4,    1e-2,  0.1,   0.5,  1.0};
  for (const char* name : {"five_point", "nine_point_isotropic", "nine_point_half"}) {
    const Stencil s = named_stencil(name);
    const double exact = leapfrog_courant_limit(s);
    for (double mu_dt : dampings) {
      const double limit = stability_limit(s, mu_dt);
      BOOST_TEST(std::abs(limit - exact) <= kLimit, name << " at μΔt = " << mu_dt << ": " << limit);
    }
  }
}

BOOST_AUTO_TEST_CASE(runs_two_percent_above_the_limit_grow_and_two_percent_below_do_not) {
  // Oracle: the computed limit itself; a run (random noise, 400 steps) above it must be found to
  // grow (GrowthRun::grew: its measured rate exceeds 1 by more than the run resolves) and one below
  // it must not, its RMS staying within 3× (neutral modes can add up).
  for (const char* name : {"five_point", "nine_point_half", "nine_point_isotropic"})
    for (double mu_dt : {0.0, 0.5}) {
      const Stencil s = named_stencil(name);
      const double limit = stability_limit(s, mu_dt);
      GrowthRun above = run_growth(s, 1.02 * limit, mu_dt);
      GrowthRun below = run_growth(s, 0.98 * limit, mu_dt);
      BOOST_TEST(above.grew, name << " μΔt " << mu_dt << " ratio " << above.norm_ratio);
      BOOST_TEST(!below.grew, name << " μΔt " << mu_dt << " rate " << below.growth_per_step);
      BOOST_TEST(below.norm_ratio <= 3.0, name << " μΔt " << mu_dt << " ratio " << below.norm_ratio);
    }
}

BOOST_AUTO_TEST_CASE(lengyel_bound_admits_a_growing_checkerboard) {
  // Oracle: model/README.md §2.2 — five-point, μΔt = 0.5, σ = 0.75 satisfies Lengyel's σ < ½√(μΔt + 2)
  // (= 0.79) yet the checkerboard root of 2.5g² + 5g + 1.5 = 0 is g = −(5 + √10)/5 ≈ −1.632.
  const Stencil s = named_stencil("five_point");
  BOOST_TEST(0.75 < lengyel_bound(0.5));
  const double g = (5 + std::sqrt(10.0)) / 5;
  BOOST_TEST(std::abs(max_amplification(s, 0.75, 0.5) - g) <= 1e-12);
  GrowthRun run = run_growth(s, 0.75, 0.5, 16, 200);
  BOOST_TEST(std::abs(run.growth_per_step - g) <= 1e-3);  // the run converges onto the worst mode
}

BOOST_AUTO_TEST_CASE(stable_modes_decay_at_the_exact_damped_rate) {
  // Oracle: model/README.md §2.2 — complex roots have |g| = √((2 − μΔt)/(2 + μΔt)).
  BOOST_TEST(std::abs(amplification(-2.0, 0.5, 0.4) - std::sqrt(1.6 / 2.4)) <= 1e-15);
}

BOOST_AUTO_TEST_CASE(the_measured_limit_is_the_von_neumann_limit_at_every_damping) {
  // Oracle: model/README.md §2.2 — the five-point limit is σ = 1/√2 for every μΔt. Just above it the
  // checkerboard grows by |g| ≈ 1 + 8 δ(σ²)/μΔt per step, so slowly that a run of 2000 steps barely
  // grows; a detector that waits for visible growth places the limit too high, and the more so
  // the stronger the damping (the old "RMS up 10×" rule: 0.70714 … 0.70756). Measured by the
  // growth rate, the limit must sit within the bisection's own width (1e-6 relative, × 4 for its
  // last halving and the rate tolerance) of 1/√2 at every μΔt, with no trend between them.
  constexpr double kBisection = 1e-6;
  constexpr double kAgreement = 4 * kBisection;
  const Stencil s = named_stencil("five_point");
  const double exact = 1 / std::sqrt(2.0);
  double lowest = 1e300, highest = -1e300;
  for (double mu_dt : {0.1, 0.5, 1.0, 1.5}) {
    const double m = measured_stability_limit(s, mu_dt, 0.9 * exact, 1.1 * exact, kBisection, 2000);
    BOOST_TEST(std::abs(m / exact - 1) <= kAgreement,
               "μΔt = " << mu_dt << ": measured " << m << ", relative error " << m / exact - 1);
    lowest = std::min(lowest, m);
    highest = std::max(highest, m);
  }
  BOOST_TEST((highest - lowest) / exact <= kAgreement, "spread over μΔt " << (highest - lowest) / exact);
}

BOOST_AUTO_TEST_CASE(the_measured_growth_rate_is_the_largest_von_neumann_amplification) {
  // Oracle: max_amplification on the run's own 16 × 16 wavenumber grid. Once the faster-decaying
  // modes have died out (latter half of the run), log RMS falls or rises at exactly log |g| of
  // the largest root; the least-squares rate must match it to 1e-9 (the fit of an exponential
  // sampled in double precision over 200 steps), above the limit and at Lengyel's σ.
  constexpr double kRate = 1e-9;
  const Stencil s = named_stencil("five_point");
  for (double sigma : {1.02 / std::sqrt(2.0), 0.75})
    for (double mu_dt : {0.5, 1.0}) {
      const GrowthRun run = run_growth(s, sigma, mu_dt, 16, 400);
      const double g = max_amplification(s, sigma, mu_dt, 16);
      BOOST_TEST(std::abs(run.growth_per_step - g) <= kRate * g,
                 "σ " << sigma << " μΔt " << mu_dt << ": measured " << run.growth_per_step << ", |g| " << g);
    }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
