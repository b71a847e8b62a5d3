#include "reports/common/colour_scale.hpp"

#include <algorithm>
#include <cmath>

namespace stoneskip {

RobustScale robust_scale(const std::vector<double>& z) {
  RobustScale r;
  for (double v : z)
    if (std::isfinite(v)) r.largest = std::max(r.largest, std::abs(v));
  if (!(r.largest > 0)) return r;
  std::vector<double> a;
  for (double v : z)
    if (std::isfinite(v) && std::abs(v) > kDisturbedFraction * r.largest) a.push_back(std::abs(v));
  r.disturbed = a.size();
  // The value with at most (1 - p) of the disturbed cells above it (nearest rank).
  const std::size_t k = std::min(a.size() - 1, static_cast<std::size_t>(std::ceil(kScalePercentile * double(a.size()))) - 1);
  std::nth_element(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(k), a.end());
  r.scale = a[k];
  r.beyond = static_cast<std::size_t>(std::count_if(a.begin(), a.end(), [&](double v) { return v > r.scale; }));
  return r;
}

}  // namespace stoneskip
