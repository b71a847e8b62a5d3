#pragma once
// Timing of a capture (model/README.md §4: the remote sends no timestamp; the recorder stamps each report
// with the host clock, so jitter, gaps and repeats are normal). Nothing here assumes a rate that
// the time column does not show:
//   * repeated reports (flag R) are dropped and counted;
//   * the typical interval is the median interval (the "rate" is its inverse; the mean rate over
//     the recording is reported beside it); an interval of gap_factor typical intervals or more is
//     a gap, and about round(interval / typical) − 1 reports were lost in it. Reports that reach the
//     host in bursts (more than a quarter of the intervals shorter than half the median mean
//     interval over 8 consecutive intervals) are grouped into bursts: the typical interval is the
//     median, over runs of bursts holding 8 reports or more, of the time between the runs' last
//     stamps over their reports, and slots are counted burst by burst (a loss where a burst's
//     time exceeds its reports by ¾ of a period or more);
//   * jitter = standard deviation of the intervals that are not gaps, with the largest deviation,
//     the shortest and longest interval and the number of equal stamps;
//   * the clock (ClockModel): a Wii Remote sends its reports on its own regular clock and the host
//     adds jitter. Its period is found from all stamps at once: the one (within ±20 % of the typical
//     interval) for which the stamps' phases t/P mod 1 fit in the shortest arc; each report's slot
//     is the one nearest its phase (gaps counted from the slots), and a least-squares line through
//     (slot, stamp) is the clock.
//     Valid only when every stamp lies within half a period of its slot (the arc shorter than one
//     period; otherwise the slots are ambiguous).
//     `automatic` checks exactly that and otherwise uses the stamps as given (a logger whose rows
//     are not one per report, a device without a regular clock). Integration always uses the
//     actual steps between the times chosen here, never a nominal dt.
// Traces with nominal timestamps (no time column: gesture files) are left as they are (jitter
// unknown).
#include <cstddef>
#include <string>
#include <vector>

#include "verification/captures/capture_trace.hpp"

namespace stoneskip {

enum class ClockModel {
  automatic,        // regular_reports when every stamp is within half an interval of its slot
  regular_reports,  // the remote's regular clock fitted through the report slots (de-jittered)
  stamps_as_given,  // the host stamps, unchanged
};
const char* to_string(ClockModel m);

struct TimingOptions {
  ClockModel clock = ClockModel::automatic;
  // An interval this many typical intervals long or longer is a gap. 1.5: halfway between one and
  // two report periods, so one lost report is counted whatever the jitter below half a period.
  double gap_factor = 1.5;
  // automatic: the largest |stamp − fitted clock| allowed for regular_reports, in typical intervals.
  // 0.5: beyond it a stamp could belong to the neighbouring slot and the slot count is ambiguous.
  double regular_max_residual_intervals = 0.5;
};

struct TimingStats {
  std::size_t samples = 0;      // in the file
  std::size_t repeated = 0;     // dropped as repeats
  std::size_t used = 0;
  double duration_s = 0;
  double period_s = 0;          // median interval (bursts: see above)
  double rate_hz = 0;           // 1 / period_s
  double mean_rate_hz = 0;      // (used − 1) / duration
  double jitter_s = 0;          // std of the non-gap intervals
  double max_jitter_s = 0;      // largest |interval − period| among non-gap intervals
  double min_interval_s = 0, max_interval_s = 0;
  std::size_t equal_stamps = 0; // intervals of exactly zero (two reports stamped alike)
  double clock_residual_rms_s = 0;  // RMS of stamp − fitted regular clock
  double clock_residual_max_s = 0;  // largest |stamp − fitted regular clock|
  ClockModel clock = ClockModel::stamps_as_given;  // the model used (never automatic)
  double clock_rate_hz = 0;     // regular_reports: 1 / the fitted clock's period (the rate the
                                // times use, which the median interval can miss); 0 otherwise
  int gaps = 0;
  long dropped_reports = 0;     // estimated from the gaps' lengths
  double longest_gap_s = 0;
  bool nominal = false;         // times from the nominal rate (no host stamps)
  bool ok = false;              // a positive period could be found
  bool bursts = false;          // the reports reached the host in bursts (see above)
};

struct TimedSamples {
  TimingStats stats;
  std::vector<std::size_t> index;  // into trace.samples, kept samples only
  std::vector<double> t_s;         // the times used: fitted clock or stamps (ClockModel)
  std::vector<long> report_index;  // slot in the remote's report sequence (gaps counted)
};

TimedSamples analyse_timing(const Trace& trace, const TimingOptions& options = {});

}  // namespace stoneskip
