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
  // Per step: 1 / (step in typical steps); 1 for a regular rate. A zero step (equal stamps)
  // counts as a typical one.
  std::vector<double> step_scale(n, 1.0);
  if (t_s.size() == n && n > 2) {
    std::vector<double> dt;
    for (std::size_t k = 1; k < n; ++k)
      if (t_s[k] > t_s[k - 1]) dt.push_back(t_s[k] - t_s[k - 1]);
    if (!dt.empty()) {
      std::nth_element(dt.begin(), dt.begin() + std::ptrdiff_t(dt.size() / 2), dt.end());
      const double typical = dt[dt.size() / 2];
      for (std::size_t k = 1; k < n; ++k) {
        const double steps = t_s[k] > t_s[k - 1] ? (t_s[k] - t_s[k - 1]) / typical : 1.0;
        step_scale[k] = 1.0 / steps;
      }
    }
  }
  // The rate's slope into sample k in state pair (p at k−1, s at k), slow-mode counts per typical step.
  auto slope = [&](std::size_t k, int axis, int p, int s) {
    const double w = counts[k][axis] * (s ? fast_factor : 1.0), wp = counts[k - 1][axis] * (p ? fast_factor : 1.0);
    return (w - wp) * step_scale[k];
  };
  if (n == 1) return out;
  // State (p, s): the modes at k−1 and k, index 2p + s. back[4k + state] is the mode at k−2.
  std::vector<std::uint8_t> back(4 * n);
  for (int axis = 0; axis < 3; ++axis) {
    // k = 1: the first step's slope anchors the start, which is in slow mode (a fast start costs a switch).
    double cost[4];
    for (int p = 0; p < 2; ++p)
      for (int s = 0; s < 2; ++s) {
        const double d = slope(1, axis, p, s);
        cost[2 * p + s] = d * d + switch_cost * (p + (p != s ? 1 : 0));
      }
    for (std::size_t k = 2; k < n; ++k) {
      double next[4];
      for (int p = 0; p < 2; ++p)
        for (int s = 0; s < 2; ++s) {
          const double in = slope(k, axis, p, s);
          double best = 0;
          int from = 0;
          for (int a = 0; a < 2; ++a) {
            const double change = in - slope(k - 1, axis, a, p);
            const double c = cost[2 * a + p] + change * change + (p != s ? switch_cost : 0.0);
            if (a == 0 || c < best) best = c, from = a;
          }
          next[2 * p + s] = best;
          back[4 * k + 2 * p + s] = std::uint8_t(from);
        }
      std::copy(next, next + 4, cost);
    }
    int state = int(std::min_element(cost, cost + 4) - cost);
    for (std::size_t k = n - 1; k >= 1; --k) {
      const int p = state / 2, s = state % 2;
      out.fast[k][axis] = s == 1;
      out.fast[k - 1][axis] = p == 1;
      if (p != s) ++out.switches;
      if (k >= 2) state = 2 * back[4 * k + state] + p;
    }
  }
  return out;
}

}  // namespace stoneskip
