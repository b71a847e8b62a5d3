#include "verification/captures/capture_timing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace stoneskip {

const char* to_string(ClockModel m) {
  switch (m) {
    case ClockModel::automatic: return "automatic";
    case ClockModel::regular_reports: return "regular_reports";
    case ClockModel::stamps_as_given: return "stamps_as_given";
  }
  return "?";
}

namespace {

// Least-squares line t = mt + b (slot − mi) through the (slot, stamp) pairs; false if degenerate.
bool fit_clock(const std::vector<long>& slot, const std::vector<double>& stamps, double& mi, double& mt, double& b) {
  const double n = double(stamps.size());
  mi = mt = 0;
  for (std::size_t k = 0; k < stamps.size(); ++k) mi += double(slot[k]), mt += stamps[k];
  mi /= n;
  mt /= n;
  double sii = 0, sit = 0;
  for (std::size_t k = 0; k < stamps.size(); ++k) {
    const double di = double(slot[k]) - mi;
    sii += di * di;
    sit += di * (stamps[k] - mt);
  }
  b = sii > 0 ? sit / sii : 0.0;
  return b > 0 && std::isfinite(b);
}

}  // namespace

TimedSamples analyse_timing(const Trace& trace, const TimingOptions& o) {
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
  out.t_s = stamps;
  out.report_index.assign(stamps.size(), 0);
  if (stamps.size() < 2) return out;
  s.duration_s = stamps.back() - stamps.front();
  if (s.duration_s > 0) s.mean_rate_hz = double(stamps.size() - 1) / s.duration_s;
  std::vector<double> dt(stamps.size() - 1);
  for (std::size_t k = 1; k < stamps.size(); ++k) dt[k - 1] = stamps[k] - stamps[k - 1];
  s.min_interval_s = *std::min_element(dt.begin(), dt.end());
  s.max_interval_s = *std::max_element(dt.begin(), dt.end());
  s.equal_stamps = std::size_t(std::count(dt.begin(), dt.end(), 0.0));
  std::vector<double> sorted = dt;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  s.period_s = sorted[sorted.size() / 2];
  // Reports that reach the host in bursts (a logger reading its queue in batches: two or more
  // stamped within a fraction of a period, then a long wait) make the single intervals a mix of
  // near zero and several periods, whose median is neither. Where more than a quarter of the
  // intervals are shorter than half the median mean interval over kBurstWindow intervals (host
  // jitter alone makes a few; lost reports make intervals longer, not shorter), the stamps are
  // grouped into bursts at those short intervals. A burst is stamped when its last report arrives,
  // so the time from one burst's last stamp to a later one's holds the reports of the bursts
  // between: the period is the median, over runs of consecutive bursts holding at least
  // kBurstWindow reports (so bursts of varying size, 2, 3, 2, 3 from a 25 ms poll of a 100 Hz
  // remote, average out), of that time over their number.
  constexpr std::size_t kBurstWindow = 8;
  std::vector<std::size_t> burst_end;  // index of each burst's last stamp (bursts only)
  if (dt.size() >= 2 * kBurstWindow) {
    std::vector<double> window(stamps.size() - kBurstWindow);
    for (std::size_t k = 0; k < window.size(); ++k)
      window[k] = (stamps[k + kBurstWindow] - stamps[k]) / double(kBurstWindow);
    std::nth_element(window.begin(), window.begin() + window.size() / 2, window.end());
    const double split = 0.5 * window[window.size() / 2];
    const auto short_intervals = std::count_if(dt.begin(), dt.end(), [&](double d) { return d < split; });
    if (split > 0 && 4 * std::size_t(short_intervals) > dt.size()) {
      for (std::size_t k = 0; k < dt.size(); ++k)
        if (dt[k] >= split) burst_end.push_back(k);
      burst_end.push_back(dt.size());
      std::vector<double> per_report;
      for (std::size_t g = 0, h = 1; g + 1 < burst_end.size(); ++g) {
        h = std::max(h, g + 1);
        while (h + 1 < burst_end.size() && burst_end[h] - burst_end[g] < kBurstWindow) ++h;
        if (burst_end[h] - burst_end[g] < kBurstWindow) break;  // the rest holds fewer reports
        per_report.push_back((stamps[burst_end[h]] - stamps[burst_end[g]]) / double(burst_end[h] - burst_end[g]));
      }
      if (!per_report.empty()) {
        std::nth_element(per_report.begin(), per_report.begin() + per_report.size() / 2, per_report.end());
        s.period_s = per_report[per_report.size() / 2];
        s.bursts = true;
      }
    }
  }
  if (!(s.period_s > 0) || !std::isfinite(s.period_s)) return out;
  s.ok = true;
  s.rate_hz = 1.0 / s.period_s;
  // Gaps, lost reports, report slots.
  constexpr long kMaxLostPerGap = 1000000;  // bounds the slot arithmetic for absurd stamps
  const double gap = o.gap_factor * s.period_s;
  double sum = 0;
  long n_ok = 0;
  std::vector<char> counted(dt.size(), 0);  // the intervals the jitter is taken over
  auto lost = [&](std::size_t k, long step) {  // interval k skipped step − 1 slots
    ++s.gaps;
    s.dropped_reports += step - 1;
    s.longest_gap_s = std::max(s.longest_gap_s, dt[k]);
  };
  auto jitter = [&](std::size_t k) {
    sum += dt[k];
    ++n_ok;
    counted[k] = 1;
    s.max_jitter_s = std::max(s.max_jitter_s, std::abs(dt[k] - s.period_s));
  };
  if (s.bursts) {
    // Each burst's last report is as many slots after the previous burst's last as it has reports,
    // and more where the time between them exceeds that by three quarters of a period or more: a
    // poll that is no whole number of periods (25 ms of a 100 Hz remote: bursts of 2 and 3 in
    // 2.5 periods) must not count a loss in every short burst, so a loss needs most of a period
    // to show. The others precede it slot by slot; slots skipped are reports lost (an estimate,
    // within a report per burst). Every interval inside a burst and every one into a burst that
    // skips no slot is the bursts' jitter.
    std::size_t first = 0;
    for (std::size_t g = 0; g < burst_end.size(); ++g) {
      const std::size_t last = burst_end[g];
      long end_slot = long(last);
      if (g > 0) {
        const std::size_t prev = burst_end[g - 1];
        const long reports = long(last - prev);
        const double x = std::min((stamps[last] - stamps[prev]) / s.period_s, double(kMaxLostPerGap));
        const long slots_between = std::max(reports, static_cast<long>(std::floor(x + 0.25)));
        end_slot = out.report_index[prev] + slots_between;
        if (slots_between > reports) lost(prev, slots_between - reports + 1);
        else jitter(prev);
      }
      for (std::size_t k = first; k <= last; ++k) out.report_index[k] = end_slot - long(last - k);
      for (std::size_t k = first; k < last; ++k) jitter(k);
      first = last + 1;
    }
  }
  for (std::size_t k = 0; k < dt.size() && !s.bursts; ++k) {
    long step = 1;
    if (dt[k] >= gap) {
      const double ratio = std::min(dt[k] / s.period_s, double(kMaxLostPerGap));
      step = std::max(2L, std::lround(ratio));
      lost(k, step);
    } else {
      jitter(k);
    }
    out.report_index[k + 1] = out.report_index[k] + step;
  }
  if (n_ok > 1) {
    const double mean = sum / double(n_ok);
    double var = 0;
    for (std::size_t k = 0; k < dt.size(); ++k)
      if (counted[k]) var += (dt[k] - mean) * (dt[k] - mean);
    s.jitter_s = std::sqrt(var / double(n_ok - 1));
  }
  if (trace.nominal_timestamps) return out;
  // The remote's regular clock. Slots counted interval by interval go wrong where the jitter makes
  // an interval look like a gap or hides one, and the error carries into every later slot. So the
  // clock is found from many stamps at once: for each trial period P within ±20 % of the typical
  // interval, the phases t/P mod 1 of the first 256 stamps are sorted and the shortest arc holding
  // them all is found (one minus the largest gap between neighbouring phases); the period with the
  // shortest arc is the clock's, and each stamp's slot is the nearest to its phase in that arc. Later
  // stamps are tracked with a least-squares clock through the slots so far, then all are checked
  // against the final period. Half the arc, in periods, is the largest distance of a stamp from its
  // slot; a least-squares line through (slot, stamp) gives the clock.
  double mi = 0, mt = 0, b = 0;
  std::vector<long> slots = out.report_index;
  bool fitted = false;
  double minimax_residual_s = std::numeric_limits<double>::infinity();
  if (s.duration_s > 0) {
    const double t0 = stamps.front();
    std::vector<double> phase;
    // The shortest arc (in cycles) holding the phases of stamps[0, m) for a period; centre: its middle.
    auto shortest_arc = [&](double period, std::size_t m, double& centre) {
      phase.resize(m);
      for (std::size_t k = 0; k < m; ++k) {
        const double x = (stamps[k] - t0) / period;
        phase[k] = x - std::floor(x);
      }
      std::sort(phase.begin(), phase.end());
      double widest = phase.front() + 1.0 - phase.back(), start = phase.front();  // the widest gap, the wrap-around one first
      for (std::size_t k = 1; k < m; ++k)
        if (phase[k] - phase[k - 1] > widest) widest = phase[k] - phase[k - 1], start = phase[k];
      centre = start + 0.5 * (1.0 - widest);
      return 1.0 - widest;
    };
    auto assign = [&](double period, double centre, std::size_t m) {  // false unless increasing
      for (std::size_t k = 0; k < m; ++k) {
        const double x = (stamps[k] - t0) / period - centre;
        if (!(std::abs(x) < 1e12)) return false;
        slots[k] = std::lround(x);
        if (k > 0 && slots[k] <= slots[k - 1]) return false;
      }
      return true;
    };
    // 1. The period from the first kHead stamps (the search costs ~40·m² log m): the arc changes by
    // about m·δP/P over a step δP, so step for 1 % of a cycle.
    constexpr std::size_t kHead = 256;
    const std::size_t m = std::min(stamps.size(), kHead);
    const long steps = 40 * long(m);  // 0.4 P in steps of 0.01 P/m (counted, so no step can vanish)
    double best = 2, best_period = s.period_s, best_centre = 0;
    for (long i = 0; i <= steps; ++i) {
      const double period = s.period_s * (0.8 + 0.4 * double(i) / double(steps));
      double centre = 0;
      const double arc = shortest_arc(period, m, centre);
      if (arc < best) best = arc, best_period = period, best_centre = centre;
    }
    bool ok = best < 1.0 && assign(best_period, best_centre, m);
    // 2. The rest tracked: a least-squares clock through the slots so far gives each next slot.
    if (ok && m < stamps.size()) {
      double n_s = 0, si = 0, st = 0, sii = 0, sit = 0, intercept = 0, slope = 0;
      auto add = [&](long i, double t) {
        n_s += 1, si += double(i), st += t, sii += double(i) * double(i), sit += double(i) * t;
      };
      auto refit = [&] {
        const double d = n_s * sii - si * si;
        if (!(d > 0)) return false;
        slope = (n_s * sit - si * st) / d;
        intercept = (st - slope * si) / n_s;
        return slope > 0 && std::isfinite(slope) && std::isfinite(intercept);
      };
      for (std::size_t k = 0; k < m; ++k) add(slots[k], stamps[k]);
      ok = refit();
      for (std::size_t k = m; k < stamps.size() && ok; ++k) {
        const double x = (stamps[k] - intercept) / slope;
        if (!(std::abs(x) < 1e12)) ok = false;
        else {
          slots[k] = std::max(slots[k - 1] + 1, std::lround(x));
          add(slots[k], stamps[k]);
          ok = refit();
        }
      }
      // 3. Every stamp against the final period: its arc and its slot.
      if (ok) {
        best_period = slope;
        best = shortest_arc(best_period, stamps.size(), best_centre);
        ok = best < 1.0 && assign(best_period, best_centre, stamps.size());
      }
    }
    if (ok) {
      const long first = slots.front();
      for (long& x : slots) x -= first;
      fitted = fit_clock(slots, stamps, mi, mt, b);
      minimax_residual_s = 0.5 * best * best_period;
    }
  }
  if (!fitted) {
    slots = out.report_index;
    fitted = fit_clock(slots, stamps, mi, mt, b);
  }
  std::vector<double> clock(stamps.size());
  if (fitted) {
    double r2 = 0;
    for (std::size_t k = 0; k < stamps.size(); ++k) {
      clock[k] = mt + b * (double(slots[k]) - mi);
      const double r = stamps[k] - clock[k];
      r2 += r * r;
      s.clock_residual_max_s = std::max(s.clock_residual_max_s, std::abs(r));
    }
    s.clock_residual_rms_s = std::sqrt(r2 / double(stamps.size()));
  }
  bool regular = false;
  switch (o.clock) {
    case ClockModel::regular_reports: regular = fitted; break;
    case ClockModel::stamps_as_given: regular = false; break;
    case ClockModel::automatic:
      // Every stamp within half a period of a regular clock: by the least-squares line, or by the
      // minimax phase arc (the line may stray a little further where the jitter is large).
      regular = fitted && std::min(s.clock_residual_max_s, minimax_residual_s) <= o.regular_max_residual_intervals * b;
      break;
  }
  if (regular && slots != out.report_index) {
    // The gaps and the jitter by the refined slots: an interval spanning one slot is not a gap.
    out.report_index = slots;
    s.gaps = 0;
    s.dropped_reports = 0;
    s.longest_gap_s = 0;
    s.max_jitter_s = 0;
    double sum1 = 0, sum2 = 0;
    long n1 = 0;
    for (std::size_t k = 0; k < dt.size(); ++k) {
      const long step = slots[k + 1] - slots[k];
      if (step > 1) {
        ++s.gaps;
        s.dropped_reports += step - 1;
        s.longest_gap_s = std::max(s.longest_gap_s, dt[k]);
      } else {
        sum1 += dt[k];
        sum2 += dt[k] * dt[k];
        ++n1;
        s.max_jitter_s = std::max(s.max_jitter_s, std::abs(dt[k] - s.period_s));
      }
    }
    if (n1 > 1) s.jitter_s = std::sqrt(std::max(0.0, (sum2 - sum1 * sum1 / double(n1)) / double(n1 - 1)));
  }
  s.clock = regular ? ClockModel::regular_reports : ClockModel::stamps_as_given;
  if (regular) {
    out.t_s = clock;
    s.clock_rate_hz = 1.0 / b;
  }
  return out;
}

}  // namespace stoneskip
