#pragma once
// Observed order of convergence from any sequence of (h, error) pairs: a least-squares fit of
// log e = log C + p log h with the 95 % confidence interval of p (Student t), and the pairwise
// orders p_k = log(e_k / e_{k+1}) / log(h_k / h_{k+1}) of neighbouring pairs. On request the fit
// also tests the first correction term of the error's expansion (OrderFitOptions).
#include <string>
#include <vector>

namespace stoneskip {

// Ordinary least squares y = a + b x with the 95 % confidence interval of the slope (Student t,
// n − 2 degrees of freedom; the interval is the point itself with 2 points). The one fit behind
// the observed orders below and the growth rates of verification/waves/stability.hpp.
struct LineFit {
  bool valid = false;   // false with fewer than 2 points or all x equal
  int points = 0;
  double slope = 0, intercept = 0;
  double slope_low = 0, slope_high = 0;
  double r_squared = 0;
  double residual_min = 0, residual_max = 0;  // the scatter of y about the line
};
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y);

struct OrderFit {
  bool valid = false;            // false with fewer than 2 usable points (error > 0, h > 0)
  std::string problem;           // why not valid
  // Points left out of the fit: an error or h that is NaN or infinite (a failed or unstable run),
  // and an error ≤ 0 (exact to the last bit, or a signed quantity). judge_order claims no order
  // where any run failed: the survivors are not the sequence that was asked for.
  int failed_points = 0, nonpositive_points = 0;
  double order = 0;              // slope p
  double constant = 0;           // C
  double order_low = 0;          // 95 % confidence interval of p (equal to p with 2 points)
  double order_high = 0;
  double r_squared = 0;
  int points = 0;
  std::vector<double> pairwise;  // size points − 1
  // With OrderFitOptions::correction_term: whether the correction term was significant, and then
  // order, order_low, order_high and constant above are the three-parameter fit's, with the single
  // power's kept here; correction is d·h_max (the relative size of the term at the largest h).
  bool corrected = false;
  double single_order = 0, single_low = 0, single_high = 0;
  double correction = 0;
  double f_statistic = 0, f_critical = 0;  // the test's F and its 95 % quantile (0: not tested)
  // Whether one power describes the fitted points at all (power_law_shape.hpp: the F test of a
  // quadratic in log h, n ≥ 4), and the quadratic's local order at the coarsest and the finest h.
  // A fit whose local order drifts across its range (an error running onto a floor: 2.0 at the
  // coarse end, 0.2 at the fine) has an interval that describes no part of it (judge_order).
  bool shape_tested = false, curved = false;
  double curvature_f = 0, curvature_f_critical = 0;
  double local_order_coarse = 0, local_order_fine = 0;
  std::string brief() const;     // "p = 2.01 [1.98, 2.04] (5 points)"
  int growing_refinements() const;  // pairwise orders ≤ 0 (or NaN): refinements at which the error grew
};

// The first correction term of the error's asymptotic expansion. A fixed-step one-step method of
// order p on a smooth problem has a global error e = h^p e_p(t) + h^(p+1) e_(p+1)(t) + O(h^(p+2))
// (Hairer, Nørsett & Wanner, Solving ODEs I, 2nd ed. 1993, Thm II.8.1), so
// log e = log C + p log h + d h + O(h²). Far from h → 0 (a spinning stone at ωh ≈ 1 rad a step)
// the second term bends a single power's fit, whose interval then misses p although the pairwise
// orders approach it. With `correction_term`, h (over its largest value) enters the regression
// as a second regressor, and the three-parameter fit is used when it lowers the residual sum of
// squares significantly: the extra-sum-of-squares F test, F = (SSE₁ − SSE₂) / (SSE₂ / (n − 3))
// above the 95 % quantile of F(1, n − 3) (e.g. Montgomery & Runger, Applied Statistics, §12.2.2).
// It needs n ≥ 4 points whose error falls at every halving (every pairwise order > 0: an error
// that grows somewhere as h shrinks is not approaching C h^p, and a three-parameter fit of such
// scatter means nothing); its interval on p (Student t, n − 3 degrees of freedom) is wider than
// the single power's, so few points give "not established", never a narrower claim (it is computed
// on the data that chose the model by the F test, so its 95 % is nominal, not exact). A floor (the
// reference's error) bends the fine end, which this term does not describe: such points are to be
// left out before the fit, as the studies do.
struct OrderFitOptions {
  bool correction_term = false;
};

OrderFit fit_order(const std::vector<double>& h, const std::vector<double>& error, const OrderFitOptions& options = {});

// Richardson extrapolation of two solutions on sizes h_fine < h_coarse = r h_fine with known
// order p: φ_ext = (r^p φ_fine − φ_coarse) / (r^p − 1) (Celik et al. 2008, Eq. 6).
double richardson_extrapolate(double phi_fine, double phi_coarse, double ratio, double order);

// What a sequence of errors says about convergence to the quantity it was measured against.
// The rule reads the fit's 95 % confidence interval [low, high], never the point estimate alone:
//   converges_at_expected_order  the whole interval lies within `tolerance` of the expected order;
//   converges_at_other_order     the interval misses the band expected ± tolerance entirely and
//                                lies above minimum_order (it excludes no convergence too);
//   does_not_converge            the whole interval lies at or below minimum_order: the data show
//                                that the error falls no faster than h^minimum_order, if at all (a
//                                wide interval shows nothing);
//   order_not_established        anything else: a run failed (a NaN or infinite error); the
//                                interval is too wide to decide or straddles the band's edge; where
//                                one of the two order verdicts would be given, the error does not
//                                fall at some refinement (a pairwise order ≤ 0); where any of the
//                                three would be, the local order drifts across the range by more
//                                than the band's width (2 × tolerance) with the curvature
//                                significant (F test; not for a fit that took the correction term,
//                                which describes that bend);
//   insufficient_data            fewer than 3 points in the fit (a two-point fit has no residual,
//                                so its "interval" is the point itself), or no fit at all.
enum class OrderVerdict {
  converges_at_expected_order,
  converges_at_other_order,
  does_not_converge,
  insufficient_data,
  order_not_established,
};
const char* to_string(OrderVerdict v);

struct OrderJudgement {
  double expected_order = 2;
  double tolerance = 0.1;        // the interval must lie within expected ± tolerance
  double minimum_order = 0.25;   // at or below this slope the error is said not to fall
  std::string expected_name = "expected";  // how the reason names the expected order ("formal")
};

// A verdict and its reason in one line, computed from the numbers:
// "p = 2.41 [1.74, 3.08] excludes the formal 4".
struct OrderDecision {
  OrderVerdict verdict = OrderVerdict::insufficient_data;
  std::string reason;
};

OrderDecision judge_order(const OrderFit& fit, const OrderJudgement& judgement = {});

}  // namespace stoneskip
