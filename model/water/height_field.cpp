#include "model/water/height_field.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stoneskip {

const char* to_string(Boundary b) {
  switch (b) {
    case Boundary::periodic: return "periodic";
    case Boundary::reflecting: return "reflecting";
    case Boundary::fixed: return "fixed";
  }
  return "?";
}

bool parse_boundary(const std::string& s, Boundary& out) {
  for (auto b : {Boundary::periodic, Boundary::reflecting, Boundary::fixed})
    if (s == to_string(b)) {
      out = b;
      return true;
    }
  return false;
}

HeightField::HeightField(const HeightFieldOptions& options)
    : options_(options), stride_(static_cast<std::size_t>(options.nx) + 2) {
  if (options.nx < 2 || options.ny < 2) throw std::invalid_argument("height field needs nx, ny >= 2");
  const std::size_t n = stride_ * (static_cast<std::size_t>(options.ny) + 2);
  cur_.assign(n, 0.0);
  prev_.assign(n, 0.0);
}

void HeightField::fill_ghosts(std::vector<double>& z) const {
  const int nx = options_.nx, ny = options_.ny;
  const std::size_t w = stride_;
  double* p = z.data();
  switch (options_.boundary) {
    case Boundary::fixed:
      return;  // ghosts are zero from construction and never written
    case Boundary::periodic:
      for (int j = 1; j <= ny; ++j) {
        p[j * w + 0] = p[j * w + nx];
        p[j * w + nx + 1] = p[j * w + 1];
      }
      for (std::size_t i = 0; i < w; ++i) {  // whole rows, so the corners wrap too
        p[i] = p[ny * w + i];
        p[(ny + 1) * w + i] = p[w + i];
      }
      return;
    case Boundary::reflecting:
      for (int j = 1; j <= ny; ++j) {
        p[j * w + 0] = p[j * w + 1];
        p[j * w + nx + 1] = p[j * w + nx];
      }
      for (std::size_t i = 0; i < w; ++i) {
        p[i] = p[w + i];
        p[(ny + 1) * w + i] = p[ny * w + i];
      }
      return;
  }
}

void HeightField::step() {
  // Lee & Baek 2013 Eq. 11 in the centred-damping form of spec §2.1.
  const double mdt = options_.damping_per_s * options_.dt_s;
  const double inv = 1.0 / (2 + mdt);
  const double a = 4 * inv, b = (2 - mdt) * inv;
  const double s = 2 * options_.courant() * options_.courant() * inv;  // 2c²Δt²/d² /(2+μΔt)
  const double wc = s * options_.stencil.centre + a, wo = s * options_.stencil.orth, wd = s * options_.stencil.diag;
  fill_ghosts(cur_);
  const int nx = options_.nx, ny = options_.ny;
  const std::ptrdiff_t w = static_cast<std::ptrdiff_t>(stride_);
  const double* __restrict z = cur_.data();
  double* __restrict zp = prev_.data();  // holds z⁻, receives z⁺
  if (wd == 0) {
    for (int j = 1; j <= ny; ++j) {
      const std::ptrdiff_t r = j * w;
      for (std::ptrdiff_t k = r + 1; k <= r + nx; ++k)
        zp[k] = wc * z[k] + wo * (z[k - 1] + z[k + 1] + z[k - w] + z[k + w]) - b * zp[k];
    }
  } else {
    for (int j = 1; j <= ny; ++j) {
      const std::ptrdiff_t r = j * w;
      for (std::ptrdiff_t k = r + 1; k <= r + nx; ++k)
        zp[k] = wc * z[k] + wo * (z[k - 1] + z[k + 1] + z[k - w] + z[k + w]) +
                wd * (z[k - w - 1] + z[k - w + 1] + z[k + w - 1] + z[k + w + 1]) - b * zp[k];
    }
  }
  cur_.swap(prev_);
  ++steps_;
  time_s_ = steps_ * options_.dt_s;
}

void HeightField::advance(long n) {
  for (long i = 0; i < n; ++i) step();
}

void HeightField::apply_laplacian(const std::vector<double>& z, std::vector<double>& out) const {
  const int nx = options_.nx, ny = options_.ny;
  const std::ptrdiff_t w = static_cast<std::ptrdiff_t>(stride_);
  const double id2 = 1.0 / (options_.cell_m * options_.cell_m);
  const Stencil& st = options_.stencil;
  out.assign(z.size(), 0.0);
  for (int j = 1; j <= ny; ++j)
    for (std::ptrdiff_t k = j * w + 1; k <= j * w + nx; ++k)
      out[k] = id2 * (st.centre * z[k] + st.orth * (z[k - 1] + z[k + 1] + z[k - w] + z[k + w]) +
                      st.diag * (z[k - w - 1] + z[k - w + 1] + z[k + w - 1] + z[k + w + 1]));
}

void HeightField::set_state(const std::vector<double>& z0, const std::vector<double>& v0) {
  const int nx = options_.nx, ny = options_.ny;
  const std::size_t n = static_cast<std::size_t>(nx) * ny;
  if (z0.size() != n || (!v0.empty() && v0.size() != n)) throw std::invalid_argument("set_state: wrong field size");
  std::fill(cur_.begin(), cur_.end(), 0.0);
  std::fill(prev_.begin(), prev_.end(), 0.0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) cur_[index(i, j)] = z0[static_cast<std::size_t>(j) * nx + i];
  fill_ghosts(cur_);
  std::vector<double> lap;
  apply_laplacian(cur_, lap);
  const double dt = options_.dt_s, c2 = options_.wave_speed_m_s * options_.wave_speed_m_s, mu = options_.damping_per_s;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      std::size_t k = index(i, j);
      double v = v0.empty() ? 0.0 : v0[static_cast<std::size_t>(j) * nx + i];
      prev_[k] = cur_[k] - dt * v + 0.5 * dt * dt * (c2 * lap[k] - mu * v);
    }
  time_s_ = 0;
  steps_ = 0;
}

void HeightField::heights(std::vector<double>& out) const {
  const int nx = options_.nx, ny = options_.ny;
  out.resize(static_cast<std::size_t>(nx) * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) out[static_cast<std::size_t>(j) * nx + i] = cur_[index(i, j)];
}

double HeightField::interpolate(double x_m, double y_m) const {
  const int nx = options_.nx, ny = options_.ny;
  double gx = x_m / options_.cell_m, gy = y_m / options_.cell_m;
  const bool wrap = options_.boundary == Boundary::periodic;
  if (wrap) {
    gx -= nx * std::floor(gx / nx);
    gy -= ny * std::floor(gy / ny);
  } else {
    gx = std::clamp(gx, 0.0, nx - 1.0);
    gy = std::clamp(gy, 0.0, ny - 1.0);
  }
  int i0 = std::min(static_cast<int>(std::floor(gx)), nx - 1), j0 = std::min(static_cast<int>(std::floor(gy)), ny - 1);
  double fx = gx - i0, fy = gy - j0;
  int i1 = i0 + 1, j1 = j0 + 1;
  if (wrap) {
    i1 %= nx;
    j1 %= ny;
  } else {
    i1 = std::min(i1, nx - 1);
    j1 = std::min(j1, ny - 1);
  }
  return (1 - fx) * (1 - fy) * height(i0, j0) + fx * (1 - fy) * height(i1, j0) + (1 - fx) * fy * height(i0, j1) +
         fx * fy * height(i1, j1);
}

}  // namespace stoneskip
