#include "solvers/scene/wave_energy.hpp"

#include <cmath>
#include <complex>
#include <numbers>

#include <fftw3.h>

namespace stoneskip {

WaveEnergy::WaveEnergy(const HeightFieldOptions& o, double rho_g)
    : nx_(o.nx), ny_(o.ny), mx_(o.boundary == Boundary::periodic ? o.nx / 2 + 1 : o.nx), cell_m_(o.cell_m),
      c_(o.wave_speed_m_s), mu_(o.damping_per_s), dt_s_(o.dt_s), rho_g_(rho_g),
      periodic_(o.boundary == Boundary::periodic), fixed_(o.boundary == Boundary::fixed), available_(o.wave_speed_m_s > 0) {
  if (!available_) return;
  const std::size_t modes = static_cast<std::size_t>(mx_) * ny_;
  inverse_lambda_.assign(modes, 0);
  weight_.assign(modes, 0);
  grid_scale_.assign(modes, 0);
  const double pi = std::numbers::pi;
  for (int my = 0; my < ny_; ++my)
    for (int mx = 0; mx < mx_; ++mx) {
      const std::size_t k = static_cast<std::size_t>(my) * mx_ + mx;
      double a, b, w;
      if (periodic_) {
        // r2c: Σ x² = (1/(nx ny)) Σ over all modes |X|²; the stored half counts twice except at
        // kx = 0 and kx = nx/2.
        a = 2 * pi * mx / nx_;
        b = 2 * pi * std::min(my, ny_ - my) / ny_;
        const bool self = mx == 0 || (nx_ % 2 == 0 && mx == nx_ / 2);
        w = (self ? 1.0 : 2.0) / (static_cast<double>(nx_) * ny_);
      } else if (fixed_) {
        // DST-I (FFTW RODFT00, X_m = 2 Σ x_i sin(π (m + 1)(i + 1)/(N + 1))) diagonalises a symmetric
        // stencil with zero ghosts (solvers/spectral/walled_wave.hpp); Σ x² = Π over axes of
        // (1/(2(N + 1))) Σ X_m². No mode is neutral: −L is positive definite there.
        a = pi * (mx + 1) / (nx_ + 1);
        b = pi * (my + 1) / (ny_ + 1);
        w = 1.0 / (2.0 * (nx_ + 1)) / (2.0 * (ny_ + 1));
      } else {
        // DCT-II (FFTW REDFT10, X_m = 2 Σ x_i cos(π m (i + ½)/N)) diagonalises a symmetric
        // stencil with mirror ghosts; Σ x² = Π over axes of (1/(2N)) (X_0²/2 + Σ_{m≥1} X_m²).
        a = pi * mx / nx_;
        b = pi * my / ny_;
        w = (mx == 0 ? 0.5 : 1.0) / (2.0 * nx_) * (my == 0 ? 0.5 : 1.0) / (2.0 * ny_);
      }
      weight_[k] = w;
      const double lambda = -o.stencil.symbol(a, b) / (cell_m_ * cell_m_);  // eigenvalue of −L
      inverse_lambda_[k] = (!fixed_ && mx == 0 && my == 0) || !(lambda > 0) ? 0.0 : 1.0 / lambda;
      grid_scale_[k] = std::hypot(a, b) > pi / 2;
    }
  buffer_.assign(static_cast<std::size_t>(nx_) * ny_, 0);
  if (periodic_) {
    auto* out = fftw_alloc_complex(modes);
    out_ = out;
    plan_ = fftw_plan_dft_r2c_2d(ny_, nx_, buffer_.data(), out, FFTW_ESTIMATE);
  } else {
    work_.assign(static_cast<std::size_t>(nx_) * ny_, 0);
    const fftw_r2r_kind kind = fixed_ ? FFTW_RODFT00 : FFTW_REDFT10;
    plan_ = fftw_plan_r2r_2d(ny_, nx_, buffer_.data(), work_.data(), kind, kind, FFTW_ESTIMATE);
  }
}

WaveEnergy::~WaveEnergy() {
  if (plan_) fftw_destroy_plan(static_cast<fftw_plan>(plan_));
  if (out_) fftw_free(out_);
}

void WaveEnergy::transform(const std::vector<double>& in, std::vector<double>& re, std::vector<double>& im) {
  const std::size_t modes = static_cast<std::size_t>(mx_) * ny_;
  buffer_ = in;
  fftw_execute(static_cast<fftw_plan>(plan_));
  re.resize(modes);
  im.assign(modes, 0);
  if (periodic_) {
    const auto* out = static_cast<const fftw_complex*>(out_);
    for (std::size_t k = 0; k < modes; ++k) {
      re[k] = out[k][0];
      im[k] = out[k][1];
    }
  } else {
    re = work_;
  }
}

WaveEnergyReading WaveEnergy::energy(const HeightField& field) {
  WaveEnergyReading r;
  if (!available_) return r;
  std::vector<double> z_now(static_cast<std::size_t>(nx_) * ny_), z_next;
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) z_now[static_cast<std::size_t>(j) * nx_ + i] = field.previous_height(i, j);
  field.heights(z_next);
  std::vector<double> v(z_next.size());
  for (std::size_t k = 0; k < v.size(); ++k) v[k] = (z_next[k] - z_now[k]) / dt_s_;
  transform(v, re_a_, im_a_);
  std::vector<double> vr = re_a_, vi = im_a_;
  transform(z_now, re_a_, im_a_);
  transform(z_next, re_b_, im_b_);
  const double scale = rho_g_ * cell_m_ * cell_m_;
  for (std::size_t k = 0; k < weight_.size(); ++k) {
    const double kinetic = (vr[k] * vr[k] + vi[k] * vi[k]) * inverse_lambda_[k] / (2 * c_ * c_);
    const double potential = 0.5 * (re_a_[k] * re_b_[k] + im_a_[k] * im_b_[k]);
    const double e = scale * weight_[k] * (kinetic + potential);
    r.total_J += e;
    if (grid_scale_[k]) r.grid_scale_J += e;
  }
  return r;
}

double WaveEnergy::damping_loss_J(const std::vector<double>& before, const std::vector<double>& after) {
  if (!available_ || mu_ == 0) return 0;
  std::vector<double> w(before.size());
  for (std::size_t k = 0; k < w.size(); ++k) w[k] = (after[k] - before[k]) / (2 * dt_s_);
  transform(w, re_a_, im_a_);
  double s = 0;
  for (std::size_t k = 0; k < weight_.size(); ++k)
    s += weight_[k] * (re_a_[k] * re_a_[k] + im_a_[k] * im_a_[k]) * inverse_lambda_[k];
  return rho_g_ * cell_m_ * cell_m_ * mu_ * dt_s_ * s / (c_ * c_);
}

}  // namespace stoneskip
