#include "verification/waves/stability.hpp"

#include <cmath>
#include <complex>
#include <limits>
#include <random>

#include "model/water/height_field.hpp"
#include "verification/convergence/order_fit.hpp"

namespace stoneskip {

double amplification(double symbol, double sigma, double mu_dt) {
  using C = std::complex<double>;
  const double t = sigma * sigma * symbol;
  const double a = 2 + mu_dt, b = 4 + 2 * t, c = 2 - mu_dt;
  // b² − 4ac = 4(μΔt² + t(4 + t)), formed from its small terms: subtracting 4ac ≈ 16 from b² ≈ 16
  // cancels every digit of μΔt² for μΔt below 1e-7, and the rounding left (≈ 1e-15) then reads
  // as a real root above 1 (the limit came out 0 for μΔt between 1.8e-11 and 1e-7).
  const C disc = std::sqrt(C(4 * (mu_dt * mu_dt + t * (4 + t)), 0));
  // Roots (b ± √disc)/(2a); choose the larger-magnitude pairing to avoid cancellation.
  const C g1 = (b >= 0 ? C(b) + disc : C(b) - disc) / (2 * a);
  const C g2 = std::abs(g1) > 0 ? C(c / a) / g1 : C(0);  // product of the roots is c/a
  return std::max(std::abs(g1), std::abs(g2));
}

double max_amplification(const Stencil& stencil, double sigma, double mu_dt, int n) {
  // A symbol within round-off of 0 (Stencil::symbol_roundoff) is the neutral s = 0: a positive
  // round-off s would read as growth of √(σ² s) per step, 2e-9 at σ = 0.1.
  const double symbol_roundoff = stencil.symbol_roundoff();
  double worst = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      double s = stencil.symbol(2 * M_PI * i / n, 2 * M_PI * j / n);
      if (std::abs(s) <= symbol_roundoff) s = 0;
      worst = std::max(worst, amplification(s, sigma, mu_dt));
    }
  return worst;
}

double stability_limit(const Stencil& stencil, double mu_dt, const StabilityLimitOptions& o) {
  auto stable = [&](double sigma) {
    return max_amplification(stencil, sigma, mu_dt, o.wavenumbers) <= 1 + o.growth_tolerance;
  };
  if (stable(o.sigma_max)) return o.sigma_max;
  double lo = 0, hi = o.sigma_max;
  if (!stable(o.tolerance)) return 0;
  while (hi - lo > o.tolerance) {
    const double mid = 0.5 * (lo + hi);
    (stable(mid) ? lo : hi) = mid;
  }
  return lo;
}

double lengyel_bound(double mu_dt) { return 0.5 * std::sqrt(mu_dt + 2); }

GrowthRun run_growth(const Stencil& stencil, double sigma, double mu_dt, int n, long steps, std::uint64_t seed) {
  // A step's round-off can change a neutral mode's amplitude by a few hundred ulps at most:
  // growth per step below this is not told from round-off.
  constexpr double kRoundoffRate = 1e-13;
  // Past this RMS the growth is unmistakable; stopping keeps the field finite.
  constexpr double kBlowUp = 1e100;
  HeightFieldOptions o;
  o.nx = o.ny = n;
  o.cell_m = 1.0 / n;
  o.wave_speed_m_s = 1;
  o.dt_s = sigma * o.cell_m;
  o.damping_per_s = mu_dt / o.dt_s;
  o.stencil = stencil;
  o.boundary = Boundary::periodic;
  HeightField field(o);
  std::mt19937_64 rng(seed);
  std::vector<double> z0(static_cast<std::size_t>(n) * n), z;
  for (double& v : z0) v = (static_cast<double>(rng() >> 11) * 0x1.0p-53) - 0.5;  // uniform in [−½, ½)
  // Zero mean: the k = 0 mode is neutral at every σ (g = 1) and says nothing about stability.
  double mean = 0;
  for (double v : z0) mean += v;
  mean /= static_cast<double>(z0.size());
  for (double& v : z0) v -= mean;
  auto rms = [](const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x * x;
    return std::sqrt(s / static_cast<double>(v.size()));
  };
  field.set_state(z0);
  const double n0 = rms(z0);
  std::vector<double> log_rms{std::log(n0)};
  double last = n0;
  for (long k = 1; k <= steps; ++k) {
    field.step();
    field.heights(z);
    last = rms(z);
    if (!(last > 0) || !std::isfinite(last)) break;
    log_rms.push_back(std::log(last));
    if (last > kBlowUp) break;
  }
  GrowthRun g;
  g.sigma = sigma;
  g.mu_dt = mu_dt;
  g.steps = steps;
  g.steps_run = static_cast<long>(log_rms.size()) - 1;
  g.norm_ratio = last / n0;
  g.von_neumann_g = max_amplification(stencil, sigma, mu_dt, n);
  // Least-squares rate over the latter half of the steps taken.
  const std::size_t first = log_rms.size() / 2;
  std::vector<double> x, y;
  for (std::size_t k = first; k < log_rms.size(); ++k) {
    x.push_back(static_cast<double>(k));
    y.push_back(log_rms[k]);
  }
  const LineFit fit = fit_line(x, y);
  const double window = x.size() > 1 ? x.back() - x.front() : 1.0;
  g.growth_per_step = fit.valid ? std::exp(fit.slope) : 0;
  g.rate_tolerance = (fit.residual_max - fit.residual_min) / window + kRoundoffRate;
  g.grew = !std::isfinite(last) || last > kBlowUp || (fit.valid && fit.slope > g.rate_tolerance);
  return g;
}

double measured_stability_limit(const Stencil& stencil, double mu_dt, double lo, double hi, double rel, long steps) {
  while (hi - lo > rel * hi) {
    const double mid = 0.5 * (lo + hi);
    (run_growth(stencil, mid, mu_dt, 16, steps).grew ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace stoneskip
