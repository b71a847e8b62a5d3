#pragma once
// Timing of a capture (spec §4: the remote sends no timestamp; the recorder stamps each report
// with the host clock, so jitter and dropped reports are normal).
//   * repeated reports (flag R) are dropped;
//   * the nominal period is the median interval; an interval longer than 1.5 periods is a gap, and
//     round(interval / period) − 1 reports were lost in it;
//   * jitter = standard deviation of the intervals that are not gaps (and their largest deviation
//     from the period);
//   * de-jittering: each kept report gets its index in the remote's own sequence (gaps counted),
//     and the host stamps are replaced by a least-squares line through (index, stamp), so the
//     remote's regular clock is recovered; the residual RMS is the stamps' own jitter.
// Traces with nominal timestamps (gesture format) are left as they are (jitter unknown).
#include <cstddef>
#include <vector>

#include "verification/captures/capture_trace.hpp"

namespace stoneskip {

struct TimingStats {
  std::size_t samples = 0;      // in the file
  std::size_t repeated = 0;     // dropped as repeats
  std::size_t used = 0;
  double duration_s = 0;
  double period_s = 0;          // median interval
  double rate_hz = 0;
  double jitter_s = 0;          // std of the non-gap intervals
  double max_jitter_s = 0;      // largest |interval − period| among non-gap intervals
  double clock_residual_rms_s = 0;  // RMS of stamp − fitted clock
  int gaps = 0;
  long dropped_reports = 0;
  double longest_gap_s = 0;
  bool nominal = false;         // times from the nominal rate (no host stamps)
  bool ok = false;              // a positive period could be found
};

struct TimedSamples {
  TimingStats stats;
  std::vector<std::size_t> index;  // into trace.samples, kept samples only
  std::vector<double> t_s;         // de-jittered times of those samples
  std::vector<long> report_index;  // position in the remote's report sequence
};

TimedSamples analyse_timing(const Trace& trace);

}  // namespace stoneskip
