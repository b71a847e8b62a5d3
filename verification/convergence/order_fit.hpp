#pragma once
// Observed order of convergence from any sequence of (h, error) pairs: a least-squares fit of
// log e = log C + p log h with the 95 % confidence interval of p (Student t), and the pairwise
// orders p_k = log(e_k / e_{k+1}) / log(h_k / h_{k+1}) of neighbouring pairs.
#include <string>
#include <vector>

namespace stoneskip {

struct OrderFit {
  bool valid = false;            // false with fewer than 2 usable points (error > 0, h > 0)
  std::string problem;           // why not valid
  double order = 0;              // slope p
  double constant = 0;           // C
  double order_low = 0;          // 95 % confidence interval of p (equal to p with 2 points)
  double order_high = 0;
  double r_squared = 0;
  int points = 0;
  std::vector<double> pairwise;  // size points − 1
  std::string brief() const;     // "p = 2.01 [1.98, 2.04] (5 points)"
};

OrderFit fit_order(const std::vector<double>& h, const std::vector<double>& error);

// Richardson extrapolation of two solutions on sizes h_fine < h_coarse = r h_fine with known
// order p: φ_ext = (r^p φ_fine − φ_coarse) / (r^p − 1) (Celik et al. 2008, Eq. 6).
double richardson_extrapolate(double phi_fine, double phi_coarse, double ratio, double order);

// What a sequence of errors says about convergence to the quantity it was measured against.
enum class OrderVerdict {
  converges_at_expected_order,  // the fit's interval lies within tolerance of the expected order
  converges_at_other_order,     // the error falls, but not at the expected order
  does_not_converge,            // the error does not fall with h (slope ≤ minimum_order, or interval reaches 0)
  insufficient_data,            // fewer than 2 usable points
};
const char* to_string(OrderVerdict v);

struct OrderJudgement {
  double expected_order = 2;
  double tolerance = 0.1;        // |p − expected| allowed
  double minimum_order = 0.25;   // below this slope the error is said not to converge
};

// Judges a fit: uses the fit's point estimate and its confidence interval (both must be within
// tolerance for "at expected order").
OrderVerdict judge_order(const OrderFit& fit, const OrderJudgement& judgement = {});

}  // namespace stoneskip
