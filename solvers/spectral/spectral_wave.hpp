#pragma once
// The exact reference for the periodic damped wave equation z_tt = c²∇²z − μ z_t (model/README.md §2.3):
// the initial fields are transformed once (FFTW r2c), every Fourier mode is advanced exactly in
// time (solvers/spectral/damped_mode.hpp) and transformed back (c2r). With the continuum symbol
// λ = c²|k|² this is exact in time and spectrally accurate in space; with a stencil's own symbol
// λ = −c² symbol(kx d, ky d)/d² it is the exact solution of the semi-discrete (method-of-lines)
// system of that stencil, so a leapfrog run minus it is the time error alone.
#include <complex>
#include <memory>
#include <vector>

#include "model/water/height_field.hpp"
#include "model/water/stencil.hpp"

namespace stoneskip {

enum class SpectralSymbol { continuum, stencil };

struct SpectralWaveOptions {
  int nx = 64, ny = 64;
  double cell_m = 1.0 / 64;
  double wave_speed_m_s = 1;
  double damping_per_s = 0;
  SpectralSymbol symbol = SpectralSymbol::continuum;
  Stencil stencil;  // used when symbol == stencil
};

// The reference's options for a height field's grid, wave speed, damping and stencil (its
// boundary is the caller's to check: this reference is the periodic one).
SpectralWaveOptions spectral_wave_options(const HeightFieldOptions& field, SpectralSymbol symbol);

class SpectralWave {
 public:
  explicit SpectralWave(const SpectralWaveOptions& options);
  ~SpectralWave();
  SpectralWave(const SpectralWave&) = delete;
  SpectralWave& operator=(const SpectralWave&) = delete;

  // z0, v0: row-major, x fastest, size nx·ny (empty v0: at rest).
  void set_initial(const std::vector<double>& z0, const std::vector<double>& v0 = {});
  // The exact solution at time t into z (resized to nx·ny).
  void evaluate(double t_s, std::vector<double>& z);
  // λ of the mode (i, j) of the r2c layout (i < nx/2 + 1, j < ny).
  double lambda(int i, int j) const;

  // The pieces of evaluate(), for references built on this one (solvers/spectral/forced_wave.hpp).
  // Modes in the r2c layout: index j·(nx/2 + 1) + i.
  const std::vector<double>& lambdas() const { return lambda_; }
  const SpectralWaveOptions& options() const { return options_; }
  // The free solution's spectrum at t (unnormalised, as transform() gives).
  void evaluate_spectrum(double t_s, std::vector<std::complex<double>>& spectrum) const;
  // field (nx·ny) → spectrum (FFTW r2c, unnormalised); spectrum → field (c2r, divided by nx·ny).
  void transform(const std::vector<double>& field, std::vector<std::complex<double>>& spectrum);
  void synthesise(const std::vector<std::complex<double>>& spectrum, std::vector<double>& field);

 private:
  SpectralWaveOptions options_;
  int nxc_;
  std::vector<double> lambda_;
  std::vector<std::complex<double>> z0_hat_, v0_hat_, work_;
  struct Plans;
  std::unique_ptr<Plans> plans_;
};

}  // namespace stoneskip
