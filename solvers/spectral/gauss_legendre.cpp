#include "solvers/spectral/gauss_legendre.hpp"

#include <cmath>
#include <stdexcept>

namespace stoneskip {

GaussLegendreRule gauss_legendre(int n) {
  if (n < 1) throw std::invalid_argument("gauss_legendre: n must be >= 1");
  GaussLegendreRule r;
  r.nodes.resize(n);
  r.weights.resize(n);
  for (int k = 1; k <= (n + 1) / 2; ++k) {
    double x = std::cos(M_PI * (k - 0.25) / (n + 0.5));
    double dp = 1;
    for (int it = 0; it < 100; ++it) {
      // P_n(x) and P_n'(x) by the three-term recurrence (m + 1) P_{m+1} = (2m + 1) x P_m − m P_{m−1}.
      double p0 = 1, p1 = x;
      for (int m = 1; m < n; ++m) {
        const double p2 = ((2 * m + 1) * x * p1 - m * p0) / (m + 1);
        p0 = p1;
        p1 = p2;
      }
      const double pn = n == 1 ? x : p1, pm = n == 1 ? 1 : p0;
      dp = n * (x * pn - pm) / (x * x - 1);
      const double dx = pn / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    // Recompute P_n' at the converged root for the weight.
    double p0 = 1, p1 = x;
    for (int m = 1; m < n; ++m) {
      const double p2 = ((2 * m + 1) * x * p1 - m * p0) / (m + 1);
      p0 = p1;
      p1 = p2;
    }
    dp = n == 1 ? 1 : n * (x * p1 - p0) / (x * x - 1);
    const double w = 2 / ((1 - x * x) * dp * dp);
    r.nodes[k - 1] = -x;
    r.nodes[n - k] = x;
    r.weights[k - 1] = r.weights[n - k] = w;
  }
  return r;
}

}  // namespace stoneskip
