#include "model/water/propagator_bound.hpp"

#include <algorithm>
#include <cmath>

namespace stoneskip {

double leapfrog_propagator_bound(const Stencil& stencil, double sigma, double mu_dt, int nx, int ny, long steps) {
  const double sig2 = sigma * sigma;
  const double m01 = -(2 - mu_dt) / (2 + mu_dt);
  double k_max = 1;  // p = 0
  for (int mx = 0; mx <= nx; ++mx)
    for (int my = 0; my <= (nx == ny ? mx : ny); ++my) {  // symbol(a, b) = symbol(b, a)
      const double m00 = (4 + 2 * sig2 * stencil.symbol(M_PI * mx / nx, M_PI * my / ny)) / (2 + mu_dt);
      double p00 = 1, p01 = 0, p10 = 0, p11 = 1;
      for (long p = 1; p <= steps; ++p) {
        const double q00 = m00 * p00 + m01 * p10, q01 = m00 * p01 + m01 * p11;
        p10 = p00;
        p11 = p01;
        p00 = q00;
        p01 = q01;
        // ‖P‖₂² = (F + √(F² − 4 det²))/2, F the squared Frobenius norm.
        const double fro = p00 * p00 + p01 * p01 + p10 * p10 + p11 * p11, det = p00 * p11 - p01 * p10;
        k_max = std::max(k_max, std::sqrt(0.5 * (fro + std::sqrt(std::max(fro * fro - 4 * det * det, 0.0)))));
      }
    }
  return k_max;
}

double leapfrog_rounding_bound(const Stencil& stencil, double sigma, double mu_dt, double z_norm, double z_previous_norm,
                               double unit_roundoff) {
  const double inv = 1 / (2 + mu_dt), s = 2 * sigma * sigma * inv;
  const double w_z = std::abs(s * stencil.centre + 4 * inv) + 4 * std::abs(s * stencil.orth) + 4 * std::abs(s * stencil.diag);
  const double w_p = (2 - mu_dt) * inv;
  const double gamma = 12 * unit_roundoff / (1 - 12 * unit_roundoff);
  return 4 * gamma * (w_z * z_norm + w_p * z_previous_norm);
}

}  // namespace stoneskip
