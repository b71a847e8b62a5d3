#pragma once
// The exact reference for the periodic damped wave equation with a prescribed draught (model/README.md §2.5):
//   z_tt = c² ∇²(z + b) − μ z_t,  b = b(x, y, t) given,
// one Fourier mode at a time: ẑ'' + μ ẑ' + λ ẑ = −λ b̂(t), λ = c²|k|² (continuum) or the
// stencil's −c² symbol/d² (the exact semi-discrete solution of that stencil, as for the free
// reference). Its solution is the free one (solvers/spectral/spectral_wave.hpp) plus the Duhamel
// integral
//   ẑ_forced(t) = ∫₀ᵗ G(t − s) (−λ b̂(s)) ds,  G(τ) = e^{−μτ/2} S(τ)
// (G is the free mode started with ẑ = 0, ẑ' = 1: damped_mode(λ, μ, τ).gv), evaluated by
// Gauss–Legendre quadrature on equal sub-intervals of [0, t], one FFT of b per node. For a b smooth
// in time the quadrature converges to round-off as the sub-intervals are refined (geometrically,
// once a sub-interval spans less than about a period of the fastest mode that b excites).
#include <complex>
#include <functional>
#include <vector>

#include "solvers/spectral/duhamel.hpp"
#include "solvers/spectral/spectral_wave.hpp"

namespace stoneskip {

// A prescribed draught of model/README.md §2.5: a Gaussian patch b = depth · e(t) · exp(−|x − x_c(t)|²/w²)
// (summed over the neighbouring periodic images, as model/water/disturbance.hpp does for a bump),
// its centre moving at constant velocity, x_c(t) = x0 + v t, under the smooth envelope
// e(t) = 1 − exp(−(t/rise)²): e(0) = e'(0) = 0, so a run started at rest is smooth from t = 0.
struct MovingGaussianDraught {
  double depth_m = 0.005;
  double width_m = 0.1;
  double x0_m = 0.3, y0_m = 0.4;
  double vx_m_s = 0.4, vy_m_s = 0.2;
  double rise_s = 0.1;

  double envelope(double t_s) const;
  // b on the cell points x_i = i d, y_j = j d of an nx × ny grid that tiles the plane periodically.
  void sample(double t_s, int nx, int ny, double cell_m, std::vector<double>& b) const;
  // b on the points x_i = first_x + i d, y_j = first_y + j d of a walled pond: the Gaussian alone, no images.
  void sample_walled(double t_s, int nx, int ny, double cell_m, double first_x_m, double first_y_m, std::vector<double>& b) const;
  DraughtField on_grid(int nx, int ny, double cell_m) const;
};

class ForcedSpectralWave {
 public:
  // options: the grid, c, μ and the symbol (continuum or a stencil's), as for SpectralWave.
  ForcedSpectralWave(const SpectralWaveOptions& options, DraughtField draught, const DuhamelQuadrature& quadrature);

  // Free initial state (empty v0: at rest).
  void set_initial(const std::vector<double>& z0, const std::vector<double>& v0 = {});
  // The exact solution at t into z (nx·ny): free part plus the Duhamel integral.
  void evaluate(double t_s, std::vector<double>& z);
  // FFTs of b taken so far (the reference's cost: intervals × nodes per evaluate).
  long draught_transforms() const { return transforms_; }

 private:
  SpectralWave free_;
  DraughtField draught_;
  DuhamelQuadrature quadrature_;
  long transforms_ = 0;
  std::vector<double> b_;
  std::vector<std::complex<double>> b_hat_, spectrum_;
};

}  // namespace stoneskip
