#pragma once
// Von Neumann stability of the damped leapfrog (model/README.md §2.1) with a 3×3 stencil. A Fourier mode with
// symbol s (d² × the stencil's eigenvalue) is multiplied each step by a root g of
//   (2 + μΔt) g² − (4 + 2σ² s) g + (2 − μΔt) = 0,   σ = cΔt/d,
// found by inserting z ∝ gⁿ e^{ik·x} into the update. The scheme is stable when |g| ≤ 1 for every
// mode of the wavenumber grid. stability_limit() finds the limit by bisection on σ, not from a
// formula: the waves studies use it as an independent check of the closed form
// (model/water/stencil.hpp: leapfrog_courant_limit), which is what `wave` and `scene` report.
#include <cstdint>
#include <string>

#include "model/water/stencil.hpp"

namespace stoneskip {

// Largest |g| of the mode with symbol s.
double amplification(double symbol, double sigma, double mu_dt);

// Largest |g| over the wavenumbers 2π(i, j)/n, i, j < n (n even, so the checkerboard is included).
double max_amplification(const Stencil& stencil, double sigma, double mu_dt, int n = 64);

struct StabilityLimitOptions {
  int wavenumbers = 64;       // n of the wavenumber grid
  double growth_tolerance = 1e-9;  // |g| ≤ 1 + this counts as stable (|g| = 1 is neutral)
  double sigma_max = 4;       // search range (0, sigma_max]
  double tolerance = 1e-10;   // bisection width
};

// Largest stable σ for the given μΔt; 0 if unstable for every σ > 0, sigma_max if stable up to it.
double stability_limit(const Stencil& stencil, double mu_dt, const StabilityLimitOptions& options = {});

// Lengyel's printed bound (Mathematics for 3D Game Programming, height fields):
// c < (d/2Δt)√(μΔt + 2), i.e. σ < ½√(μΔt + 2). Reported beside the computed limit.
double lengyel_bound(double mu_dt);

// A run of the height field (periodic, n × n) from seeded zero-mean random noise, to see growth
// directly. The growth RATE is measured, not the growth: log RMS is fitted by least squares
// against the step number over the latter half of the run, where the fastest mode dominates (the
// others have decayed relative to it), so the fitted rate is that mode's |g|; it is reported beside
// the von Neumann |g| of the run's own wavenumber grid. The run "grew" when the fitted rate
// exceeds 1 by more than the run can resolve: the rise of log RMS over the window must exceed the
// scatter of log RMS about the fitted line (rate tolerance = scatter / window length, which
// shrinks as the run grows longer or cleaner) plus a round-off floor per step. Just above a
// limit with damping, |g| − 1 ∝ (σ − σ_limit)/μΔt is tiny: a threshold on the growth itself ("RMS
// up 10×") misses it and places the limit too high, the more so the stronger the damping.
struct GrowthRun {
  double sigma = 0, mu_dt = 0;
  long steps = 0;               // asked for
  long steps_run = 0;           // taken (a run stops early once its RMS passes 1e100)
  double norm_ratio = 0;        // ‖z_end‖ / ‖z_0‖ (RMS)
  double growth_per_step = 0;   // measured: exp(slope of log RMS) over the latter half of the run
  double von_neumann_g = 0;     // max |g| over the run's n × n wavenumbers (max_amplification)
  double rate_tolerance = 0;    // ln(growth_per_step) must exceed this to count as growth
  bool grew = false;
};
GrowthRun run_growth(const Stencil& stencil, double sigma, double mu_dt, int n = 16, long steps = 400,
                     std::uint64_t seed = 1);

// The limit measured by running: bisection on σ between a run that does not grow and one that
// does (GrowthRun::grew), to a relative width `relative_tolerance`.
double measured_stability_limit(const Stencil& stencil, double mu_dt, double sigma_low, double sigma_high,
                                double relative_tolerance = 1e-4, long steps = 2000);

}  // namespace stoneskip
