#include "tools/capture/gyro_range.hpp"

#include <algorithm>
#include <cstdint>

namespace stoneskip {

GyroRangeInference infer_gyro_range(const std::vector<std::array<double, 3>>& counts, double fast_factor,
                                    const std::vector<double>& t_s, double switch_cost) {
  GyroRangeInference out;
  const std::size_t n = counts.size();
  out.fast.assign(n, {false, false, false});
  if (n == 0) return out;
  // Per step: 1 / (step in typical steps), squared; 1 for a regular rate. A zero step (equal
  // stamps) counts as a typical one.
  std::vector<double> weight(n, 1.0);
  if (t_s.size() == n && n > 2) {
    std::vector<double> dt;
    for (std::size_t k = 1; k < n; ++k)
      if (t_s[k] > t_s[k - 1]) dt.push_back(t_s[k] - t_s[k - 1]);
    if (!dt.empty()) {
      std::nth_element(dt.begin(), dt.begin() + std::ptrdiff_t(dt.size() / 2), dt.end());
      const double typical = dt[dt.size() / 2];
      for (std::size_t k = 1; k < n; ++k) {
        const double steps = t_s[k] > t_s[k - 1] ? (t_s[k] - t_s[k - 1]) / typical : 1.0;
        weight[k] = 1.0 / (steps * steps);
      }
    }
  }
  std::vector<std::uint8_t> back(2 * n);
  for (int axis = 0; axis < 3; ++axis) {
    // cost[s] of the best path ending in state s (0 slow, 1 fast); start in slow mode.
    double cost[2] = {0.0, switch_cost};
    for (std::size_t k = 1; k < n; ++k) {
      double next[2];
      for (int s = 0; s < 2; ++s) {
        const double w = counts[k][axis] * (s ? fast_factor : 1.0);
        double best = 0;
        int from = 0;
        for (int p = 0; p < 2; ++p) {
          const double wp = counts[k - 1][axis] * (p ? fast_factor : 1.0);
          const double c = cost[p] + weight[k] * (w - wp) * (w - wp) + (p != s ? switch_cost : 0.0);
          if (p == 0 || c < best) best = c, from = p;
        }
        next[s] = best;
        back[2 * k + s] = std::uint8_t(from);
      }
      cost[0] = next[0];
      cost[1] = next[1];
    }
    int s = cost[1] < cost[0] ? 1 : 0;
    for (std::size_t k = n; k-- > 0;) {
      out.fast[k][axis] = s == 1;
      if (k > 0) {
        const int p = back[2 * k + s];
        if (p != s) ++out.switches;
        s = p;
      }
    }
  }
  return out;
}

}  // namespace stoneskip
