#include "tools/capture/capture_times.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "tools/capture/capture_text.hpp"

namespace stoneskip {

double median_time_s(const Trace& t) {
  std::vector<double> times;
  for (const TraceSample& x : t.samples)
    if (std::isfinite(x.t_s)) times.push_back(x.t_s);
  if (times.empty()) return 0;
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  return times[times.size() / 2];
}

void count_times_from_first(Trace& t) {
  if (t.samples.empty()) return;
  const double median = median_time_s(t), first = t.samples.front().t_s;
  for (const TraceSample& x : t.samples)
    if (!std::isfinite(x.t_s) || !(std::abs(x.t_s - median) <= kMaxCaptureTimeSpread_s)) return;
  for (TraceSample& x : t.samples) x.t_s -= first;
}

}  // namespace stoneskip
