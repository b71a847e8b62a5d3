#include "model/water/disturbance.hpp"

#include <cmath>

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

void sample_disturbance(const Disturbance& d, int nx, int ny, double cell_m, std::vector<double>& z) {
  z.assign(static_cast<std::size_t>(nx) * ny, 0.0);
  const double lx = nx * cell_m, ly = ny * cell_m;
  auto at = [&](int i, int j) -> double& { return z[static_cast<std::size_t>(j) * nx + i]; };
  switch (d.kind) {
    case DisturbanceKind::impulse: {
      int i = static_cast<int>(std::lround(d.x_m / cell_m)), j = static_cast<int>(std::lround(d.y_m / cell_m));
      i = ((i % nx) + nx) % nx;
      j = ((j % ny) + ny) % ny;
      at(i, j) = d.amplitude_m;
      return;
    }
    case DisturbanceKind::plane_wave: {
      const double k = 2 * M_PI / d.wavelength_m, th = d.angle_deg * M_PI / 180;
      const double kx = k * std::cos(th), ky = k * std::sin(th);
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) at(i, j) = d.amplitude_m * std::cos(kx * i * cell_m + ky * j * cell_m);
      return;
    }
    case DisturbanceKind::gaussian:
    case DisturbanceKind::ring: {
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
          double sum = 0;
          for (int py = -1; py <= 1; ++py)
            for (int px = -1; px <= 1; ++px) {
              double dx = i * cell_m - d.x_m + px * lx, dy = j * cell_m - d.y_m + py * ly;
              double r = std::sqrt(dx * dx + dy * dy);
              double u = d.kind == DisturbanceKind::gaussian ? r / d.width_m : (r - d.radius_m) / d.width_m;
              sum += std::exp(-u * u);
            }
          at(i, j) = d.amplitude_m * sum;
        }
      return;
    }
  }
}

}  // namespace stoneskip
