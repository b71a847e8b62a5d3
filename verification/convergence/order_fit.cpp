#include "verification/convergence/order_fit.hpp"

#include <boost/math/distributions/students_t.hpp>

#include <cmath>
#include <cstdio>

namespace stoneskip {

OrderFit fit_order(const std::vector<double>& h, const std::vector<double>& error) {
  OrderFit fit;
  if (h.size() != error.size()) {
    fit.problem = "h and error have different lengths";
    return fit;
  }
  std::vector<double> x, y;
  for (std::size_t i = 0; i < h.size(); ++i) {
    if (h[i] > 0 && error[i] > 0 && std::isfinite(h[i]) && std::isfinite(error[i])) {
      x.push_back(std::log(h[i]));
      y.push_back(std::log(error[i]));
    }
  }
  fit.points = static_cast<int>(x.size());
  if (x.size() < 2) {
    fit.problem = "fewer than 2 points with h > 0 and error > 0";
    return fit;
  }
  // Ordinary least squares y = a + p x (e.g. Montgomery & Runger, Applied Statistics, §11.2).
  const double n = static_cast<double>(x.size());
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= n;
  my /= n;
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  if (sxx <= 0) {
    fit.problem = "all h are equal";
    fit.points = static_cast<int>(x.size());
    return fit;
  }
  fit.order = sxy / sxx;
  fit.constant = std::exp(my - fit.order * mx);
  double sse = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    double r = y[i] - (my + fit.order * (x[i] - mx));
    sse += r * r;
  }
  fit.r_squared = syy > 0 ? 1 - sse / syy : 1;
  fit.order_low = fit.order_high = fit.order;
  if (x.size() > 2) {
    // 95 % two-sided interval of the slope: p ± t_{0.975, n−2} · sqrt(SSE/(n−2)/Sxx).
    boost::math::students_t dist(n - 2);
    double t = boost::math::quantile(boost::math::complement(dist, 0.025));
    double se = std::sqrt(sse / (n - 2) / sxx);
    fit.order_low = fit.order - t * se;
    fit.order_high = fit.order + t * se;
  }
  for (std::size_t i = 0; i + 1 < x.size(); ++i) fit.pairwise.push_back((y[i] - y[i + 1]) / (x[i] - x[i + 1]));
  fit.valid = true;
  return fit;
}

std::string OrderFit::brief() const {
  if (!valid) return "no fit: " + problem;
  char buf[128];
  std::snprintf(buf, sizeof buf, "p = %.3g [%.3g, %.3g] (%d points)", order, order_low, order_high, points);
  return buf;
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
    case OrderVerdict::insufficient_data: return "insufficient data";
  }
  return "?";
}

OrderVerdict judge_order(const OrderFit& fit, const OrderJudgement& j) {
  if (!fit.valid) return OrderVerdict::insufficient_data;
  // No convergence when the slope is (nearly) flat or negative, or when the interval cannot
  // exclude a flat error (the data are consistent with no convergence at all).
  if (fit.order <= j.minimum_order || fit.order_low <= 0) return OrderVerdict::does_not_converge;
  if (std::abs(fit.order - j.expected_order) <= j.tolerance &&
      std::abs(fit.order_low - j.expected_order) <= j.tolerance &&
      std::abs(fit.order_high - j.expected_order) <= j.tolerance)
    return OrderVerdict::converges_at_expected_order;
  return OrderVerdict::converges_at_other_order;
}

}  // namespace stoneskip
