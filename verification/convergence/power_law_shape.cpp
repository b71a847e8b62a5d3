#include "verification/convergence/power_law_shape.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/distributions/fisher_f.hpp>
#include <cmath>
#include <limits>
#include <utility>

namespace stoneskip {

PowerLawShape test_power_law_shape(const std::vector<double>& x, const std::vector<double>& y) {
  PowerLawShape s;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  s.local_min = s.local_max = nan;
  std::vector<std::pair<double, double>> p;  // (log x, log y), in order of x
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i)
    if (x[i] > 0 && y[i] > 0 && std::isfinite(x[i]) && std::isfinite(y[i])) p.emplace_back(std::log(x[i]), std::log(y[i]));
  std::sort(p.begin(), p.end());
  const int n = static_cast<int>(p.size());
  s.points = n;
  for (int i = 0; i + 1 < n; ++i) {
    if (!(p[i + 1].first > p[i].first)) continue;  // a repeated x has no local exponent
    const double k = (p[i + 1].second - p[i].second) / (p[i + 1].first - p[i].first);
    s.local_min = std::isnan(s.local_min) ? k : std::min(s.local_min, k);
    s.local_max = std::isnan(s.local_max) ? k : std::max(s.local_max, k);
  }
  if (n < 4) return s;
  double mean = 0;
  for (const auto& q : p) mean += q.first / n;
  Eigen::MatrixXd X(n, 3);
  Eigen::VectorXd Y(n);
  for (int i = 0; i < n; ++i) {
    const double u = p[i].first - mean;  // centred: the quadratic column is not near-collinear with the line
    X(i, 0) = 1;
    X(i, 1) = u;
    X(i, 2) = u * u;
    Y(i) = p[i].second;
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> line(X.leftCols(2)), quadratic(X);
  if (quadratic.rank() < 3) return s;  // fewer than 3 distinct x
  const Eigen::Vector3d b = quadratic.solve(Y);
  const double sse1 = (Y - X.leftCols(2) * line.solve(Y)).squaredNorm();
  const double sse2 = (Y - X * b).squaredNorm();
  const double syy = (Y.array() - Y.mean()).matrix().squaredNorm();
  // A line through every point (to round-off): a power law, nothing to test against.
  if (!(sse1 > 1e-20 * syy)) return s;
  const double dof = n - 3;
  s.tested = true;
  s.f_critical = boost::math::quantile(boost::math::complement(boost::math::fisher_f(1, dof), 0.05));
  // A quadratic through every point that the line misses: as curved as a series can be.
  s.f_statistic = sse2 > 1e-20 * syy ? std::max(0.0, sse1 - sse2) / (sse2 / dof) : std::numeric_limits<double>::infinity();
  s.curved = s.f_statistic > s.f_critical;
  s.quadratic_slope_at_min_x = b(1) + 2 * b(2) * (p.front().first - mean);
  s.quadratic_slope_at_max_x = b(1) + 2 * b(2) * (p.back().first - mean);
  return s;
}

}  // namespace stoneskip
