#include "solvers/spectral/forced_wave.hpp"

#include <cmath>
#include <stdexcept>


namespace stoneskip {

double MovingGaussianDraught::envelope(double t_s) const {
  if (t_s <= 0) return 0;
  const double u = t_s / rise_s;
  return -std::expm1(-u * u);
}

void MovingGaussianDraught::sample(double t_s, int nx, int ny, double cell_m, std::vector<double>& b) const {
  // The Gaussian and its image sum separate in x and y: Σ_p Σ_q g(x + pL) g(y + qL) = gx(x) gy(y).
  const double lx = nx * cell_m, ly = ny * cell_m;
  double xc = x0_m + vx_m_s * t_s, yc = y0_m + vy_m_s * t_s;
  xc -= lx * std::floor(xc / lx);  // keep the centre in the domain so that ±1 image covers it
  yc -= ly * std::floor(yc / ly);
  auto images = [&](int n, double centre, double period, std::vector<double>& g) {
    g.resize(n);
    for (int i = 0; i < n; ++i) {
      double s = 0;
      for (int p = -1; p <= 1; ++p) {
        const double u = (i * cell_m - centre + p * period) / width_m;
        s += std::exp(-u * u);
      }
      g[i] = s;
    }
  };
  std::vector<double> gx, gy;
  images(nx, xc, lx, gx);
  images(ny, yc, ly, gy);
  const double a = depth_m * envelope(t_s);
  b.resize(static_cast<std::size_t>(nx) * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) b[static_cast<std::size_t>(j) * nx + i] = a * gx[i] * gy[j];
}

void MovingGaussianDraught::sample_walled(double t_s, int nx, int ny, double cell_m, double first_x_m, double first_y_m,
                                          std::vector<double>& b) const {
  const double xc = x0_m + vx_m_s * t_s, yc = y0_m + vy_m_s * t_s, a = depth_m * envelope(t_s);
  std::vector<double> gx(static_cast<std::size_t>(nx)), gy(static_cast<std::size_t>(ny));
  for (int i = 0; i < nx; ++i) gx[i] = std::exp(-std::pow((first_x_m + i * cell_m - xc) / width_m, 2));
  for (int j = 0; j < ny; ++j) gy[j] = std::exp(-std::pow((first_y_m + j * cell_m - yc) / width_m, 2));
  b.resize(static_cast<std::size_t>(nx) * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) b[static_cast<std::size_t>(j) * nx + i] = a * gx[i] * gy[j];
}

DraughtField MovingGaussianDraught::on_grid(int nx, int ny, double cell_m) const {
  const MovingGaussianDraught copy = *this;
  return [copy, nx, ny, cell_m](double t_s, std::vector<double>& b) { copy.sample(t_s, nx, ny, cell_m, b); };
}

ForcedSpectralWave::ForcedSpectralWave(const SpectralWaveOptions& options, DraughtField draught,
                                       const DuhamelQuadrature& quadrature)
    : free_(options), draught_(std::move(draught)), quadrature_(quadrature) {
  if (!draught_) throw std::invalid_argument("ForcedSpectralWave: no draught");
  if (quadrature.intervals < 1 || quadrature.nodes < 1)
    throw std::invalid_argument("ForcedSpectralWave: quadrature needs intervals, nodes >= 1");
  const std::size_t n = static_cast<std::size_t>(options.nx) * options.ny;
  free_.set_initial(std::vector<double>(n, 0.0));
}

void ForcedSpectralWave::set_initial(const std::vector<double>& z0, const std::vector<double>& v0) {
  free_.set_initial(z0, v0);
}

void ForcedSpectralWave::evaluate(double t_s, std::vector<double>& z) {
  free_.evaluate_spectrum(t_s, spectrum_);
  // Spec §2.5: ∫₀ᵗ G(t − s) (−λ b̂(s)) ds, node by node.
  transforms_ += add_duhamel_integral(
      t_s, free_.lambdas(), free_.options().damping_per_s, quadrature_, draught_,
      [this](const std::vector<double>& b, std::vector<std::complex<double>>& b_hat) { free_.transform(b, b_hat); }, spectrum_,
      b_, b_hat_);
  free_.synthesise(spectrum_, z);
}

}  // namespace stoneskip
