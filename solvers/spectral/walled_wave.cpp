#include "solvers/spectral/walled_wave.hpp"

#include <fftw3.h>

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "solvers/spectral/damped_mode.hpp"

namespace stoneskip {

struct WalledWave::Plans {
  double* real = nullptr;
  double* spec = nullptr;
  fftw_plan forward = nullptr, backward = nullptr;
  Plans(int nx, int ny, Boundary b) {
    const std::size_t n = static_cast<std::size_t>(nx) * ny;
    real = fftw_alloc_real(n);
    spec = fftw_alloc_real(n);
    // FFTW's 2-D arrays are row-major with the last index fastest: n0 = ny, n1 = nx.
    const fftw_r2r_kind fwd = b == Boundary::reflecting ? FFTW_REDFT10 : FFTW_RODFT00;
    const fftw_r2r_kind bwd = b == Boundary::reflecting ? FFTW_REDFT01 : FFTW_RODFT00;
    if (real && spec) {
      forward = fftw_plan_r2r_2d(ny, nx, real, spec, fwd, fwd, FFTW_ESTIMATE);
      backward = fftw_plan_r2r_2d(ny, nx, spec, real, bwd, bwd, FFTW_ESTIMATE);
    }
    if (!real || !spec || !forward || !backward) {
      release();  // a constructor that throws runs no destructor
      throw std::runtime_error("FFTW: could not create plans");
    }
  }
  ~Plans() { release(); }
  void release() {
    if (forward) fftw_destroy_plan(forward);
    if (backward) fftw_destroy_plan(backward);
    fftw_free(real);
    fftw_free(spec);
    forward = backward = nullptr;
    real = spec = nullptr;
  }
};

WalledWaveOptions walled_wave_options(const HeightFieldOptions& field, SpectralSymbol symbol) {
  WalledWaveOptions o;
  o.nx = field.nx;
  o.ny = field.ny;
  o.cell_m = field.cell_m;
  o.wave_speed_m_s = field.wave_speed_m_s;
  o.damping_per_s = field.damping_per_s;
  o.boundary = field.boundary;
  o.symbol = symbol;
  o.stencil = field.stencil;
  return o;
}

WalledWave::WalledWave(const WalledWaveOptions& options) : options_(options) {
  if (options.boundary == Boundary::periodic) throw std::invalid_argument("WalledWave: a periodic grid's reference is SpectralWave");
  if (options.nx < 1 || options.ny < 1) throw std::invalid_argument("WalledWave: the grid needs at least 1 x 1 points");
  plans_ = std::make_unique<Plans>(options.nx, options.ny, options.boundary);
  const int nx = options.nx, ny = options.ny;
  const double d = options.cell_m, c2 = options.wave_speed_m_s * options.wave_speed_m_s;
  const double symbol_roundoff = options.stencil.symbol_roundoff();
  lambda_.resize(static_cast<std::size_t>(nx) * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double kx = wave_number(i, nx), ky = wave_number(j, ny);
      double lam = c2 * (kx * kx + ky * ky);
      if (options.symbol != SpectralSymbol::continuum) {
        double s = options.stencil.symbol(kx * d, ky * d);
        if (std::abs(s) <= symbol_roundoff) s = 0;  // as in SpectralWave: the neutral mode stays neutral
        lam = -c2 * s / (d * d);
      }
      lambda_[static_cast<std::size_t>(j) * nx + i] = lam;
    }
  z0_hat_.assign(lambda_.size(), 0.0);
  v0_hat_.assign(lambda_.size(), 0.0);
}

WalledWave::~WalledWave() = default;

double WalledWave::wave_number(int m, int n) const {
  const double d = options_.cell_m;
  return options_.boundary == Boundary::reflecting ? M_PI * m / (n * d) : M_PI * (m + 1) / ((n + 1) * d);
}

void WalledWave::transform(const std::vector<double>& field, std::vector<double>& modes) {
  const std::size_t n = lambda_.size();
  if (field.size() != n) throw std::invalid_argument("WalledWave: wrong field size");
  std::memcpy(plans_->real, field.data(), n * sizeof(double));
  fftw_execute(plans_->forward);
  modes.assign(plans_->spec, plans_->spec + n);
}

void WalledWave::set_initial(const std::vector<double>& z0, const std::vector<double>& v0) {
  const std::size_t n = lambda_.size();
  if (z0.size() != n || (!v0.empty() && v0.size() != n)) throw std::invalid_argument("WalledWave: wrong field size");
  transform(z0, z0_hat_);
  if (v0.empty())
    std::fill(v0_hat_.begin(), v0_hat_.end(), 0.0);
  else
    transform(v0, v0_hat_);
}

double WalledWave::upper_half_fraction() const {
  const int nx = options_.nx, ny = options_.ny;
  const bool cosines = options_.boundary == Boundary::reflecting;
  double upper = 0, all = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x = z0_hat_[static_cast<std::size_t>(j) * nx + i];
      const double w = (cosines && i == 0 ? 0.5 : 1.0) * (cosines && j == 0 ? 0.5 : 1.0);
      all += w * x * x;
      if (2 * i >= nx || 2 * j >= ny) upper += w * x * x;
    }
  return all > 0 ? std::sqrt(upper / all) : 0.0;
}

void WalledWave::evaluate_modes(double t_s, std::vector<double>& modes) const {
  modes.resize(lambda_.size());
  for (std::size_t k = 0; k < lambda_.size(); ++k) {
    const DampedModeFactors f = damped_mode(lambda_[k], options_.damping_per_s, t_s);
    modes[k] = f.gz * z0_hat_[k] + f.gv * v0_hat_[k];
  }
}

void WalledWave::synthesise(const std::vector<double>& modes, std::vector<double>& z) {
  const std::size_t n = lambda_.size();
  if (modes.size() != n) throw std::invalid_argument("WalledWave: wrong number of modes");
  std::memcpy(plans_->spec, modes.data(), n * sizeof(double));
  fftw_execute(plans_->backward);
  // FFTW's transforms are unnormalised: forward then backward multiplies by 2n (REDFT10/01) or
  // 2(n + 1) (RODFT00) along each axis.
  const double per_axis_x = options_.boundary == Boundary::reflecting ? 2.0 * options_.nx : 2.0 * (options_.nx + 1);
  const double per_axis_y = options_.boundary == Boundary::reflecting ? 2.0 * options_.ny : 2.0 * (options_.ny + 1);
  const double scale = 1.0 / (per_axis_x * per_axis_y);
  z.resize(n);
  for (std::size_t k = 0; k < n; ++k) z[k] = plans_->real[k] * scale;
}

void WalledWave::evaluate(double t_s, std::vector<double>& z) {
  evaluate_modes(t_s, work_);
  synthesise(work_, z);
}

}  // namespace stoneskip
