#include "verification/waves/isotropy.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "model/water/disturbance.hpp"
#include "model/water/height_field.hpp"
#include "solvers/realtime/clocks.hpp"
#include "solvers/spectral/spectral_wave.hpp"

namespace stoneskip {

double phase_speed_error(const Stencil& stencil, double kd, double theta) {
  const double s = stencil.symbol(kd * std::cos(theta), kd * std::sin(theta));
  if (s > 0) return std::numeric_limits<double>::quiet_NaN();
  return std::sqrt(-s) / kd - 1;
}

double phase_error_spread(const Stencil& stencil, double kd, int angles) {
  double lo = 1e300, hi = -1e300;
  for (int a = 0; a < angles; ++a) {
    const double e = phase_speed_error(stencil, kd, 0.5 * M_PI * a / (angles - 1));
    lo = std::min(lo, e);
    hi = std::max(hi, e);
  }
  return hi - lo;
}

MeasuredPhaseSpeed measure_phase_speed(const Stencil& stencil, double kd, double theta, int N, double sigma, long steps) {
  MeasuredPhaseSpeed r;
  const double radius = kd * N / (2 * M_PI);  // |(m, n)| of the wanted mode
  r.m = static_cast<int>(std::lround(radius * std::cos(theta)));
  r.n = static_cast<int>(std::lround(radius * std::sin(theta)));
  const double a = 2 * M_PI * r.m / N, b = 2 * M_PI * r.n / N;
  r.kd = std::hypot(a, b);
  r.theta_rad = std::atan2(b, a);
  HeightFieldOptions o;
  o.nx = o.ny = N;
  o.cell_m = 1.0 / N;
  o.dt_s = sigma * o.cell_m;
  o.stencil = stencil;
  HeightField f(o);
  std::vector<double> mode(static_cast<std::size_t>(N) * N), z;
  for (int j = 0; j < N; ++j)
    for (int i = 0; i < N; ++i) mode[static_cast<std::size_t>(j) * N + i] = std::cos(a * i + b * j);
  f.set_state(mode);
  // Amplitude of the mode at each step (projection on the initial shape).
  std::vector<double> amp;
  amp.reserve(steps + 1);
  double norm = 0;
  for (double v : mode) norm += v * v;
  auto project = [&] {
    f.heights(z);
    double s = 0;
    for (std::size_t k = 0; k < z.size(); ++k) s += z[k] * mode[k];
    return s / norm;
  };
  amp.push_back(project());
  for (long s = 0; s < steps; ++s) {
    f.step();
    amp.push_back(project());
  }
  double num = 0, den = 0;
  for (std::size_t n = 1; n + 1 < amp.size(); ++n) {
    num += amp[n] * (amp[n + 1] + amp[n - 1]);
    den += 2 * amp[n] * amp[n];
  }
  const double omega_dt = std::acos(std::clamp(num / den, -1.0, 1.0));
  // c_measured/c = ω/(c k) = ωΔt / (σ kd).
  r.measured_error = omega_dt / (sigma * r.kd) - 1;
  r.semi_discrete_error = phase_speed_error(stencil, r.kd, r.theta_rad);
  const double sym = stencil.symbol(a, b);
  r.fully_discrete_error = std::acos(1 + sigma * sigma * sym / 2) / (sigma * r.kd) - 1;
  return r;
}

namespace {
// Radius of the wavefront along the ray θ from (cx, cy): the mean radius weighted by z² over
// [r_min, r_max] (sampled every quarter cell, bilinear). A weighted mean is insensitive to where
// the crest falls between cell points, which a crest-maximum search is not.
double front_radius(const HeightField& f, double cx, double cy, double theta, double r_min, double r_max) {
  const double dr = f.options().cell_m / 4;
  double num = 0, den = 0;
  for (double r = r_min; r <= r_max; r += dr) {
    const double v = f.interpolate(cx + r * std::cos(theta), cy + r * std::sin(theta));
    num += r * v * v;
    den += v * v;
  }
  return den > 0 ? num / den : 0;
}
}  // namespace

RingTest ring_test(const Stencil& stencil, const RingTestOptions& o) {
  RingTest r;
  const int n = o.n;
  r.cell_m = 1.0 / n;
  HeightFieldOptions ho;
  ho.nx = ho.ny = n;
  ho.cell_m = r.cell_m;
  const long steps = std::lround(o.t_s / (o.sigma * r.cell_m));
  ho.dt_s = o.t_s / steps;
  ho.stencil = stencil;
  Disturbance d;
  d.kind = DisturbanceKind::gaussian;
  d.amplitude_m = 0.01;
  d.width_m = o.width_m;
  d.x_m = d.y_m = 0.5;
  std::vector<double> z0, zr;
  sample_disturbance(d, n, n, r.cell_m, z0);
  HeightField f(ho);
  f.set_state(z0);
  CpuTimer timer;
  f.advance(steps);
  r.cpu_s = timer.seconds();
  // The continuum reference, sampled through a height field holding its values (same interpolation).
  SpectralWaveOptions so;
  so.nx = so.ny = n;
  so.cell_m = r.cell_m;
  SpectralWave ref(so);
  ref.set_initial(z0);
  ref.evaluate(f.time_s(), zr);
  HeightField g(ho);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) g.set_height(i, j, zr[static_cast<std::size_t>(j) * n + i]);
  const double r_min = 0.6 * o.t_s, r_max = std::min(0.48, 1.4 * o.t_s);
  double lo = 1e300, hi = -1e300;
  for (int a = 0; a < o.angles; ++a) {
    const double th = 0.5 * M_PI * a / (o.angles - 1);
    r.theta_rad.push_back(th);
    const double rc = front_radius(f, 0.5, 0.5, th, r_min, r_max);
    r.front_radius_m.push_back(rc);
    r.reference_front_radius_m.push_back(front_radius(g, 0.5, 0.5, th, r_min, r_max));
    lo = std::min(lo, rc);
    hi = std::max(hi, rc);
  }
  r.spread_m = hi - lo;
  return r;
}

}  // namespace stoneskip
