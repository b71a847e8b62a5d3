#pragma once
// Gauss–Legendre quadrature on [−1, 1]: the n nodes are the roots of P_n, found by Newton's method
// from Tricomi's estimate cos(π(k − ¼)/(n + ½)), the weights 2 / ((1 − x²) P_n'(x)²)
// (Abramowitz & Stegun 25.4.29). Exact for polynomials of degree ≤ 2n − 1.
#include <vector>

namespace stoneskip {

struct GaussLegendreRule {
  std::vector<double> nodes, weights;  // ascending nodes in (−1, 1); weights sum to 2
};

GaussLegendreRule gauss_legendre(int n);  // n ≥ 1; throws std::invalid_argument otherwise

}  // namespace stoneskip
