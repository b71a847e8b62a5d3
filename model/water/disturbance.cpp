#include "model/water/disturbance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace stoneskip {

const char* to_string(DisturbanceKind k) {
  switch (k) {
    case DisturbanceKind::gaussian: return "gaussian";
    case DisturbanceKind::plane_wave: return "plane_wave";
    case DisturbanceKind::ring: return "ring";
    case DisturbanceKind::impulse: return "impulse";
  }
  return "?";
}

bool parse_disturbance_kind(const std::string& s, DisturbanceKind& out) {
  for (auto k : {DisturbanceKind::gaussian, DisturbanceKind::plane_wave, DisturbanceKind::ring, DisturbanceKind::impulse})
    if (s == to_string(k)) {
      out = k;
      return true;
    }
  return false;
}

namespace {

// Every image beyond this many widths from a cell adds less than e^-42 (6e-19) of the peak.
constexpr double kReachWidths = 6.5;

// Images needed on each side: with the centre and the cells in [0, L), image p lies at least
// (|p| − 1) L from every cell, so |p| ≤ ⌈reach / L⌉ + 1 holds every image within `reach`.
int images_each_side(double reach_m, double period_m) { return static_cast<int>(std::ceil(reach_m / period_m)) + 1; }

// x wrapped into [0, L).
double wrapped(double x, double period) {
  const double w = x - period * std::floor(x / period);
  return w >= period ? 0.0 : w;
}

// Σ_p exp(−((u + pL)/w)²), the periodic sum of a 1-D Gaussian (u = x − centre, both in [0, L)).
// Narrow (w ≤ L): directly, at most 9 images each side. Wide: by Poisson summation (Σ_p f(u + pL)
// = (1/L) Σ_k f̂(k/L) e^{2πiku/L}, with f̂(ν) = √π w e^{−(π w ν)²}; e.g. Stein & Shakarchi,
// Fourier Analysis, ch. 5 §3), (√π w / L) [1 + 2 Σ_k exp(−(π k w / L)²) cos(2π k u / L)], whose
// terms fall below e^-43 by k = 3.
double periodic_gaussian(double u, double width, double period) {
  if (width <= period) {
    const int n = images_each_side(kReachWidths * width, period);
    double s = 0;
    for (int p = -n; p <= n; ++p) {
      const double v = (u + p * period) / width;
      s += std::exp(-v * v);
    }
    return s;
  }
  double s = 1;
  for (int k = 1;; ++k) {
    const double a = M_PI * k * width / period;
    if (a * a > 43) break;
    s += 2 * std::exp(-a * a) * std::cos(2 * M_PI * k * u / period);
  }
  return std::sqrt(M_PI) * width / period * s;
}

}  // namespace

double gaussian_image_peak_m(const Disturbance& d, double lx_m, double ly_m) {
  if (d.kind != DisturbanceKind::gaussian) return 0;
  return std::abs(d.amplitude_m) * periodic_gaussian(0, d.width_m, lx_m) * periodic_gaussian(0, d.width_m, ly_m);
}

std::string disturbance_image_problem(const Disturbance& d, double lx_m, double ly_m, double max_height_m) {
  if (d.kind == DisturbanceKind::gaussian) {
    // The sum peaks at the centre: A Sx(0) Sy(0), about A π w² / (Lx Ly) once w is past the grid.
    const double peak = gaussian_image_peak_m(d, lx_m, ly_m);
    // Refused only where the images add materially: |A| itself may reach the bound, and a bump a
    // fifth of the grid wide adds 3e-11 of it.
    if (!(peak <= max_height_m * (1 + 1e-6))) {
      char b[320];
      std::snprintf(b, sizeof b,
                    "a Gaussian of width_m %.6g on the %.6g m x %.6g m grid sums with its periodic images to a surface "
                    "%.7g m high, above the %.7g m that amplitude_m may reach: narrow it",
                    d.width_m, lx_m, ly_m, peak, max_height_m);
      return b;
    }
    return "";
  }
  if (d.kind != DisturbanceKind::ring) return "";
  const double reach = d.radius_m + kReachWidths * d.width_m;
  if (images_each_side(reach, lx_m) <= kMostRingImages && images_each_side(reach, ly_m) <= kMostRingImages) return "";
  char b[320];
  std::snprintf(b, sizeof b,
                "a ring of radius_m + 6.5 width_m = %.6g m reaches past %d periods of the %.6g m x %.6g m grid: its "
                "periodic images cannot be summed (keep radius_m + 6.5 width_m within %.6g m)",
                reach, kMostRingImages - 1, lx_m, ly_m, (kMostRingImages - 1) * std::min(lx_m, ly_m));
  return b;
}

std::string resample_problem(const Disturbance& d) {
  if (d.kind == DisturbanceKind::impulse)
    return "an impulse is one cell's height, not a surface that another grid can sample: give a gaussian, a ring or a plane_wave";
  return "";
}

void sample_disturbance(const Disturbance& d, int nx, int ny, double cell_m, std::vector<double>& z) {
  if (d.kind == DisturbanceKind::impulse) {
    z.assign(static_cast<std::size_t>(nx) * ny, 0.0);
    int i = static_cast<int>(std::lround(d.x_m / cell_m)), j = static_cast<int>(std::lround(d.y_m / cell_m));
    i = ((i % nx) + nx) % nx;
    j = ((j % ny) + ny) % ny;
    z[static_cast<std::size_t>(j) * nx + i] = d.amplitude_m;
    return;
  }
  sample_disturbance_at(d, nx * cell_m, ny * cell_m, 0.0, 0.0, nx, ny, cell_m, z);
}

void sample_disturbance_at(const Disturbance& d, double lx, double ly, double x0, double y0, int nx, int ny, double cell_m,
                           std::vector<double>& z) {
  if (const std::string why = resample_problem(d); !why.empty()) throw std::invalid_argument(why);
  z.assign(static_cast<std::size_t>(nx) * ny, 0.0);
  auto at = [&](int i, int j) -> double& { return z[static_cast<std::size_t>(j) * nx + i]; };
  // The points in the own grid's frame, wrapped into it (once each, not per image): with x0 = 0 and
  // i cell_m < lx, exactly i cell_m.
  std::vector<double> px(static_cast<std::size_t>(nx)), py(static_cast<std::size_t>(ny));
  for (int i = 0; i < nx; ++i) px[static_cast<std::size_t>(i)] = wrapped(x0 + i * cell_m, lx);
  for (int j = 0; j < ny; ++j) py[static_cast<std::size_t>(j)] = wrapped(y0 + j * cell_m, ly);
  switch (d.kind) {
    case DisturbanceKind::impulse: return;  // refused above
    case DisturbanceKind::plane_wave: {
      // z = A cos(k·x) at the point itself (not wrapped: the cosine need not fit the own grid's period).
      const double k = 2 * M_PI / d.wavelength_m, th = d.angle_deg * M_PI / 180;
      const double kx = k * std::cos(th), ky = k * std::sin(th);
      const double phase = kx * x0 + ky * y0;  // 0 on the own grid: the sum below is then unchanged
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) at(i, j) = d.amplitude_m * std::cos(kx * i * cell_m + ky * j * cell_m + phase);
      return;
    }
    case DisturbanceKind::gaussian: {
      // exp(−(dx² + dy²)/w²) = exp(−dx²/w²) exp(−dy²/w²): the image sum is a product of two
      // periodic 1-D sums. The centre is wrapped into the grid, so that the images are counted from it.
      const double xc = wrapped(d.x_m, lx), yc = wrapped(d.y_m, ly);
      std::vector<double> gx(static_cast<std::size_t>(nx)), gy(static_cast<std::size_t>(ny));
      for (int i = 0; i < nx; ++i) gx[static_cast<std::size_t>(i)] = periodic_gaussian(px[static_cast<std::size_t>(i)] - xc, d.width_m, lx);
      for (int j = 0; j < ny; ++j) gy[static_cast<std::size_t>(j)] = periodic_gaussian(py[static_cast<std::size_t>(j)] - yc, d.width_m, ly);
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) at(i, j) = d.amplitude_m * gx[static_cast<std::size_t>(i)] * gy[static_cast<std::size_t>(j)];
      return;
    }
    case DisturbanceKind::ring: {
      const double xc = wrapped(d.x_m, lx), yc = wrapped(d.y_m, ly);
      const double reach = d.radius_m + kReachWidths * d.width_m;
      const int nx_images = std::min(images_each_side(reach, lx), kMostRingImages);
      const int ny_images = std::min(images_each_side(reach, ly), kMostRingImages);
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          double sum = 0;
          for (int qy = -ny_images; qy <= ny_images; ++qy)
            for (int qx = -nx_images; qx <= nx_images; ++qx) {
              const double dx = px[static_cast<std::size_t>(i)] - xc + qx * lx, dy = py[static_cast<std::size_t>(j)] - yc + qy * ly;
              const double u = (std::sqrt(dx * dx + dy * dy) - d.radius_m) / d.width_m;
              sum += std::exp(-u * u);
            }
          at(i, j) = d.amplitude_m * sum;
        }
      return;
    }
  }
}

}  // namespace stoneskip
