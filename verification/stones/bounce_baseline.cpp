#include "verification/stones/bounce_baseline.hpp"

#include <cmath>
#include <cstdio>

namespace stoneskip {

BaselineComparison compare_with_baseline(const BounceBaseline& stored, const BounceSweepResult& now) {
  BaselineComparison c;
  c.name = stored.name;
  c.grid_points = static_cast<int>(stored.values.size());
  c.thresholds = static_cast<int>(stored.thresholds.size());
  const std::string unit = std::string(" ") + unit_of(stored.parameter);
  const std::string pname = to_string(stored.parameter);
  auto fmt = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return std::string(buf);
  };
  if (!stored.has_result) {
    c.passed = false;
    c.regressions.push_back("the baseline has no [result] (run `stoneskip regress --update --baseline " + stored.file + "`)");
    return c;
  }
  for (std::size_t i = 0; i < stored.values.size() && i < now.counts.size(); ++i) {
    if (stored.counts[i] == now.counts[i]) continue;
    const double v = stored.values[i];
    bool near = false;
    for (const auto& t : stored.thresholds) near = near || std::abs(v - t.value()) <= stored.compare_tolerance;
    std::string line = "count at " + pname + " = " + fmt(v) + unit + ": stored " + std::to_string(stored.counts[i]) +
                       ", now " + std::to_string(now.counts[i]);
    if (now.counts[i] < 0 && !now.failures[i].empty()) line += " (solver failed: " + now.failures[i] + ")";
    if (near)
      c.tolerated.push_back(line + " (within " + fmt(stored.compare_tolerance) + unit + " of a stored threshold)");
    else
      c.regressions.push_back(line);
  }
  std::vector<bool> used(now.thresholds.size(), false);
  for (const auto& t : stored.thresholds) {
    int best = -1;
    double best_d = 0;
    for (std::size_t j = 0; j < now.thresholds.size(); ++j) {
      const auto& n = now.thresholds[j];
      if (used[j] || n.count_below != t.count_below || n.count_above != t.count_above) continue;
      const double d = std::abs(n.value() - t.value());
      if (best < 0 || d < best_d) {
        best = static_cast<int>(j);
        best_d = d;
      }
    }
    const std::string what = "threshold " + std::to_string(t.count_below) + " -> " + std::to_string(t.count_above) +
                             " bounces stored at " + pname + " = " + fmt(t.value()) + unit;
    if (best >= 0 && best_d <= stored.compare_tolerance) {
      used[best] = true;
      continue;
    }
    if (best >= 0)
      c.regressions.push_back(what + ": now at " + fmt(now.thresholds[best].value()) + unit + " (moved " + fmt(best_d) +
                              unit + ", tolerance " + fmt(stored.compare_tolerance) + unit + ")");
    else
      c.regressions.push_back(what + ": gone");
    if (best >= 0) used[best] = true;
  }
  for (std::size_t j = 0; j < now.thresholds.size(); ++j) {
    if (used[j]) continue;
    const auto& n = now.thresholds[j];
    c.regressions.push_back("new threshold " + std::to_string(n.count_below) + " -> " + std::to_string(n.count_above) +
                            " bounces at " + pname + " = " + fmt(n.value()) + unit + " (not in the baseline)");
  }
  c.passed = c.regressions.empty();
  return c;
}

}  // namespace stoneskip
