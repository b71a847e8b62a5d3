#pragma once
// The fixed physical problem of the wave studies and the two ways of solving it that the studies
// compare: the leapfrog height field and the spectral reference (continuum or semi-discrete).
//   Unit periodic square, c = 1 m/s, μ = 0.5 /s, a Gaussian bump of amplitude 1 cm and width
//   0.1 m at the centre, at rest; the surface at t_end = 0.5 s.
// Errors are RMS over the domain (the discrete L2 norm divided by √area) and the max norm.
#include <string>
#include <cmath>
#include <cstddef>
#include <vector>

#include "model/water/disturbance.hpp"
#include "model/water/height_field.hpp"
#include "solvers/spectral/spectral_wave.hpp"

namespace stoneskip {

struct WaveProblem {
  double length_m = 1;
  double wave_speed_m_s = 1;
  double damping_per_s = 0.5;
  double t_end_s = 0.5;
  Disturbance initial{DisturbanceKind::gaussian, 0.01, 0.1, 0.5, 0.5, 0.2, 0, 0.25};
};

struct FieldError {
  double l2_m = 0;   // RMS of the difference over the domain
  double max_m = 0;  // largest absolute difference
};
FieldError field_error(const std::vector<double>& a, const std::vector<double>& b);

// The RMS of n values x(0) … x(n − 1) without overflow: the plain sum of squares where it is finite
// (the usual case, unchanged to the bit), else the scaled sum of squares of the reference BLAS
// dnrm2 (Hammarling's algorithm: Σ(|x|/scale)² with scale the largest |x| so far, every ratio ≤ 1),
// so a surface of 1e200 m has an RMS of about 1e200 m, not inf. A non-finite value gives inf or NaN.
template <class X>
double root_mean_square(std::size_t n, X x) {
  if (n == 0) return 0;
  double s = 0;
  for (std::size_t k = 0; k < n; ++k) s += x(k) * x(k);
  if (std::isfinite(s)) return std::sqrt(s / static_cast<double>(n));
  double scale = 0, ssq = 1;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = std::abs(x(k));
    if (!std::isfinite(a)) return a;  // inf or NaN: said as such by the caller
    if (a == 0) continue;
    if (scale < a) {
      ssq = 1 + ssq * (scale / a) * (scale / a);
      scale = a;
    } else {
      ssq += (a / scale) * (a / scale);
    }
  }
  return scale * std::sqrt(ssq / static_cast<double>(n));
}
inline double root_mean_square(const std::vector<double>& v) {
  return root_mean_square(v.size(), [&](std::size_t k) { return v[k]; });
}

// The problem's initial surface on an n × n grid.
std::vector<double> initial_surface(const WaveProblem& p, int n);

struct LeapfrogResult {
  std::vector<double> z;  // the surface at the end
  long steps = 0;
  double dt_s = 0;
  double t_s = 0;     // steps · dt
  double cpu_s = 0;   // stepping only
};
// The problem's n × n periodic height field with `steps` equal steps to t_end, and its spectral
// reference's options (continuum symbol, or the stencil's).
HeightFieldOptions leapfrog_options(const WaveProblem& p, const Stencil& stencil, int n, long steps);
SpectralWaveOptions spectral_options(const WaveProblem& p, int n, SpectralSymbol symbol, const Stencil& stencil = {});

// Leapfrog with `steps` equal steps to t_end on an n × n periodic grid.
LeapfrogResult solve_leapfrog(const WaveProblem& p, const Stencil& stencil, int n, long steps);

// The spectral reference at t_end: continuum symbol, or the stencil's (semi-discrete exact).
std::vector<double> solve_spectral(const WaveProblem& p, int n, SpectralSymbol symbol, const Stencil& stencil = {});

}  // namespace stoneskip
