#pragma once
// Whether a single power law y = C x^k describes a series at all, before its exponent is read:
// the extra-sum-of-squares F test of a quadratic term in log x against the straight line in
// log–log coordinates, log y = a + k log x + c (log x − mean)², F = (SSE₁ − SSE₂) / (SSE₂ / (n − 3))
// against the 95 % quantile of F(1, n − 3) (e.g. Montgomery & Runger, Applied Statistics, §12.2.2;
// the same test order_fit.hpp applies to its correction term). Where the term is significant the
// local exponent drifts across the range, and a fitted k with its interval describes no part of the
// series: the exponents between neighbouring points are reported instead. With fewer than 4
// points, or a line through every point (to round-off), nothing is tested; a quadratic through
// every point that the line misses is curved (F infinite).
#include <vector>

namespace stoneskip {

struct PowerLawShape {
  bool tested = false;      // n ≥ 4 usable points (x > 0, y > 0, finite) and a residual to test against
  int points = 0;
  double f_statistic = 0, f_critical = 0;
  bool curved = false;      // F > F_0.95(1, n − 3): the series bends in log–log coordinates
  // Exponents between neighbouring points in order of x, log(y₂/y₁)/log(x₂/x₁): their least and
  // greatest (NaN with fewer than 2 points).
  double local_min = 0, local_max = 0;
  // Where tested: the quadratic's local exponent d log y / d log x at the least and the greatest x
  // (k + 2c (log x − mean)); their difference is how far the exponent drifts across the range.
  double quadratic_slope_at_min_x = 0, quadratic_slope_at_max_x = 0;
};

PowerLawShape test_power_law_shape(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace stoneskip
