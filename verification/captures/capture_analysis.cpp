#include "verification/captures/capture_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "model/stone/throw.hpp"
#include "verification/captures/capture_chain.hpp"

namespace stoneskip {

const char* to_string(Verdict v) {
  switch (v) {
    case Verdict::usable: return "usable";
    case Verdict::usable_with_caveats: return "usable with caveats";
    case Verdict::unusable: return "unusable";
  }
  return "?";
}

bool ReleaseKinematics::finite() const {
  return velocity_m_s.allFinite() && accel_velocity_m_s.allFinite() && lever_velocity_m_s.allFinite() &&
         omega_body_rad_s.allFinite() && std::isfinite(height_m) && std::isfinite(stone_orientation.w()) &&
         stone_orientation.vec().allFinite();
}

Mounting resolve_mounting(const Trace& trace, const std::vector<std::string>& overrides) {
  Mounting m;
  for (const auto& s : trace.mounting) apply_mounting_setting(m, s, trace.source);
  for (const auto& s : overrides) apply_mounting_setting(m, s, "--mount");
  return m;
}

namespace {

std::string format(const char* fmt, double a = 0, double b = 0, double c = 0) {
  char buf[320];
  std::snprintf(buf, sizeof buf, fmt, a, b, c);
  return buf;
}

const char* axis_name(int i) { return i == 0 ? "X" : i == 1 ? "Y" : "Z"; }

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const double x = p * double(v.size() - 1);
  const std::size_t i = std::size_t(x);
  const double f = x - double(i);
  return i + 1 < v.size() ? v[i] * (1 - f) + v[i + 1] * f : v[i];
}

Interval interval_of(double nominal, const std::vector<ReleaseKinematics>& e, double ReleaseKinematics::*field) {
  std::vector<double> v;
  for (const auto& m : e)
    if (std::isfinite(m.*field)) v.push_back(m.*field);
  Interval r{nominal, nominal, nominal};
  if (v.empty()) return r;
  r.low = std::min(nominal, percentile(v, 0.025));
  r.high = std::max(nominal, percentile(v, 0.975));
  return r;
}

// The still part: the latest window of at least min_still_s before `last` where accelerometer and
// gyro stay within tolerance of their window means; then grown backwards (up to 2 s).
bool find_still(const ChainInput& in, const CaptureOptions& o, std::size_t last, std::size_t& begin, std::size_t& end) {
  const std::size_t n = in.t_s.size();
  if (n < 3 || last >= n) return false;
  const double period = in.period_s > 0 ? in.period_s : 0.01;
  const std::size_t w = std::size_t(std::clamp(std::ceil(o.min_still_s / period), 3.0, 100000.0));
  if (w > last + 1) return false;
  auto quiet = [&](std::size_t b, std::size_t e) {
    Vec3 fa = Vec3::Zero(), wa = Vec3::Zero();
    for (std::size_t k = b; k <= e; ++k) {
      if (in.flags[k] & (kAccelSaturated | kGyroSaturated)) return false;
      fa += in.accel_g[k];
      wa += in.rate_slow_deg_s(k);
    }
    fa /= double(e - b + 1);
    wa /= double(e - b + 1);
    if (std::abs(fa.norm() - 1.0) > 0.3 || wa.cwiseAbs().maxCoeff() > 60.0) return false;
    for (std::size_t k = b; k <= e; ++k) {
      if ((in.accel_g[k] - fa).cwiseAbs().maxCoeff() > o.still_accel_tol_g) return false;
      if ((in.rate_slow_deg_s(k) - wa).cwiseAbs().maxCoeff() > o.still_rate_tol_deg_s) return false;
    }
    return true;
  };
  for (std::size_t e = last + 1; e-- > w - 1;) {
    if (!quiet(e + 1 - w, e)) continue;
    std::size_t b = e + 1 - w;
    const std::size_t max_len = std::size_t(std::clamp(2.0 / period, double(w), 100000.0));
    while (b > 0 && e - b + 2 <= max_len && quiet(b - 1, e)) --b;
    begin = b;
    end = e;
    return true;
  }
  return false;
}

}  // namespace

CaptureAnalysis analyse_capture(const Trace& trace, const CaptureOptions& options) {
  CaptureAnalysis a;
  a.source = trace.source;
  a.format = trace.format;
  a.trace = trace;
  a.options = options;
  a.timing = analyse_timing(trace);
  const TimingStats& ts = a.timing.stats;
  std::vector<std::string> fatal, caveats;

  // The kept samples, with saturation flags.
  ChainInput in = make_chain_input(trace, a.timing, options);
  const std::size_t n = in.t_s.size();
  for (std::size_t k = 0; k < n; ++k) {
    for (int i = 0; i < 3; ++i)
      if (in.flags[k] & (kSaturatedX << i)) ++a.saturated_samples[i];
    if (in.flags[k] & kAccelSaturated) ++a.saturated_any;
  }
  a.saturated_fraction = n ? double(a.saturated_any) / double(n) : 0.0;
  a.spans = saturated_spans(in);
  a.gyro_range_switches = count_range_switches(in);

  // Series for the plots (filled further by the nominal chain).
  a.series.t_s = in.t_s;
  a.series.accel_g = in.accel_g;
  a.series.buttons = in.buttons;
  a.series.flags = in.flags;

  if (!trace.has_gyro) fatal.push_back("no MotionPlus data: the orientation through the throw cannot be followed");
  if (n < 10) fatal.push_back(format("only %.0f usable samples", double(n)));
  if (!ts.ok) fatal.push_back("no sample rate can be found from the timestamps");
  else if (ts.rate_hz < 20.0) fatal.push_back(format("sample rate %.3g Hz is too low (a throw lasts about 0.2 s)", ts.rate_hz));

  // The release.
  if (n >= 2) {
    if (trace.has_buttons) {
      std::size_t last_down = n;
      for (std::size_t k = n; k-- > 0;)
        if (in.buttons[k] & options.release_button) {
          last_down = k;
          break;
        }
      if (last_down == n) {
        fatal.push_back(std::string("no press of the action button (") +
                        (options.release_button == kButtonA ? "A" : "B") + ") found: the release cannot be located");
      } else {
        a.press_found = true;
        a.release_sample = last_down;
        if (last_down + 1 < n) {
          a.release_found = true;
          a.release_t_low_s = in.t_s[last_down];
          a.release_t_high_s = in.t_s[last_down + 1];
          a.release_t_s = 0.5 * (a.release_t_low_s + a.release_t_high_s);
        } else {
          a.release_found = true;
          a.release_at_end = true;
          caveats.push_back("the button is still held at the end of the file: the release is taken at the file's end");
        }
      }
    } else {
      a.press_found = a.release_found = a.release_at_end = true;
      a.release_sample = n - 1;
    }
    if (a.release_at_end) {
      a.release_sample = n - 1;
      a.release_t_s = a.release_t_high_s = in.t_s[n - 1];
      a.release_t_low_s = in.t_s[n - 2];
    }
    if (a.release_found && a.release_t_high_s - a.release_t_low_s > 0.1)
      fatal.push_back(format("the release falls in a gap of %.3g s: its state is unknown",
                             a.release_t_high_s - a.release_t_low_s));
  }

  // The still part.
  if (a.release_found) {
    a.still_found = find_still(in, options, a.release_sample, a.still_begin, a.still_end);
    if (!a.still_found)
      fatal.push_back(format("no still part of at least %.3g s before the release: gravity and the gyro bias cannot be found",
                             options.min_still_s));
  }
  in.still_begin = a.still_begin;
  in.still_end = a.still_end;
  in.release_sample = a.release_sample;
  in.release_t_s = a.release_t_s;
  in.release_t_low_s = a.release_t_low_s;
  in.release_t_high_s = a.release_t_high_s;

  if (a.still_found) {
    for (std::size_t k = a.still_end; k <= std::min(a.release_sample + 1, n - 1); ++k) {
      ++a.swing_samples;
      if (in.flags[k] & kAccelSaturated) ++a.saturated_in_swing;
      if (in.flags[k] & kGyroSaturated) a.gyro_saturated_in_swing = true;
    }
    a.clipped = a.saturated_in_swing > 0;
    in.use_lever = a.clipped;
    a.still_t0_s = in.t_s[a.still_begin];
    a.still_t1_s = in.t_s[a.still_end];
  }

  if (fatal.empty()) {
    ChainDiagnostics d;
    a.nominal = run_chain(in, options, Perturbation{}, &a.series, &d);
    a.still_accel_g = d.still_accel_g;
    a.still_accel_error_g = d.still_accel_g - 1.0;
    a.gyro_bias_deg_s = d.gyro_bias_deg_s;
    if (!a.nominal.finite()) fatal.push_back("the release state is not finite (numbers out of range in the capture)");
  }

  if (fatal.empty()) {
    // Bounds from the accelerometer and the ensemble.
    a.accel_lower = a.nominal;
    a.accel_upper = a.clipped ? run_chain(in, options, Perturbation{false, ClipFill::at_max, 0}, nullptr, nullptr) : a.nominal;
    std::mt19937_64 seeds(options.seed);
    for (int m = 0; m < options.members; ++m) {
      Perturbation p{true, a.clipped ? ClipFill::random_bump : ClipFill::as_recorded, seeds()};
      const ReleaseKinematics r = run_chain(in, options, p, nullptr, nullptr);
      if (r.finite()) a.ensemble.push_back(r);
    }
    a.speed_m_s = interval_of(a.nominal.speed_m_s, a.ensemble, &ReleaseKinematics::speed_m_s);
    a.accel_speed_m_s = interval_of(a.nominal.accel_speed_m_s, a.ensemble, &ReleaseKinematics::accel_speed_m_s);
    a.lever_speed_m_s = interval_of(a.nominal.lever_speed_m_s, a.ensemble, &ReleaseKinematics::lever_speed_m_s);
    a.attack_angle_deg = interval_of(a.nominal.attack_angle_deg, a.ensemble, &ReleaseKinematics::attack_angle_deg);
    a.path_angle_deg = interval_of(a.nominal.path_angle_deg, a.ensemble, &ReleaseKinematics::path_angle_deg);
    a.spin_rev_s = interval_of(a.nominal.spin_rev_s, a.ensemble, &ReleaseKinematics::spin_rev_s);
    a.height_m = interval_of(a.nominal.height_m, a.ensemble, &ReleaseKinematics::height_m);
    if (a.clipped) {
      // The accelerometer alone bounds the speed: clipped spans as recorded … at max_accel_g.
      a.accel_speed_m_s.low = std::min(a.accel_speed_m_s.low, a.accel_lower.accel_speed_m_s);
      a.accel_speed_m_s.high = std::max(a.accel_speed_m_s.high, a.accel_upper.accel_speed_m_s);
      a.speed_m_s.low = std::min({a.speed_m_s.low, a.accel_speed_m_s.low, a.lever_speed_m_s.low});
      a.speed_m_s.high = std::max({a.speed_m_s.high, a.accel_speed_m_s.high, a.lever_speed_m_s.high});
    }
    a.speed_difference_m_s = a.nominal.accel_speed_m_s - a.nominal.lever_speed_m_s;
  }

  // Caveats.
  if (a.clipped) {
    std::string axes;
    for (int i = 0; i < 3; ++i) {
      bool on_axis = false;
      for (const auto& s : a.spans)
        if (s.axis == i && s.t1_s >= a.still_t1_s && s.t0_s <= a.release_t_high_s) on_axis = true;
      if (on_axis) axes += std::string(axes.empty() ? "" : ", ") + axis_name(i);
    }
    caveats.push_back(format("accelerometer clipped (|a| >= %.3g g) on ", options.saturation_g) + axes +
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
    if (lost > 0.02) caveats.push_back(format("%.0f reports lost in %.0f gaps (%.2g %% of the reports)",
                                             double(ts.dropped_reports), ts.gaps, 100 * lost));
    else if (ts.dropped_reports > 0)
      a.notes.push_back(format("%.0f reports lost in %.0f gaps", double(ts.dropped_reports), ts.gaps));
    if (ts.jitter_s > 0.003) caveats.push_back(format("timestamp jitter %.3g ms (standard deviation of the intervals)", 1e3 * ts.jitter_s));
  }
  if (ts.repeated > 0) a.notes.push_back(format("%.0f repeated reports dropped", double(ts.repeated)));
  if (a.still_found && fatal.empty()) {
    const double err = std::abs(a.still_accel_error_g);
    if (err > 3 * options.calibration_tol_g)
      fatal.push_back(format("still-part |a| = %.4g g, not 1 g within %.3g g: the calibration is wrong", a.still_accel_g,
                             3 * options.calibration_tol_g));
    else if (err > options.calibration_tol_g)
      caveats.push_back(format("still-part |a| = %.4g g differs from 1 g by more than %.3g g: check the calibration",
                               a.still_accel_g, options.calibration_tol_g));
  }
  if (trace.nominal_timestamps)
    caveats.push_back(format("no timestamps in the file: the nominal rate %.4g Hz was assumed", trace.nominal_rate_hz));
  if (trace.gyro_mode_inferred && a.gyro_range_switches > 0)
    caveats.push_back(format("%.0f MotionPlus range switches inferred from jumps (no range flags in the file)",
                             a.gyro_range_switches));
  if (!trace.calibration.accel_from_device)
    caveats.push_back("no device calibration in the file: the nominal accelerometer calibration was used");
  if (fatal.empty() && !a.clipped && a.nominal.lever_speed_m_s > 0 &&
      std::abs(a.speed_difference_m_s) > 0.25 * a.nominal.speed_m_s)
    caveats.push_back(format("the accelerometer (%.3g m/s) and the lever arm (%.3g m/s) disagree by more than 25 %%: "
                             "check the mounting's lever arm",
                             a.nominal.accel_speed_m_s, a.nominal.lever_speed_m_s));
  if (!trace.warnings.empty())
    caveats.push_back(format("%.0f reader warning(s), e.g. ", double(trace.warnings.size())) + trace.warnings.front());

  a.reasons = fatal;
  a.reasons.insert(a.reasons.end(), caveats.begin(), caveats.end());
  a.verdict = !fatal.empty() ? Verdict::unusable : caveats.empty() ? Verdict::usable : Verdict::usable_with_caveats;
  return a;
}

}  // namespace stoneskip
