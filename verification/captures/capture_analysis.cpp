#include "verification/captures/capture_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "model/stone/throw.hpp"
#include "verification/captures/capture_chain.hpp"

namespace stoneskip {

bool ReleaseKinematics::finite() const {
  return velocity_m_s.allFinite() && accel_velocity_m_s.allFinite() && lever_velocity_m_s.allFinite() &&
         measured.velocity_m_s.allFinite() && measured.omega_body_rad_s.allFinite() && std::isfinite(measured.rise_m) &&
         omega_body_rad_s.allFinite() && std::isfinite(height_m) && std::isfinite(stone_orientation.w()) &&
         stone_orientation.vec().allFinite();
}

bool CaptureOptions::is_valid(std::string* why) const {
  auto fail = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (!(saturation_g > 0 && saturation_g < 1000)) return fail("saturation_g must be in (0, 1000) g");
  // A still remote reads up to 1 + still_accel_tol_g on its vertical axis: a clip level at or below
  // that marks the still part itself clipped, and the capture then "has no still part".
  if (still_accel_tol_g > 0 && still_accel_tol_g < 1 && !(saturation_g > 1 + still_accel_tol_g)) {
    char b[200];
    std::snprintf(b, sizeof b,
                  "saturation_g must be above %g g, what a still remote may read (1 g + the still part's tolerance "
                  "%g g): every still sample would be clipped",
                  1 + still_accel_tol_g, still_accel_tol_g);
    return fail(b);
  }
  if (!(max_accel_g >= saturation_g && max_accel_g < 1000)) return fail("max_accel_g must be at least saturation_g and below 1000 g");
  if (!(max_rate_deg_s >= 100 && max_rate_deg_s < 1e5)) return fail("max_rate_deg_s must be in [100, 1e5) deg/s");
  if (!(gravity_m_s2 > 0 && gravity_m_s2 < 100)) return fail("gravity_m_s2 must be in (0, 100)");
  if (!(min_still_s > 0 && min_still_s <= 10)) return fail("min_still_s must be in (0, 10] s");
  if (!(still_accel_tol_g > 0 && still_accel_tol_g < 1)) return fail("still_accel_tol_g must be in (0, 1) g");
  if (!(still_rate_tol_deg_s > 0 && still_rate_tol_deg_s < 100)) return fail("still_rate_tol_deg_s must be in (0, 100) deg/s");
  if (!(accel_noise_g >= 0 && accel_noise_g < 1)) return fail("accel_noise_g must be in [0, 1) g");
  if (!(accel_bias_g >= 0 && accel_bias_g < 1)) return fail("accel_bias_g must be in [0, 1) g");
  if (!(gyro_noise_deg_s >= 0 && gyro_noise_deg_s < 100)) return fail("gyro_noise_deg_s must be in [0, 100) deg/s");
  if (!(gyro_scale_rel_uncertainty >= 0 && gyro_scale_rel_uncertainty < 1))
    return fail("gyro_scale_rel_uncertainty must be in [0, 1)");
  if (members < 0 || members > 100000) return fail("members must be in [0, 100000]");
  if (!(timing.gap_factor > 1 && timing.gap_factor < 100)) return fail("timing.gap_factor must be in (1, 100)");
  if (!(timing.regular_max_residual_intervals > 0 && timing.regular_max_residual_intervals <= 1))
    return fail("timing.regular_max_residual_intervals must be in (0, 1]");
  return thrower.is_valid(why) && rules.is_valid(why);
}

Mounting resolve_mounting(const Trace& trace, const std::vector<std::string>& overrides) {
  Mounting m;
  for (const auto& s : trace.mounting) apply_mounting_setting(m, s, trace.source);
  for (const auto& s : overrides) apply_mounting_setting(m, s, "--mount");
  check_mounting(m, overrides.empty() ? trace.source : trace.source + " with --mount");
  return m;
}

VirtualThrowerOptions resolve_thrower(const Trace& trace, const std::vector<std::string>& overrides) {
  VirtualThrowerOptions o;
  for (const auto& s : trace.thrower) apply_thrower_setting(o, s, trace.source);
  for (const auto& s : overrides) apply_thrower_setting(o, s, "--thrower");
  return o;
}

namespace {

const char* axis_name(int i) { return i == 0 ? "X" : i == 1 ? "Y" : "Z"; }

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const double x = p * double(v.size() - 1);
  const std::size_t i = std::size_t(x);
  const double f = x - double(i);
  return i + 1 < v.size() ? v[i] * (1 - f) + v[i + 1] * f : v[i];
}

// The nominal value joined with the 2.5–97.5 % range of the members.
template <class Get>
Interval interval_of(const ReleaseKinematics& nominal, const std::vector<ReleaseKinematics>& e, Get get) {
  std::vector<double> v;
  for (const auto& m : e)
    if (std::isfinite(get(m))) v.push_back(get(m));
  const double x = get(nominal);
  Interval r{x, x, x};
  if (v.empty()) return r;
  r.low = std::min(x, percentile(v, kIntervalLowQuantile));
  r.high = std::max(x, percentile(v, kIntervalHighQuantile));
  return r;
}

// An angle (degrees, in (−180, 180]) taken to the turn nearest `near`: an attack angle near ±180°
// (a remote face down) spreads across the cut, and its interval is then read around the nominal
// value ([−180.4, −179.5], not [−179.98, 179.94], which holds nearly every angle).
double near_angle_deg(double angle, double near) { return near + std::remainder(angle - near, 360.0); }

// Step 3: the release from the action button (or the file's end).
void locate_release(CaptureAnalysis& a, const ChainInput& in, const Trace& trace, unsigned button) {
  const std::size_t n = in.t_s.size();
  if (n < 2) return;
  if (trace.has_buttons) {
    std::size_t last_down = n;
    for (std::size_t k = n; k-- > 0;)
      if (in.buttons[k] & button) {
        last_down = k;
        break;
      }
    if (last_down == n) return;  // no press
    a.press_found = a.release_found = true;
    a.release_sample = last_down;
    if (last_down + 1 < n) {
      a.release_t_low_s = in.t_s[last_down];
      a.release_t_high_s = in.t_s[last_down + 1];
      a.release_t_s = 0.5 * (a.release_t_low_s + a.release_t_high_s);
    } else {
      a.release_at_end = true;
    }
  } else {
    a.press_found = a.release_found = a.release_at_end = true;
  }
  if (a.release_at_end) {
    // The button went up after the last sample, before the next report would have come.
    a.release_sample = n - 1;
    a.release_t_low_s = in.t_s[n - 1];
    a.release_t_high_s = in.t_s[n - 1] + (in.period_s > 0 ? in.period_s : in.t_s[n - 1] - in.t_s[n - 2]);
    a.release_t_s = 0.5 * (a.release_t_low_s + a.release_t_high_s);
  }
}

// Step 4 and the swing between the still part and the release.
void locate_still_part(CaptureAnalysis& a, const ChainInput& in, const CaptureOptions& o) {
  if (!a.release_found) return;
  a.still_found = find_still(in, o, a.release_sample, a.still_begin, a.still_end);
  if (!a.still_found) return;
  const std::size_t n = in.t_s.size();
  a.still_t0_s = in.t_s[a.still_begin];
  a.still_t1_s = in.t_s[a.still_end];
  // The still part's mean rate (slow-mode deg/s, as the chain's bias), and the swing's largest
  // rate off it, each fast-mode axis scaled back to deg/s.
  Vec3 bias_slow = Vec3::Zero();
  for (std::size_t k = a.still_begin; k <= a.still_end; ++k) bias_slow += in.rate_slow_deg_s(k);
  bias_slow /= static_cast<double>(a.still_end - a.still_begin + 1);
  for (std::size_t k = a.still_end; k <= std::min(a.release_sample + 1, n - 1); ++k) {
    ++a.swing_samples;
    if (in.flags[k] & kAccelSaturated) ++a.saturated_in_swing;
    if (in.flags[k] & kGyroSaturated) a.gyro_saturated_in_swing = true;
    if ((in.flags[k] & kGyroHeld) && a.gyro_held_in_swing++ == 0) a.gyro_held_from_s = in.t_s[k];
    Vec3 off = in.rate_slow_deg_s(k) - bias_slow;
    for (int i = 0; i < 3; ++i)
      if (in.fast[k][i]) off[i] *= in.fast_factor;
    a.swing_peak_rate_deg_s = std::max(a.swing_peak_rate_deg_s, off.norm());
  }
  a.clipped = a.saturated_in_swing > 0;
  for (int i = 0; i < 3; ++i) {
    bool on_axis = false;
    for (const auto& s : a.spans)
      if (s.axis == i && s.t1_s >= a.still_t1_s && s.t0_s <= a.release_t_high_s) on_axis = true;
    if (on_axis) a.clipped_axes += std::string(a.clipped_axes.empty() ? "" : ", ") + axis_name(i);
  }
}

// Steps 5–8 for the nominal throw, the accelerometer's bounds and the ensemble, with intervals.
void estimate_throw(CaptureAnalysis& a, const ChainInput& in, const CaptureOptions& o) {
  ChainDiagnostics d;
  a.nominal = run_chain(in, o, Perturbation{}, &a.series, &d);
  a.nominal_computed = true;
  a.still_accel_g = d.still_accel_g;
  a.still_accel_error_g = d.still_accel_g - 1.0;
  a.gyro_bias_deg_s = d.gyro_bias_deg_s;
  if (!a.nominal.finite()) return;
  a.accel_lower = a.nominal;  // clipped spans as recorded: the accelerometer's lower bound
  ChainInput floored = in;    // clipped: the lever arm's speed raised to that bound where slower
  if (a.clipped) {
    floored.speed_floor_m_s = a.accel_lower.accel_speed_m_s;
    a.nominal = run_chain(floored, o, Perturbation{}, &a.series, nullptr);
    if (!a.nominal.finite()) return;
  }
  a.accel_upper = a.clipped ? run_chain(in, o, Perturbation{Perturb::none, ClipFill::at_max, ClipFill::as_recorded, 0}, nullptr, nullptr) : a.nominal;
  std::mt19937_64 seeds(o.seed);
  std::vector<double> member_bounds;  // clipped: each member's own accelerometer bound (m/s)
  for (int m = 0; m < o.members; ++m) {
    const Perturbation p{Perturb::random, a.clipped ? ClipFill::random_bump : ClipFill::as_recorded,
                         a.gyro_saturated_in_swing ? ClipFill::random_bump : ClipFill::as_recorded, seeds()};
    if (a.clipped) {
      // The member's own bound: the same member with its clipped spans as recorded.
      Perturbation twin = p;
      twin.fill = ClipFill::as_recorded;
      const ReleaseKinematics bound = run_chain(in, o, twin, nullptr, nullptr);
      if (!bound.finite()) continue;
      floored.speed_floor_m_s = bound.accel_speed_m_s;
      member_bounds.push_back(bound.accel_speed_m_s);
    }
    const ReleaseKinematics r = run_chain(floored, o, p, nullptr, nullptr);
    if (r.finite()) a.ensemble.push_back(r);
  }
  const auto& e = a.ensemble;
  const ReleaseKinematics& nom = a.nominal;
  using R = const ReleaseKinematics&;
  a.speed_m_s = interval_of(nom, e, [](R r) { return r.speed_m_s; });
  a.attack_angle_deg = interval_of(nom, e, [&nom](R r) { return near_angle_deg(r.attack_angle_deg, nom.attack_angle_deg); });
  a.path_angle_deg = interval_of(nom, e, [](R r) { return r.path_angle_deg; });
  a.spin_rev_s = interval_of(nom, e, [](R r) { return r.spin_rev_s; });
  a.height_m = interval_of(nom, e, [](R r) { return r.height_m; });
  a.accel_speed_m_s = interval_of(nom, e, [](R r) { return r.accel_speed_m_s; });
  a.lever_speed_m_s = interval_of(nom, e, [](R r) { return r.lever_speed_m_s; });
  a.measured_speed_m_s = interval_of(nom, e, [](R r) { return r.measured_speed_m_s; });
  a.measured_spin_rev_s = interval_of(nom, e, [](R r) { return r.measured_spin_rev_s; });
  a.rise_m = interval_of(nom, e, [](R r) { return r.measured.rise_m; });
  if (a.clipped) {
    // The accelerometer alone bounds the speed and the rise: clipped spans as recorded … at
    // max_accel_g. The measured (and so the virtual) speed spans them and the members' speeds,
    // each at least its own lower bound; not the lever arm's interval, whose low end can lie below
    // the accelerometer's bound (the lever arm misses the pivot's motion).
    auto widen = [](Interval& v, double x, double y) {
      v.low = std::min({v.low, x, y});
      v.high = std::max({v.high, x, y});
    };
    widen(a.accel_speed_m_s, a.accel_lower.accel_speed_m_s, a.accel_upper.accel_speed_m_s);
    // Each member's own bound (its calibration and noise perturbed, the clipped spans as recorded)
    // is a lower bound too: a member's speed raised to it can lie below the nominal bound, and the
    // accelerometer's interval must reach it (hard_sidearm_clipped: 8.51 m/s against 8.64).
    for (const double b : member_bounds) widen(a.accel_speed_m_s, b, b);
    // The direction as well: the lever arm's velocity misses the pivot's own motion, which the
    // accelerometer sees (its clipped spans as recorded, at max_accel_g, or as each member fills
    // them), so the path and attack angles span the accelerometer's directions too (a synthetic
    // swing whose pivot rises 30° above the release direction put the true path angle, 0.43°,
    // outside the lever arm's [9.14, 10.50]°: tools/capture/clipped_direction_test.cpp).
    auto accel_attitude = [](const ReleaseKinematics& r) {
      RigidState st;
      st.orientation = r.stone_orientation;
      st.velocity_m_s = r.accel_velocity_m_s;
      return attitude_angles(st);
    };
    std::vector<const ReleaseKinematics*> directions{&a.accel_lower, &a.accel_upper};
    for (const auto& m : e) directions.push_back(&m);
    for (const ReleaseKinematics* r : directions) {
      if (!(r->accel_speed_m_s > 0)) continue;  // no direction
      const AttitudeAngles g = accel_attitude(*r);
      widen(a.path_angle_deg, g.path_angle_deg, g.path_angle_deg);
      const double attack = near_angle_deg(g.attack_angle_deg, nom.attack_angle_deg);
      widen(a.attack_angle_deg, attack, attack);
    }
    widen(a.rise_m, a.accel_lower.measured.rise_m, a.accel_upper.measured.rise_m);
    widen(a.measured_speed_m_s, a.accel_speed_m_s.low, a.accel_speed_m_s.high);
    const double scale = o.thrower.speed_scale;
    widen(a.speed_m_s, scale * a.measured_speed_m_s.low, scale * a.measured_speed_m_s.high);
    if (o.thrower.height_mapping == HeightMapping::still_part_height)
      widen(a.height_m, o.thrower.still_height_m + a.rise_m.low - o.thrower.height_uncertainty_m,
            o.thrower.still_height_m + a.rise_m.high + o.thrower.height_uncertainty_m);
  }
  a.speed_difference_m_s = nom.accel_speed_m_s - nom.lever_speed_m_s;
}

}  // namespace

CaptureAnalysis analyse_capture(const Trace& trace, const CaptureOptions& options) {
  CaptureAnalysis a;
  a.source = trace.source;
  a.format = trace.format;
  a.trace = trace;
  a.options = options;
  a.notes = trace.notes;
  // 1–2. Timing, the kept samples and their saturation flags.
  a.timing = analyse_timing(trace, options.timing);
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
  a.series.t_s = in.t_s;
  a.series.accel_g = in.accel_g;
  a.series.buttons = in.buttons;
  a.series.flags = in.flags;
  // 3–4. Release and still part.
  locate_release(a, in, trace, options.release_button);
  locate_still_part(a, in, options);
  in.still_begin = a.still_begin;
  in.still_end = a.still_end;
  in.release_sample = a.release_sample;
  in.release_t_s = a.release_t_s;
  in.release_t_low_s = a.release_t_low_s;
  in.release_t_high_s = a.release_t_high_s;
  in.use_lever = a.clipped;
  // 5–8. The throw, when the capture holds what it needs.
  const TimingStats& ts = a.timing.stats;
  const bool preconditions = trace.has_gyro && n >= options.rules.min_samples && ts.ok &&
                             ts.rate_hz >= options.rules.min_rate_hz && a.release_found && a.still_found &&
                             a.release_t_high_s - a.release_t_low_s <= options.rules.max_release_gap_s;
  if (preconditions) estimate_throw(a, in, options);
  // 9. The verdict.
  judge_capture(a, options.rules);
  return a;
}

}  // namespace stoneskip
