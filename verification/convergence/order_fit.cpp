#include "verification/convergence/order_fit.hpp"

#include "verification/convergence/power_law_shape.hpp"

#include <boost/math/distributions/fisher_f.hpp>
#include <boost/math/distributions/students_t.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace stoneskip {

LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  LineFit f;
  f.points = static_cast<int>(std::min(x.size(), y.size()));
  if (f.points < 2) return f;
  // Ordinary least squares y = a + b x (e.g. Montgomery & Runger, Applied Statistics, §11.2).
  const double n = f.points;
  double mx = 0, my = 0;
  for (int i = 0; i < f.points; ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= n;
  my /= n;
  double sxx = 0, sxy = 0, syy = 0;
  for (int i = 0; i < f.points; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  if (sxx <= 0) return f;
  f.slope = sxy / sxx;
  f.intercept = my - f.slope * mx;
  double sse = 0;
  for (int i = 0; i < f.points; ++i) {
    const double r = y[i] - (my + f.slope * (x[i] - mx));
    sse += r * r;
    f.residual_min = i == 0 ? r : std::min(f.residual_min, r);
    f.residual_max = i == 0 ? r : std::max(f.residual_max, r);
  }
  f.r_squared = syy > 0 ? 1 - sse / syy : 1;
  f.slope_low = f.slope_high = f.slope;
  if (f.points > 2) {
    // 95 % two-sided interval of the slope: b ± t_{0.975, n−2} · sqrt(SSE/(n−2)/Sxx).
    boost::math::students_t dist(n - 2);
    const double t = boost::math::quantile(boost::math::complement(dist, 0.025));
    const double se = std::sqrt(sse / (n - 2) / sxx);
    f.slope_low = f.slope - t * se;
    f.slope_high = f.slope + t * se;
  }
  f.valid = true;
  return f;
}

namespace {

// The three-parameter fit log e = a + p log h + d (h / h_max) and its F test against the single
// power (order_fit.hpp, OrderFitOptions); sets the fit's corrected fields.
void test_correction_term(const std::vector<double>& x, const std::vector<double>& y, const LineFit& line,
                          OrderFit& fit) {
  const int n = static_cast<int>(x.size());
  if (n < 4) return;
  // The expansion describes an error that approaches C h^p as h shrinks; a series whose error
  // grows somewhere as h shrinks (a pairwise order ≤ 0) is not in that regime.
  for (double p : fit.pairwise)
    if (!(p > 0)) return;
  double x_max = x[0];
  for (double v : x) x_max = std::max(x_max, v);
  Eigen::MatrixXd X(n, 3);
  Eigen::VectorXd Y(n);
  for (int i = 0; i < n; ++i) {
    X(i, 0) = 1;
    X(i, 1) = x[i];
    X(i, 2) = std::exp(x[i] - x_max);  // h / h_max
    Y(i) = y[i];
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(X);
  if (qr.rank() < 3) return;  // h takes fewer than 3 distinct values
  const Eigen::Vector3d b = qr.solve(Y);
  const double sse2 = (Y - X * b).squaredNorm();
  if (!(sse2 > 0)) return;  // three parameters through every point: no residual to test against
  double sse1 = 0;
  for (int i = 0; i < n; ++i) {
    const double r = y[i] - (line.intercept + line.slope * x[i]);
    sse1 += r * r;
  }
  const double dof = n - 3;
  boost::math::fisher_f f_dist(1, dof);
  fit.f_critical = boost::math::quantile(boost::math::complement(f_dist, 0.05));
  fit.f_statistic = (sse1 - sse2) / (sse2 / dof);
  if (!(fit.f_statistic > fit.f_critical)) return;
  // Interval of p: b_p ± t_{0.975, n−3} · sqrt(SSE₂/(n−3) · [(XᵀX)⁻¹]_pp).
  const Eigen::Matrix3d inv = (X.transpose() * X).inverse();
  boost::math::students_t t_dist(dof);
  const double t = boost::math::quantile(boost::math::complement(t_dist, 0.025));
  const double se = std::sqrt(sse2 / dof * inv(1, 1));
  fit.corrected = true;
  fit.single_order = fit.order;
  fit.single_low = fit.order_low;
  fit.single_high = fit.order_high;
  fit.order = b(1);
  fit.order_low = b(1) - t * se;
  fit.order_high = b(1) + t * se;
  fit.constant = std::exp(b(0));
  fit.correction = b(2);
  double syy = 0, my = Y.mean();
  for (int i = 0; i < n; ++i) syy += (y[i] - my) * (y[i] - my);
  fit.r_squared = syy > 0 ? 1 - sse2 / syy : 1;
}

}  // namespace

OrderFit fit_order(const std::vector<double>& h, const std::vector<double>& error, const OrderFitOptions& options) {
  OrderFit fit;
  if (h.size() != error.size()) {
    fit.problem = "h and error have different lengths";
    return fit;
  }
  std::vector<double> x, y, hs, es;
  for (std::size_t i = 0; i < h.size(); ++i) {
    if (!std::isfinite(h[i]) || !std::isfinite(error[i])) {
      ++fit.failed_points;
    } else if (!(error[i] > 0)) {
      ++fit.nonpositive_points;
    } else if (h[i] > 0) {
      x.push_back(std::log(h[i]));
      y.push_back(std::log(error[i]));
      hs.push_back(h[i]);
      es.push_back(error[i]);
    }
  }
  fit.points = static_cast<int>(x.size());
  if (x.size() < 2) {
    fit.problem = "fewer than 2 points with h > 0 and error > 0";
    if (fit.failed_points > 0) fit.problem += " (" + std::to_string(fit.failed_points) + " with a NaN or infinite value)";
    return fit;
  }
  const LineFit line = fit_line(x, y);
  if (!line.valid) {
    fit.problem = "all h are equal";
    return fit;
  }
  fit.order = line.slope;
  fit.constant = std::exp(line.intercept);
  fit.order_low = line.slope_low;
  fit.order_high = line.slope_high;
  fit.r_squared = line.r_squared;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) fit.pairwise.push_back((y[i] - y[i + 1]) / (x[i] - x[i + 1]));
  fit.valid = true;
  if (options.correction_term) test_correction_term(x, y, line, fit);
  const PowerLawShape shape = test_power_law_shape(hs, es);
  if (shape.tested) {
    fit.shape_tested = true;
    fit.curved = shape.curved;
    fit.curvature_f = shape.f_statistic;
    fit.curvature_f_critical = shape.f_critical;
    fit.local_order_fine = shape.quadratic_slope_at_min_x;  // the finest h is the least
    fit.local_order_coarse = shape.quadratic_slope_at_max_x;
  }
  return fit;
}

int OrderFit::growing_refinements() const {
  int n = 0;
  for (double p : pairwise) n += p > 0 ? 0 : 1;
  return n;
}

std::string OrderFit::brief() const {
  if (!valid) return "no fit: " + problem;
  char buf[128];
  std::snprintf(buf, sizeof buf, "p = %.3g [%.3g, %.3g] (%d points)", order, order_low, order_high, points);
  if (!corrected) return buf;
  char more[160];
  std::snprintf(more, sizeof more, " with the term h^(p+1) (F = %.3g > %.3g; a single power: p = %.3g [%.3g, %.3g])",
                f_statistic, f_critical, single_order, single_low, single_high);
  return std::string(buf) + more;
}

double richardson_extrapolate(double phi_fine, double phi_coarse, double ratio, double order) {
  const double rp = std::pow(ratio, order);
  return (rp * phi_fine - phi_coarse) / (rp - 1);  // Celik et al. 2008, Eq. 6
}

const char* to_string(OrderVerdict v) {
  switch (v) {
    case OrderVerdict::converges_at_expected_order: return "converges at the expected order";
    case OrderVerdict::converges_at_other_order: return "converges, not at the expected order";
    case OrderVerdict::does_not_converge: return "does not converge";
    case OrderVerdict::insufficient_data: return "order not established (fewer than 3 points)";
    case OrderVerdict::order_not_established: return "order not established";
  }
  return "?";
}

OrderDecision judge_order(const OrderFit& fit, const OrderJudgement& j) {
  OrderDecision d;
  auto num = [](double x) {
    if (std::isnan(x)) return std::string("–");
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", x);
    return std::string(buf);
  };
  // Exact errors (≤ 0) left out are said, not hidden.
  const std::string zeros =
      fit.nonpositive_points > 0
          ? " (" + std::to_string(fit.nonpositive_points) + " run" + (fit.nonpositive_points == 1 ? "" : "s") +
                " with an error ≤ 0 left out)"
          : "";
  if (!fit.valid) {
    d.reason = "no fit: " + fit.problem + zeros;
    return d;
  }
  const int all = fit.points + fit.failed_points + fit.nonpositive_points;
  if (fit.failed_points > 0) {
    // A failed or unstable run is a result, not a gap: the others are not the sequence asked for.
    d.verdict = OrderVerdict::order_not_established;
    d.reason = std::to_string(fit.failed_points) + " of " + std::to_string(all) +
               " runs gave no finite error (a failed or unstable run): no order from the others";
    return d;
  }
  if (fit.points < 3) {
    d.reason = "only " + std::to_string(fit.points) + " points: a fit needs 3 for a confidence interval" + zeros;
    return d;
  }
  const std::string interval = "p = " + num(fit.order) + " [" + num(fit.order_low) + ", " + num(fit.order_high) + "]";
  const std::string expected = "the " + j.expected_name + " " + num(j.expected_order);
  const double band_low = j.expected_order - j.tolerance, band_high = j.expected_order + j.tolerance;
  const bool within = fit.order_low >= band_low && fit.order_high <= band_high;
  const bool misses_band = fit.order_high < band_low || fit.order_low > band_high;
  // An error that does not fall at some refinement (a pairwise order ≤ 0) is not approaching
  // C h^p, so no order is claimed from it, however narrow the fit's interval (its residuals are not
  // the scatter the interval assumes): the interval alone would call an erratic series convergent.
  const int growing = fit.growing_refinements();
  // Nor from a series whose local order drifts across the range by more than the band is wide
  // (an error running onto a floor): the interval of a straight line through a bend describes no
  // part of it, whether it claims an order or no convergence. A fit that took the correction term
  // has described its bend already.
  const bool drifts = fit.shape_tested && fit.curved && !fit.corrected &&
                      std::abs(fit.local_order_fine - fit.local_order_coarse) > 2 * j.tolerance;
  const bool claims_order = within || (misses_band && fit.order_low > j.minimum_order);
  if (claims_order && growing > 0) {
    d.verdict = OrderVerdict::order_not_established;
    d.reason = interval + ", but the error does not fall at " + std::to_string(growing) + " of " +
               std::to_string(fit.pairwise.size()) + " refinements (pairwise orders ≤ 0): not in the asymptotic range";
  } else if ((claims_order || fit.order_high <= j.minimum_order) && drifts) {
    d.verdict = OrderVerdict::order_not_established;
    d.reason = interval + ", but its local order drifts from " + num(fit.local_order_coarse) + " at the coarsest h to " +
               num(fit.local_order_fine) + " at the finest (curvature F = " + num(fit.curvature_f) + " > " +
               num(fit.curvature_f_critical) + ", more than the band's width " + num(2 * j.tolerance) +
               "): no one order describes the range";
  } else if (within) {
    d.verdict = OrderVerdict::converges_at_expected_order;
    d.reason = interval + " lies within " + num(j.tolerance) + " of " + expected;
  } else if (fit.order_high <= j.minimum_order) {
    d.verdict = OrderVerdict::does_not_converge;
    d.reason = interval + " lies at or below " + num(j.minimum_order) +
               (fit.order_low > 0 ? ": the error falls, but no faster than h^" + num(j.minimum_order) +
                                        ", too slowly to count as convergence"
                                  : ": the error does not fall as h shrinks");
  } else if (misses_band && fit.order_low > j.minimum_order) {
    d.verdict = OrderVerdict::converges_at_other_order;
    d.reason = interval + " excludes " + expected;
  } else {
    d.verdict = OrderVerdict::order_not_established;
    const bool narrow = fit.order_high - fit.order_low < 2 * j.tolerance;
    d.reason = interval + (misses_band ? " excludes " + expected + " but reaches " + num(j.minimum_order) +
                                             " (no convergence): too wide to decide"
                           : narrow    ? " straddles the edge of " + expected + " ± " + num(j.tolerance) +
                                          ": neither within the band nor outside it"
                                       : " overlaps " + expected + " ± " + num(j.tolerance) +
                                             " without lying within it: too wide to decide");
    // What makes it wide, where the data show it: an error that stops falling.
    if (growing > 0)
      d.reason += "; the error does not fall at " + std::to_string(growing) + " of " + std::to_string(fit.pairwise.size()) +
                  " refinements (pairwise orders ≤ 0)";
  }
  d.reason += zeros;
  return d;
}

}  // namespace stoneskip
