#pragma once
// The Duhamel integral of a forced damped wave equation, mode by mode (model/README.md §2.5):
//   ẑ_forced(t) = ∫₀ᵗ G(t − s) (−λ b̂(s)) ds,  G(τ) = e^{−μτ/2} S(τ) = damped_mode(λ, μ, τ).gv,
// by Gauss–Legendre quadrature on equal sub-intervals of [0, t], one transform of b per node. Shared
// by the periodic reference (Fourier modes, complex: forced_wave.hpp) and the walled one (cosine
// or sine modes, real: forced_walled_wave.hpp).
#include <functional>
#include <vector>

#include "solvers/spectral/damped_mode.hpp"
#include "solvers/spectral/gauss_legendre.hpp"

namespace stoneskip {

// Fills b (resized to nx·ny, row-major, x fastest) with the draught at the cell points at time t.
using DraughtField = std::function<void(double t_s, std::vector<double>& b)>;

struct DuhamelQuadrature {
  int intervals = 32;  // equal sub-intervals of [0, t]
  int nodes = 8;       // Gauss–Legendre nodes per sub-interval
};

// Adds the integral to `modes` (one value per λ); `transform(b, b_hat)` takes b to the same modes.
// Returns the number of transforms taken.
template <class Mode, class Transform>
long add_duhamel_integral(double t_s, const std::vector<double>& lambda, double mu, const DuhamelQuadrature& quadrature,
                          const DraughtField& draught, Transform&& transform, std::vector<Mode>& modes,
                          std::vector<double>& b, std::vector<Mode>& b_hat) {
  const GaussLegendreRule rule = gauss_legendre(quadrature.nodes);
  const double h = t_s / quadrature.intervals;
  long transforms = 0;
  for (int k = 0; k < quadrature.intervals && t_s > 0; ++k)
    for (std::size_t q = 0; q < rule.nodes.size(); ++q) {
      const double s = (k + 0.5 * (rule.nodes[q] + 1)) * h, w = 0.5 * h * rule.weights[q];
      draught(s, b);
      transform(b, b_hat);
      ++transforms;
      for (std::size_t m = 0; m < lambda.size(); ++m) {
        if (lambda[m] == 0) continue;  // a neutral mode (the mean, the level) is not forced: −λ b̂ = 0
        modes[m] -= (w * damped_mode(lambda[m], mu, t_s - s).gv * lambda[m]) * b_hat[m];
      }
    }
  return transforms;
}

}  // namespace stoneskip
