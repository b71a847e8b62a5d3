#pragma once
// The exact reference for the damped wave equation z_tt = c²∇²z − μ z_t (model/README.md §2.3) in a
// walled pond, the boundaries of model/water/height_field.hpp other than periodic:
//   reflecting: the ghost cells mirror the edge cells (z₋₁ = z₀), so the walls stand half a cell
//     outside the edge points, at x = −d/2 and (nx − ½)d, with zero normal slope. The fields are
//     sums of cos(πm(i + ½)/nx), m = 0 … nx − 1 (FFTW's REDFT10; its inverse is REDFT01);
//   fixed: the ghost cells hold 0, so the rim (z = 0) stands one cell outside the edge points, at
//     x = −d and nx·d. The fields are sums of sin(πm(i + 1)/(nx + 1)), m = 1 … nx (RODFT00, its
//     own inverse).
// Both in y alike. Each such product is the even (reflecting) or odd (fixed) extension of the
// field to a periodic one of period 2nx or 2(nx + 1), and on it every symmetric 9-point stencil with
// those ghosts (corner ghosts included) acts as on the periodic grid: the mode is an eigenvector
// with the stencil's symbol at k d = πm/nx or πm/(nx + 1) (model/water/stencil.hpp). So, as for
// SpectralWave, each mode is advanced exactly in time (solvers/spectral/damped_mode.hpp): with the
// continuum symbol λ = c²|k|² the result is the walled continuum solution for the sampled initial
// field; with the stencil's own symbol, the exact solution of the stencil's semi-discrete system
// with these walls, so a leapfrog run minus it is the time error alone.
#include <memory>
#include <vector>

#include "model/water/height_field.hpp"
#include "model/water/stencil.hpp"
#include "solvers/spectral/spectral_wave.hpp"

namespace stoneskip {

struct WalledWaveOptions {
  int nx = 64, ny = 64;
  double cell_m = 1.0 / 64;
  double wave_speed_m_s = 1;
  double damping_per_s = 0;
  Boundary boundary = Boundary::reflecting;  // reflecting or fixed (periodic: SpectralWave)
  SpectralSymbol symbol = SpectralSymbol::continuum;
  Stencil stencil;  // used when symbol == stencil
};

// The reference's options for a height field's grid, wave speed, damping, walls and stencil.
WalledWaveOptions walled_wave_options(const HeightFieldOptions& field, SpectralSymbol symbol);

class WalledWave {
 public:
  // Throws std::invalid_argument for a periodic boundary or a grid smaller than 1 × 1.
  explicit WalledWave(const WalledWaveOptions& options);
  ~WalledWave();
  WalledWave(const WalledWave&) = delete;
  WalledWave& operator=(const WalledWave&) = delete;

  // z0, v0: row-major, x fastest, size nx·ny (empty v0: at rest).
  void set_initial(const std::vector<double>& z0, const std::vector<double>& v0 = {});
  // The exact solution at time t into z (resized to nx·ny).
  void evaluate(double t_s, std::vector<double>& z);
  // The wave number of mode m along an axis of n points (1/m): πm/(n d) reflecting, π(m + 1)/((n + 1) d) fixed.
  double wave_number(int m, int n) const;
  // The share of the initial surface's RMS (set_initial's z0) in the upper half of the modes along
  // either axis (m ≥ n/2: waves of under four cells): 0 for a surface the grid resolves, near 1 for
  // grid-scale noise; a surface that meets a wall with a kink (reflecting) or a step (fixed) puts a
  // slowly falling tail there. By Parseval: Σ z² = Σ w_m X_m² / (2n), w_0 = ½ for REDFT10, else 1.
  double upper_half_fraction() const;
  // λ of mode (i, j), i < nx, j < ny.
  double lambda(int i, int j) const { return lambda_[static_cast<std::size_t>(j) * options_.nx + i]; }

  // The pieces of evaluate(), for references built on this one (solvers/spectral/forced_walled_wave.hpp).
  // Modes: index j·nx + i, unnormalised as FFTW's forward transform gives them.
  const std::vector<double>& lambdas() const { return lambda_; }
  const WalledWaveOptions& options() const { return options_; }
  void evaluate_modes(double t_s, std::vector<double>& modes) const;  // the free solution's modes at t
  void transform(const std::vector<double>& field, std::vector<double>& modes);
  void synthesise(const std::vector<double>& modes, std::vector<double>& field);  // normalised

 private:
  WalledWaveOptions options_;
  std::vector<double> lambda_, z0_hat_, v0_hat_, work_;
  struct Plans;
  std::unique_ptr<Plans> plans_;
};

}  // namespace stoneskip
