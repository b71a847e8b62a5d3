#include "solvers/spectral/spectral_wave.hpp"

#include <fftw3.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "solvers/spectral/damped_mode.hpp"

namespace stoneskip {

struct SpectralWave::Plans {
  double* real = nullptr;
  fftw_complex* spec = nullptr;
  fftw_plan forward = nullptr, backward = nullptr;
  Plans(int nx, int ny) {
    const int nxc = nx / 2 + 1;
    real = fftw_alloc_real(static_cast<std::size_t>(nx) * ny);
    spec = fftw_alloc_complex(static_cast<std::size_t>(nxc) * ny);
    // FFTW's 2-D arrays are row-major with the last index fastest: n0 = ny, n1 = nx.
    forward = fftw_plan_dft_r2c_2d(ny, nx, real, spec, FFTW_ESTIMATE);
    backward = fftw_plan_dft_c2r_2d(ny, nx, spec, real, FFTW_ESTIMATE);
    if (!real || !spec || !forward || !backward) throw std::runtime_error("FFTW: could not create plans");
  }
  ~Plans() {
    if (forward) fftw_destroy_plan(forward);
    if (backward) fftw_destroy_plan(backward);
    fftw_free(real);
    fftw_free(spec);
  }
};

SpectralWaveOptions spectral_wave_options(const HeightFieldOptions& field, SpectralSymbol symbol) {
  SpectralWaveOptions o;
  o.nx = field.nx;
  o.ny = field.ny;
  o.cell_m = field.cell_m;
  o.wave_speed_m_s = field.wave_speed_m_s;
  o.damping_per_s = field.damping_per_s;
  o.symbol = symbol;
  o.stencil = field.stencil;
  return o;
}

SpectralWave::SpectralWave(const SpectralWaveOptions& options)
    : options_(options), nxc_(options.nx / 2 + 1), plans_(std::make_unique<Plans>(options.nx, options.ny)) {
  const int nx = options.nx, ny = options.ny;
  const double d = options.cell_m, c2 = options.wave_speed_m_s * options.wave_speed_m_s;
  const double symbol_roundoff = options.stencil.symbol_roundoff();
  lambda_.resize(static_cast<std::size_t>(nxc_) * ny);
  for (int j = 0; j < ny; ++j) {
    const int mj = j <= ny / 2 ? j : j - ny;  // signed wave number index
    for (int i = 0; i < nxc_; ++i) {
      const double kx = 2 * M_PI * i / (nx * d), ky = 2 * M_PI * mj / (ny * d);
      double lam = c2 * (kx * kx + ky * ky);
      if (options.symbol != SpectralSymbol::continuum) {
        // A symbol within round-off of 0 is the neutral s = 0, as in the stability analysis
        // (model/water/stability.cpp): nine_point_isotropic's s(0, 0) = +1.1e-16 made the mean
        // mode grow as cosh(√1.1e-16 ct/d), 28 m on a 314 m uniform field after 8e7 steps.
        double s = options.stencil.symbol(kx * d, ky * d);
        if (std::abs(s) <= symbol_roundoff) s = 0;
        lam = -c2 * s / (d * d);
      }
      lambda_[static_cast<std::size_t>(j) * nxc_ + i] = lam;
    }
  }
  z0_hat_.assign(lambda_.size(), 0.0);
  v0_hat_.assign(lambda_.size(), 0.0);
}

SpectralWave::~SpectralWave() = default;

double SpectralWave::lambda(int i, int j) const { return lambda_[static_cast<std::size_t>(j) * nxc_ + i]; }

void SpectralWave::transform(const std::vector<double>& field, std::vector<std::complex<double>>& spectrum) {
  const std::size_t n = static_cast<std::size_t>(options_.nx) * options_.ny;
  if (field.size() != n) throw std::invalid_argument("SpectralWave: wrong field size");
  std::memcpy(plans_->real, field.data(), n * sizeof(double));
  fftw_execute(plans_->forward);
  spectrum.resize(lambda_.size());
  std::memcpy(reinterpret_cast<void*>(spectrum.data()), plans_->spec, spectrum.size() * sizeof(fftw_complex));
}

void SpectralWave::synthesise(const std::vector<std::complex<double>>& spectrum, std::vector<double>& field) {
  const std::size_t n = static_cast<std::size_t>(options_.nx) * options_.ny;
  if (spectrum.size() != lambda_.size()) throw std::invalid_argument("SpectralWave: wrong spectrum size");
  std::memcpy(reinterpret_cast<void*>(plans_->spec), spectrum.data(), spectrum.size() * sizeof(fftw_complex));
  fftw_execute(plans_->backward);  // unnormalised: divide by nx·ny
  field.resize(n);
  const double scale = 1.0 / static_cast<double>(n);
  for (std::size_t k = 0; k < n; ++k) field[k] = plans_->real[k] * scale;
}

void SpectralWave::set_initial(const std::vector<double>& z0, const std::vector<double>& v0) {
  const std::size_t n = static_cast<std::size_t>(options_.nx) * options_.ny;
  if (z0.size() != n || (!v0.empty() && v0.size() != n)) throw std::invalid_argument("SpectralWave: wrong field size");
  transform(z0, z0_hat_);
  if (v0.empty())
    std::fill(v0_hat_.begin(), v0_hat_.end(), 0.0);
  else
    transform(v0, v0_hat_);
}

void SpectralWave::evaluate_spectrum(double t_s, std::vector<std::complex<double>>& spectrum) const {
  spectrum.resize(lambda_.size());
  for (std::size_t k = 0; k < lambda_.size(); ++k) {
    const DampedModeFactors f = damped_mode(lambda_[k], options_.damping_per_s, t_s);
    spectrum[k] = f.gz * z0_hat_[k] + f.gv * v0_hat_[k];
  }
}

void SpectralWave::evaluate(double t_s, std::vector<double>& z) {
  evaluate_spectrum(t_s, work_);
  synthesise(work_, z);
}

}  // namespace stoneskip
