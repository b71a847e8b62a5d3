#include "verification/captures/capture_verdict.hpp"

#include <cmath>
#include <cstdio>

#include "verification/captures/capture_analysis.hpp"

namespace stoneskip {

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::usable: return "usable";
    case Verdict::usable_with_caveats: return "usable with caveats";
    case Verdict::unusable: return "unusable";
  }
  return "?";
}

bool CaptureVerdictRules::is_valid(std::string* why) const {
  auto fail = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (min_samples < 3) return fail("rules.min_samples must be at least 3");
  if (!(min_rate_hz > 0)) return fail("rules.min_rate_hz must be positive");
  if (!(max_release_gap_s > 0)) return fail("rules.max_release_gap_s must be positive");
  if (!(calibration_caveat_g > 0 && calibration_unusable_g >= calibration_caveat_g))
    return fail("rules.calibration_caveat_g must be positive and at most rules.calibration_unusable_g");
  if (!(lost_fraction_caveat >= 0 && lost_fraction_caveat <= 1)) return fail("rules.lost_fraction_caveat must be in [0, 1]");
  if (!(jitter_caveat_s >= 0)) return fail("rules.jitter_caveat_s must not be negative");
  if (!(accel_lever_disagreement > 0)) return fail("rules.accel_lever_disagreement must be positive");
  return true;
}

namespace {
std::string format(const char* fmt, double a = 0, double b = 0, double c = 0) {
  char buf[320];
  std::snprintf(buf, sizeof buf, fmt, a, b, c);
  return buf;
}
}  // namespace

void judge_capture(CaptureAnalysis& a, const CaptureVerdictRules& r) {
  std::vector<std::string> fatal, caveats;
  const Trace& trace = a.trace;
  const TimingStats& ts = a.timing.stats;
  const std::size_t n = a.series.t_s.size();
  // Unusable.
  if (!trace.has_gyro) fatal.push_back("no MotionPlus data: the orientation through the throw cannot be followed");
  if (n < r.min_samples) fatal.push_back(format("only %.0f usable samples (at least %.0f needed)", double(n), double(r.min_samples)));
  if (!ts.ok) fatal.push_back("no sample rate can be found from the timestamps");
  else if (ts.rate_hz < r.min_rate_hz)
    fatal.push_back(format("sample rate %.3g Hz is below %.3g Hz (a throw's swing lasts 0.1-0.2 s)", ts.rate_hz, r.min_rate_hz));
  if (n >= 2 && !a.press_found) {
    fatal.push_back(std::string("no press of the action button (") + (a.options.release_button == kButtonA ? "A" : "B") +
                    ") found: the release cannot be located");
  }
  if (a.release_found && a.release_t_high_s - a.release_t_low_s > r.max_release_gap_s)
    fatal.push_back(format("the release falls in a gap of %.3g s (longer than %.3g s): its state is unknown",
                           a.release_t_high_s - a.release_t_low_s, r.max_release_gap_s));
  if (a.release_found && !a.still_found)
    fatal.push_back(format("no still part of at least %.3g s before the release: gravity and the gyro bias cannot be found",
                           a.options.min_still_s));
  if (a.nominal_computed && !a.nominal.finite())
    fatal.push_back("the release state is not finite (numbers out of range in the capture)");
  const double calibration_error = std::abs(a.still_accel_error_g);
  if (a.nominal_computed && calibration_error > r.calibration_unusable_g)
    fatal.push_back(format("still-part |a| = %.4g g, not 1 g within %.3g g: the calibration is wrong", a.still_accel_g,
                           r.calibration_unusable_g));
  // Caveats.
  if (a.release_at_end && trace.has_buttons)
    caveats.push_back("the button is still held at the end of the file: the release is taken at the file's end");
  if (a.clipped) {
    caveats.push_back(format("accelerometer clipped (|a| >= %.3g g) on ", a.options.saturation_g) + a.clipped_axes +
                      format(" in %.0f of the swing's %.0f samples: the accelerometer gives only a lower bound on the speed "
                             "(%.3g m/s)",
                             a.saturated_in_swing, a.swing_samples, a.accel_lower.accel_speed_m_s) +
                      format("; the throw uses the lever-arm estimate %.3g m/s", a.nominal.lever_speed_m_s));
  } else if (a.saturated_any > 0) {
    a.notes.push_back(format("accelerometer clipped in %.0f samples outside the swing (not used for the throw)",
                             a.saturated_any));
  }
  if (a.gyro_saturated_in_swing) caveats.push_back("the MotionPlus reached the end of its range during the swing");
  if (ts.ok && !ts.nominal) {
    const double lost = double(ts.dropped_reports) / double(ts.dropped_reports + long(ts.used));
    if (lost > r.lost_fraction_caveat)
      caveats.push_back(format("about %.0f reports lost in %.0f gaps (%.2g %% of the reports)", double(ts.dropped_reports),
                               ts.gaps, 100 * lost));
    else if (ts.dropped_reports > 0)
      a.notes.push_back(format("about %.0f reports lost in %.0f gaps", double(ts.dropped_reports), ts.gaps));
    if (ts.jitter_s > r.jitter_caveat_s)
      caveats.push_back(format("timestamp jitter %.3g ms (standard deviation of the intervals; above %.3g ms)",
                               1e3 * ts.jitter_s, 1e3 * r.jitter_caveat_s));
    if (ts.clock == ClockModel::regular_reports)
      a.notes.push_back(format("clock: every stamp within %.2g ms of a regular %.5g Hz clock; the stamps were replaced by it",
                               1e3 * ts.clock_residual_max_s, ts.rate_hz));
    else
      a.notes.push_back(format("clock: stamps used as given (up to %.3g ms from the best regular clock; typical "
                               "interval %.3g ms)",
                               1e3 * ts.clock_residual_max_s, 1e3 * ts.period_s));
    if (ts.equal_stamps > 0) a.notes.push_back(format("%.0f pairs of samples with equal stamps", double(ts.equal_stamps)));
  }
  if (ts.repeated > 0) a.notes.push_back(format("%.0f repeated reports dropped", double(ts.repeated)));
  if (a.nominal_computed && calibration_error > r.calibration_caveat_g && calibration_error <= r.calibration_unusable_g)
    caveats.push_back(format("still-part |a| = %.4g g differs from 1 g by more than %.3g g: check the calibration",
                             a.still_accel_g, r.calibration_caveat_g));
  if (trace.nominal_timestamps)
    caveats.push_back(format("no timestamps in the file: the nominal rate %.4g Hz was assumed", trace.nominal_rate_hz));
  if (trace.gyro_mode_inferred && a.gyro_range_switches > 0)
    caveats.push_back(format("%.0f MotionPlus range switches inferred (no range flags in the file)",
                             a.gyro_range_switches));
  if (!trace.calibration.accel_from_device)
    caveats.push_back("no device calibration in the file: the nominal accelerometer calibration was used");
  if (a.nominal_computed && a.nominal.finite() && !a.clipped && a.nominal.lever_speed_m_s > 0 &&
      std::abs(a.speed_difference_m_s) > r.accel_lever_disagreement * a.nominal.measured_speed_m_s)
    caveats.push_back(format("the accelerometer (%.3g m/s) and the lever arm (%.3g m/s) disagree by more than %.3g %%: "
                             "check the mounting's lever arm",
                             a.nominal.accel_speed_m_s, a.nominal.lever_speed_m_s, 100 * r.accel_lever_disagreement));
  if (!trace.warnings.empty())
    caveats.push_back(format("%.0f reader warning(s), e.g. ", double(trace.warnings.size())) + trace.warnings.front());

  a.reasons = fatal;
  a.reasons.insert(a.reasons.end(), caveats.begin(), caveats.end());
  a.verdict = !fatal.empty() ? Verdict::unusable : caveats.empty() ? Verdict::usable : Verdict::usable_with_caveats;
}

}  // namespace stoneskip
