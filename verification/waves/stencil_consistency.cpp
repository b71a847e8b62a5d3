#include "verification/waves/stencil_consistency.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace stoneskip {

namespace {
// Least-squares cubic in q = (kd)² of the symbol along θ (Householder QR, well conditioned for
// the small q range after scaling q by max_kd²).
Eigen::Vector4d fit_symbol(const Stencil& s, double theta, const ConsistencyOptions& o) {
  Eigen::MatrixXd A(o.samples, 4);
  Eigen::VectorXd y(o.samples);
  const double qs = o.max_kd * o.max_kd;
  for (int i = 0; i < o.samples; ++i) {
    const double kd = o.max_kd * (i + 1) / o.samples;
    const double q = kd * kd / qs;
    A(i, 0) = 1;
    A(i, 1) = q;
    A(i, 2) = q * q;
    A(i, 3) = q * q * q;
    y(i) = s.symbol(kd * std::cos(theta), kd * std::sin(theta));
  }
  Eigen::Vector4d c = A.colPivHouseholderQr().solve(y);
  c(1) /= qs;
  c(2) /= qs * qs;
  c(3) /= qs * qs * qs;
  return c;
}
}  // namespace

ConsistencyResult analyse_consistency(const Stencil& stencil, const ConsistencyOptions& o) {
  ConsistencyResult r;
  r.stencil = stencil.name;
  r.weight_sum = stencil.weight_sum();
  Eigen::Vector4d c0 = fit_symbol(stencil, 0.0, o);
  r.constant_term = c0(0);
  r.laplacian_coefficient = -c0(1);
  r.leading_error_min = 1e300;
  r.leading_error_max = -1e300;
  for (int a = 0; a < o.angles; ++a) {
    const double th = 0.5 * M_PI * a / (o.angles - 1);
    Eigen::Vector4d c = fit_symbol(stencil, th, o);
    r.theta_rad.push_back(th);
    r.leading_error.push_back(c(2));
    r.leading_error_min = std::min(r.leading_error_min, c(2));
    r.leading_error_max = std::max(r.leading_error_max, c(2));
  }
  r.consistent = std::abs(r.constant_term) <= o.tolerance && std::abs(r.laplacian_coefficient - 1) <= o.tolerance;
  r.isotropic_leading_error = r.leading_error_max - r.leading_error_min <= 1e-6;
  char buf[300];
  if (!r.consistent) {
    std::snprintf(buf, sizeof buf,
                  "inconsistent: the symbol at k = 0 is %.4g (weights sum to %.4g, not 0) and the k² coefficient is %.4g; "
                  "the stencil does not approximate the Laplacian as d → 0",
                  r.constant_term, r.weight_sum, -r.laplacian_coefficient);
  } else {
    std::snprintf(buf, sizeof buf, "consistent, second order; leading error %s (%.4g to %.4g × d²∂⁴)",
                  r.isotropic_leading_error ? "isotropic" : "depends on direction", r.leading_error_min,
                  r.leading_error_max);
  }
  r.verdict = buf;
  return r;
}

}  // namespace stoneskip
