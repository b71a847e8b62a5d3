#include "verification/waves/stability.hpp"

#include <cmath>
#include <complex>
#include <random>

#include "model/water/height_field.hpp"

namespace stoneskip {

double amplification(double symbol, double sigma, double mu_dt) {
  using C = std::complex<double>;
  const double a = 2 + mu_dt, b = 4 + 2 * sigma * sigma * symbol, c = 2 - mu_dt;
  const C disc = std::sqrt(C(b * b - 4 * a * c, 0));
  // Roots (b ± √disc)/(2a); choose the larger-magnitude pairing to avoid cancellation.
  const C g1 = (b >= 0 ? C(b) + disc : C(b) - disc) / (2 * a);
  const C g2 = std::abs(g1) > 0 ? C(c / a) / g1 : C(0);  // product of the roots is c/a
  return std::max(std::abs(g1), std::abs(g2));
}

double max_amplification(const Stencil& stencil, double sigma, double mu_dt, int n) {
  double worst = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double s = stencil.symbol(2 * M_PI * i / n, 2 * M_PI * j / n);
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
  auto rms = [](const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x * x;
    return std::sqrt(s / v.size());
  };
  field.set_state(z0);
  const double n0 = rms(z0);
  const long m = std::max(1L, steps / 4);
  field.advance(steps - m);
  field.heights(z);
  const double n1 = rms(z);
  field.advance(m);
  field.heights(z);
  const double n2 = rms(z);
  GrowthRun g;
  g.sigma = sigma;
  g.mu_dt = mu_dt;
  g.steps = steps;
  g.norm_ratio = n2 / n0;
  g.growth_per_step = n1 > 0 ? std::pow(n2 / n1, 1.0 / m) : 0;
  g.grew = std::isfinite(g.norm_ratio) ? g.norm_ratio > 10 : true;
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
