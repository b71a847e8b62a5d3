#include "verification/captures/capture_timing.hpp"

#include <algorithm>
#include <cmath>

namespace stoneskip {

TimedSamples analyse_timing(const Trace& trace) {
  TimedSamples out;
  TimingStats& s = out.stats;
  s.samples = trace.samples.size();
  s.nominal = trace.nominal_timestamps;
  std::vector<double> stamps;
  for (std::size_t k = 0; k < trace.samples.size(); ++k) {
    if (trace.samples[k].flags & kRepeated) {
      ++s.repeated;
      continue;
    }
    out.index.push_back(k);
    stamps.push_back(trace.samples[k].t_s);
  }
  s.used = stamps.size();
  if (stamps.size() < 2) {
    out.t_s = stamps;
    out.report_index.assign(stamps.size(), 0);
    return out;
  }
  s.duration_s = stamps.back() - stamps.front();
  std::vector<double> dt(stamps.size() - 1);
  for (std::size_t k = 1; k < stamps.size(); ++k) dt[k - 1] = stamps[k] - stamps[k - 1];
  std::vector<double> sorted = dt;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  s.period_s = sorted[sorted.size() / 2];
  if (!(s.period_s > 0) || !std::isfinite(s.period_s)) {
    out.t_s = stamps;
    out.report_index.assign(stamps.size(), 0);
    return out;
  }
  s.ok = true;
  s.rate_hz = 1.0 / s.period_s;
  // Gaps, lost reports, report indices.
  constexpr double kGapFactor = 1.5;     // an interval of 1.5 periods or more is a gap
  constexpr long kMaxLostPerGap = 1000000;  // bounds the index arithmetic for absurd stamps
  out.report_index.assign(stamps.size(), 0);
  double sum = 0, sum2 = 0;
  long n_ok = 0;
  for (std::size_t k = 0; k < dt.size(); ++k) {
    long step = 1;
    if (dt[k] >= kGapFactor * s.period_s) {
      const double ratio = std::min(dt[k] / s.period_s, double(kMaxLostPerGap));
      step = std::max(2L, std::lround(ratio));
      ++s.gaps;
      s.dropped_reports += step - 1;
      s.longest_gap_s = std::max(s.longest_gap_s, dt[k]);
    } else {
      sum += dt[k];
      sum2 += dt[k] * dt[k];
      ++n_ok;
      s.max_jitter_s = std::max(s.max_jitter_s, std::abs(dt[k] - s.period_s));
    }
    out.report_index[k + 1] = out.report_index[k] + step;
  }
  if (n_ok > 1) {
    const double mean = sum / n_ok;
    double var = 0;
    for (std::size_t k = 0; k < dt.size(); ++k)
      if (dt[k] < kGapFactor * s.period_s) var += (dt[k] - mean) * (dt[k] - mean);
    s.jitter_s = std::sqrt(var / double(n_ok - 1));
  }
  if (trace.nominal_timestamps) {
    out.t_s = stamps;
    return out;
  }
  // Least-squares clock t = a + b n.
  const double n = double(stamps.size());
  double mi = 0, mt = 0;
  for (std::size_t k = 0; k < stamps.size(); ++k) mi += double(out.report_index[k]), mt += stamps[k];
  mi /= n;
  mt /= n;
  double sii = 0, sit = 0;
  for (std::size_t k = 0; k < stamps.size(); ++k) {
    const double di = double(out.report_index[k]) - mi;
    sii += di * di;
    sit += di * (stamps[k] - mt);
  }
  const double b = sii > 0 ? sit / sii : s.period_s;
  if (!(b > 0) || !std::isfinite(b)) {
    out.t_s = stamps;
    return out;
  }
  out.t_s.resize(stamps.size());
  double r2 = 0;
  for (std::size_t k = 0; k < stamps.size(); ++k) {
    out.t_s[k] = mt + b * (double(out.report_index[k]) - mi);
    r2 += (stamps[k] - out.t_s[k]) * (stamps[k] - out.t_s[k]);
  }
  s.clock_residual_rms_s = std::sqrt(r2 / n);
  return out;
}

}  // namespace stoneskip
