#pragma once
// Consistency of a Laplacian stencil, found numerically from its symbol (model/water/stencil.hpp).
// Along a direction θ, with q = (kd)², the symbol is fitted by least squares to
//   d²·symbol(kd cos θ, kd sin θ) ≈ s0 + s1 q + s2(θ) q² + s3 q³
// on small kd. A stencil consistent with ∇² has s0 = 0 (its weights sum to zero: a uniform
// raise feels no force) and s1 = −1 (the continuum's symbol is −(kd)²); its leading truncation
// error is then s2(θ) (kd)⁴/d², i.e. an error of s2(θ) d² ∂⁴ in the operator, e.g. (cos⁴θ +
// sin⁴θ)/12 for the five-point stencil (model/README.md §2.2). Nothing here knows those numbers.
#include <string>
#include <vector>

#include "model/water/stencil.hpp"

namespace stoneskip {

struct ConsistencyOptions {
  double max_kd = 0.1;    // the fit uses kd in (0, max_kd]
  int samples = 12;       // kd samples per direction
  int angles = 91;        // θ in [0, π/2] for the leading error's angular dependence
  double tolerance = 1e-8;  // |s0| and |s1 + 1| below this count as consistent
};

struct ConsistencyResult {
  std::string stencil;
  double weight_sum = 0;          // Σ weights (× 1/d²), exactly the symbol at k = 0
  double constant_term = 0;       // s0 from the fit (agrees with weight_sum)
  double laplacian_coefficient = 0;  // −s1: 1 for a consistent stencil
  std::vector<double> theta_rad;  // the leading error coefficient s2(θ) (× d² ∂⁴)
  std::vector<double> leading_error;
  double leading_error_min = 0, leading_error_max = 0;  // over θ
  bool consistent = false;
  bool isotropic_leading_error = false;  // max − min of s2(θ) below 1e-6
  std::string verdict;  // one sentence
};

ConsistencyResult analyse_consistency(const Stencil& stencil, const ConsistencyOptions& options = {});

}  // namespace stoneskip
