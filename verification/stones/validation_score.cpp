#include "verification/stones/validation_score.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace stoneskip {

double quantity_distance(const ScoredValue& v, const MeasuredRange& r, double miss) {
  if (!v.has_value || !std::isfinite(v.model)) return miss;
  const double m = v.model;
  if (!(m / r.low > 0) || !(m / r.high > 0)) return miss;  // the other sign (or zero): no comparison
  if (m >= std::min(r.low, r.high) && m <= std::max(r.low, r.high)) return 0.0;
  const double d = std::min(std::abs(std::log(m / r.low)), std::abs(std::log(m / r.high)));
  return std::min(d, miss);
}

ModelDistance model_distance(const std::vector<ScoredValue>& values, const std::vector<MeasuredRange>& ranges, double miss) {
  if (values.size() != ranges.size()) throw std::invalid_argument("model_distance: one range per value");
  ModelDistance out;
  double sum = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    out.distances.push_back(quantity_distance(values[i], ranges[i], miss));
    sum += out.distances.back();
  }
  out.mean = values.empty() ? std::numeric_limits<double>::quiet_NaN() : sum / double(values.size());
  return out;
}

}  // namespace stoneskip
