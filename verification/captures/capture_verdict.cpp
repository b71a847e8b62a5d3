#include "verification/captures/capture_verdict.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "verification/captures/capture_analysis.hpp"
#include "verification/study/verdict_rules.hpp"

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
  if (!(min_release_speed_m_s >= 0 && max_release_speed_m_s > min_release_speed_m_s))
    return fail("rules.max_release_speed_m_s must exceed rules.min_release_speed_m_s >= 0");
  if (!(max_hand_displacement_m > 0)) return fail("rules.max_hand_displacement_m must be positive");
  if (!(max_tilt_deg > 0 && max_tilt_deg <= 180)) return fail("rules.max_tilt_deg must be in (0, 180]");
  if (!(min_swing_rate_deg_s >= 0)) return fail("rules.min_swing_rate_deg_s must not be negative");
  return true;
}

namespace {
std::string format(const char* fmt, double a = 0, double b = 0, double c = 0) {
  char buf[480];
  std::snprintf(buf, sizeof buf, fmt, a, b, c);
  return buf;
}
}  // namespace

Verdict verdict_from_phrase(const std::string& phrase) {
  for (Verdict v : {Verdict::usable, Verdict::usable_with_caveats, Verdict::unusable})
    if (phrase == to_string(v)) return v;
  return Verdict::unusable;
}

namespace {
// The angle of the stone's normal (body z) from the vertical at release, degrees.
double release_tilt_deg(const CaptureAnalysis& a) {
  const double nz = (a.nominal.stone_orientation * Vec3::UnitZ()).z();
  return std::acos(std::clamp(nz, -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

// The largest distance of the stone from where it was held still, from the end of the still part
// to the release (the series' kept samples; 0 when the chain did not run).
double hand_displacement_m(const CaptureAnalysis& a) {
  const auto& p = a.series.stone_position_m;
  if (p.empty()) return 0.0;
  const std::size_t last = std::min(a.release_sample, p.size() - 1);
  double far = 0;
  for (std::size_t i = std::min(a.still_end, last); i <= last; ++i) far = std::max(far, p[i].norm());
  return far;
}
}  // namespace

Record capture_verdict_inputs(const CaptureAnalysis& a, const CaptureVerdictRules& r) {
  const Trace& trace = a.trace;
  const TimingStats& ts = a.timing.stats;
  const bool stamps = ts.ok && !ts.nominal;
  const bool finite = a.nominal_computed && a.nominal.finite();
  Record in;
  in.set("has_gyro", trace.has_gyro);
  in.set("samples", a.series.t_s.size());
  in.set("min_samples", r.min_samples);
  in.set("rate_found", ts.ok);
  in.set("rate_hz", ts.rate_hz);
  in.set("min_rate_hz", r.min_rate_hz);
  in.set("press_found", a.press_found);
  in.set("release_found", a.release_found);
  in.set("release_gap_s", a.release_found ? a.release_t_high_s - a.release_t_low_s : 0.0);
  in.set("max_release_gap_s", r.max_release_gap_s);
  in.set("still_found", a.still_found);
  in.set("throw_computed", a.nominal_computed);
  in.set("throw_finite", finite);
  in.set("calibration_error_g", a.nominal_computed ? std::abs(a.still_accel_error_g) : 0.0);
  in.set("calibration_unusable_g", r.calibration_unusable_g);
  in.set("calibration_caveat_g", r.calibration_caveat_g);
  in.set("has_buttons", trace.has_buttons);
  in.set("release_at_end", a.release_at_end);
  in.set("clipped_in_swing", a.clipped);
  in.set("gyro_saturated_in_swing", a.gyro_saturated_in_swing);
  in.set("stamps_given", stamps);
  in.set("lost_fraction", stamps ? double(ts.dropped_reports) / double(ts.dropped_reports + long(ts.used)) : 0.0);
  in.set("lost_fraction_caveat", r.lost_fraction_caveat);
  in.set("jitter_s", stamps ? ts.jitter_s : 0.0);
  in.set("jitter_caveat_s", r.jitter_caveat_s);
  in.set("nominal_timestamps", trace.nominal_timestamps);
  in.set("inferred_range_switches", trace.gyro_mode_inferred ? a.gyro_range_switches : 0);
  in.set("device_calibration", trace.calibration.accel_from_device);
  in.set("measured_speed_m_s", finite ? a.nominal.measured_speed_m_s : 0.0);
  in.set("lever_speed_m_s", finite ? a.nominal.lever_speed_m_s : 0.0);
  in.set("speed_difference_m_s", finite ? a.speed_difference_m_s : 0.0);
  in.set("accel_lever_disagreement", r.accel_lever_disagreement);
  in.set("reader_warnings", trace.warnings.size());
  in.set("release_speed_m_s", finite ? a.nominal.measured_speed_m_s : 0.0);
  in.set("min_release_speed_m_s", r.min_release_speed_m_s);
  in.set("max_release_speed_m_s", r.max_release_speed_m_s);
  in.set("hand_displacement_m", finite ? hand_displacement_m(a) : 0.0);
  in.set("max_hand_displacement_m", r.max_hand_displacement_m);
  in.set("release_tilt_deg", finite ? release_tilt_deg(a) : 0.0);
  in.set("max_tilt_deg", r.max_tilt_deg);
  in.set("swing_peak_rate_deg_s", a.swing_peak_rate_deg_s);
  in.set("gyro_held_in_swing", a.gyro_held_in_swing);
  in.set("min_swing_rate_deg_s", r.min_swing_rate_deg_s);
  return in;
}

namespace {

// The sentence for one condition of the rule (capture_conditions' names), with its numbers.
std::string reason_for(const std::string& c, const CaptureAnalysis& a, const Record& in) {
  const TimingStats& ts = a.timing.stats;
  if (c == "no_gyro") return "no MotionPlus data: the orientation through the throw cannot be followed";
  if (c == "too_few_samples")
    return format("only %.0f usable samples (at least %.0f needed)", in.number("samples"), in.number("min_samples"));
  if (c == "no_rate") return "no sample rate can be found from the timestamps";
  if (c == "rate_too_low")
    return format("sample rate %.3g Hz is below %.3g Hz (a throw's swing lasts 0.1-0.2 s)", ts.rate_hz,
                  in.number("min_rate_hz"));
  if (c == "no_press")
    return std::string("no press of the action button (") + (a.options.release_button == kButtonA ? "A" : "B") +
           ") found: the release cannot be located";
  if (c == "release_in_gap")
    return format("the release falls in a gap of %.3g s (longer than %.3g s): its state is unknown",
                  in.number("release_gap_s"), in.number("max_release_gap_s"));
  if (c == "no_still_part")
    return format("no still part of at least %.3g s before the release: gravity and the gyro bias cannot be found",
                  a.options.min_still_s);
  if (c == "gyro_held_in_swing")
    return format("the MotionPlus sent no frame for 0.1 s or more during the swing (%.0f of its samples, from %.4g s after the first "
                  "sample): their rate is the last frame's, held, not measured, so the orientation through the swing is "
                  "unknown there",
                  in.number("gyro_held_in_swing"), a.gyro_held_from_s);
  if (c == "gyro_still")
    return format("the MotionPlus shows no rotation through the swing (its largest rate off the still part's is %.3g "
                  "deg/s, below %.3g deg/s; a throwing wrist turns at hundreds) while the accelerometer measures %.3g "
                  "m/s: the gyro did not record the throw (stuck, or its stream lost), so the orientation is unknown",
                  in.number("swing_peak_rate_deg_s"), in.number("min_swing_rate_deg_s"),
                  a.nominal_computed ? a.nominal.accel_speed_m_s : 0.0);
  if (c == "state_not_finite") return "the release state is not finite (numbers out of range in the capture)";
  if (c == "calibration_wrong")
    return format("the still part reads %.4g g, not 1 g within %.3g g: the calibration is wrong", a.still_accel_g,
                  in.number("calibration_unusable_g"));
  if (c == "button_held_at_end") return "the button is still held at the end of the file: the release is taken at the file's end";
  if (c == "clipped_in_swing")
    return format("accelerometer clipped (an axis at or beyond %.3g g) on ", a.options.saturation_g) + a.clipped_axes +
           format(" in %.0f of the swing's %.0f samples: the accelerometer gives only a lower bound on the speed "
                  "(%.3g m/s)",
                  a.saturated_in_swing, a.swing_samples, a.accel_lower.accel_speed_m_s) +
           (a.nominal.speed_floored
                ? format("; the lever-arm estimate, %.3g m/s, falls below it, so the throw takes the bound in the "
                         "lever arm's direction",
                         a.nominal.lever_speed_m_s)
                : format("; the throw uses the lever-arm estimate %.3g m/s", a.nominal.lever_speed_m_s));
  if (c == "gyro_saturated") return "the MotionPlus reached the end of its range during the swing";
  if (c == "reports_lost")
    return format("about %.0f reports lost in %.0f gaps (%.2g %% of the reports)", double(ts.dropped_reports), ts.gaps,
                  100 * in.number("lost_fraction"));
  if (c == "jitter")
    return format("timestamp jitter %.3g ms (standard deviation of the intervals; above %.3g ms)", 1e3 * ts.jitter_s,
                  1e3 * in.number("jitter_caveat_s"));
  if (c == "calibration_off")
    return format("the still part reads %.4g g, off 1 g by more than %.3g g: check the calibration", a.still_accel_g,
                  in.number("calibration_caveat_g"));
  if (c == "no_timestamps")
    return format("no timestamps in the file: the nominal rate %.4g Hz was assumed", a.trace.nominal_rate_hz);
  if (c == "range_switches_inferred")
    return format("%.0f MotionPlus range switches inferred (no range flags in the file)", in.number("inferred_range_switches"));
  if (c == "nominal_calibration") return "no device calibration in the file: the nominal accelerometer calibration was used";
  if (c == "accel_lever_disagree")
    // The lever arm sees the arm's turn only: a thrower whose trunk steps or turns into the throw
    // gives the stone speed it cannot see (synthetic_capture.hpp: the pivot's speed), so a lever
    // arm below the accelerometer has two causes, one above it only the mounting.
    return format("the accelerometer (%.3g m/s) and the lever arm (%.3g m/s) disagree by more than %.3g %%: ",
                  a.nominal.accel_speed_m_s, a.nominal.lever_speed_m_s, 100 * in.number("accel_lever_disagreement")) +
           (a.nominal.lever_speed_m_s < a.nominal.accel_speed_m_s
                ? "the lever arm sees the arm's turn only, not the trunk stepping or turning into the throw; "
                  "or check the mounting's lever arm"
                : "check the mounting's lever arm");
  if (c == "release_speed_implausible")
    return format("the release speed %.3g m/s is outside a human throw's %.3g-%.3g m/s: not a hand's throw",
                  in.number("release_speed_m_s"), in.number("min_release_speed_m_s"), in.number("max_release_speed_m_s"));
  if (c == "attitude_implausible")
    return format("the stone's normal is %.3g deg from the vertical at release (more than %.3g deg; skipping throws "
                  "release it near flat): check the mounting's stone_normal and stone_forward",
                  in.number("release_tilt_deg"), in.number("max_tilt_deg"));
  if (c == "hand_displacement_implausible")
    return format("the hand displacement of %.3g m from the still part to the release is beyond an arm's reach "
                  "(%.3g m): integration drift, not a throw",
                  in.number("hand_displacement_m"), in.number("max_hand_displacement_m"));
  if (c == "no_release_signal")
    return "no release signal (no button column): the release is taken at the file's end";
  if (c == "reader_warnings")
    return format("%.0f reader warning(s), e.g. ", in.number("reader_warnings")) + a.trace.warnings.front();
  return c;
}

}  // namespace

void judge_capture(CaptureAnalysis& a, const CaptureVerdictRules& r) {
  const Record in = capture_verdict_inputs(a, r);
  const CaptureConditions conditions = capture_conditions(in);
  a.reasons.clear();
  for (const auto* list : {&conditions.unusable, &conditions.caveats})
    for (const auto& c : *list) a.reasons.push_back(reason_for(c, a, in));
  a.verdict = verdict_from_phrase(decide("capture_verdict", in));
  // Notes: information that does not change the verdict.
  const TimingStats& ts = a.timing.stats;
  if (!a.clipped && a.saturated_any > 0)
    a.notes.push_back(format("accelerometer clipped in %.0f samples outside the swing (not used for the throw)",
                             a.saturated_any));
  if (ts.ok && !ts.nominal) {
    if (in.number("lost_fraction") <= r.lost_fraction_caveat && ts.dropped_reports > 0)
      a.notes.push_back(format("about %.0f reports lost in %.0f gaps", double(ts.dropped_reports), ts.gaps));
    if (ts.clock == ClockModel::regular_reports)
      a.notes.push_back(format("clock: every stamp within %.2g ms of a regular %.5g Hz clock; the stamps were replaced by it",
                               1e3 * ts.clock_residual_max_s, ts.clock_rate_hz));
    else
      a.notes.push_back(format("clock: stamps used as given (up to %.3g ms from the best regular clock; typical "
                               "interval %.3g ms)",
                               1e3 * ts.clock_residual_max_s, 1e3 * ts.period_s));
    if (ts.equal_stamps > 0) a.notes.push_back(format("%.0f pairs of samples with equal stamps", double(ts.equal_stamps)));
  }
  if (ts.repeated > 0) a.notes.push_back(format("%.0f repeated reports dropped", double(ts.repeated)));
}

}  // namespace stoneskip
