// The analysis on traces built from closed-form motions sampled at irregular times: what the
// remote reads is computed exactly, so the release state the analysis must find is known exactly.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "model/stone/throw.hpp"
#include "verification/captures/capture_analysis.hpp"
#include "verification/captures/capture_verdict.hpp"
#include "verification/study/verdict_rules.hpp"

using namespace stoneskip;

namespace {

constexpr double kG = 9.81;
constexpr double kDeg = std::numbers::pi / 180.0;
// Trapezoid integration of a piecewise-linear acceleration and of a fixed-axis rotation at a
// piecewise-linear rate is exact when the kinks fall on samples: what is left is roundoff in a few
// hundred steps of O(10 m/s) quantities.
constexpr double kRoundoff = 1e-9;

struct Reading {
  Vec3 accel_g, rate_deg_s;
  bool button;
};

// A trace of exact readings at the given times (calibrated, with MotionPlus, slow mode).
Trace make_trace(const std::vector<double>& times, const std::function<Reading(double)>& at) {
  Trace t;
  t.source = "analytic";
  t.format = "test";
  t.has_gyro = true;
  t.calibration.accel_from_device = true;
  for (double s : times) {
    const Reading r = at(s);
    TraceSample x;
    x.t_s = s;
    x.accel_g = r.accel_g;
    x.rate_deg_s = r.rate_deg_s;
    x.buttons = r.button ? kButtonB : 0u;
    t.samples.push_back(x);
  }
  return t;
}

// Irregular sample times: the interval grows from 4 to 20 ms over every 37 samples, a sawtooth in
// rate that no regular clock follows to within half an interval.
std::vector<double> irregular_times(double end_s) {
  std::vector<double> t{0.0};
  for (int k = 0; t.back() < end_s; ++k) t.push_back(t.back() + 0.004 + 0.016 * (k % 37) / 36.0);
  return t;
}

// A triangle pulse rising from 0 at a to `peak` at m and back to 0 at b (zero outside), and its
// integral from −∞ to t.
struct Triangle {
  double a, m, b, peak;
  double operator()(double t) const {
    if (t <= a || t >= b) return 0.0;
    return peak * (t < m ? (t - a) / (m - a) : (b - t) / (b - m));
  }
  double integral(double t) const {
    if (t <= a) return 0.0;
    if (t >= b) return 0.5 * peak * (b - a);
    if (t < m) return 0.5 * peak * (t - a) * (t - a) / (m - a);
    return 0.5 * peak * (b - a) - 0.5 * peak * (b - t) * (b - t) / (b - m);
  }
};

// The first sample at or after s.
double sample_after(const std::vector<double>& t, double s) {
  for (double x : t)
    if (x >= s) return x;
  return t.back();
}

// A triangle with its three kinks moved onto samples (so the trapezoid rule is exact for it).
Triangle on_samples(const std::vector<double>& t, double a, double m, double b, double peak) {
  return {sample_after(t, a), sample_after(t, m), sample_after(t, b), peak};
}

CaptureOptions quick_options() {
  CaptureOptions o;
  o.members = 8;  // the intervals are not what these tests look at
  return o;
}

// For the analytic throws that move without turning (closed forms for the integration): a real
// throw turns the wrist, and the rule that a swing without rotation is a gyro that did not record
// is switched off for them; it is tested on its own (a_swing_the_gyro_did_not_see_is_unusable).
CaptureOptions unturned_options() {
  CaptureOptions o = quick_options();
  o.rules.min_swing_rate_deg_s = 0;
  return o;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(capture_analysis)

BOOST_AUTO_TEST_CASE(irregular_steps_are_integrated_as_they_are_not_at_a_nominal_rate) {
  // Oracle: a remote lying face up is first turned about its Y axis by a triangle-profile rate
  // (angle θ = ∫ω dt in closed form), then pushed along world x by a triangle-profile acceleration
  // (speed ΔV = ∫a dt), then coasts; the button is released while it coasts. Sampled at irregular
  // times with each kink on a sample, the trapezoid/Bortz integration over the actual steps is exact,
  // so the release speed is ΔV and the attitude is the model's attitude_angles of the exact state.
  const std::vector<double> t = irregular_times(1.2);
  const Triangle rate_deg_s = on_samples(t, 0.45, 0.52, 0.62, 120.0);  // the turn
  const Triangle accel_m_s2 = on_samples(t, 0.70, 0.85, 0.90, 30.0);   // the push (3 g: below the clipping level)
  const double release = sample_after(t, 1.0);
  auto angle_rad = [&](double s) { return kDeg * rate_deg_s.integral(s); };
  const Trace trace = make_trace(t, [&](double s) {
    const Mat3 R = Eigen::AngleAxisd(angle_rad(s), Vec3::UnitY()).toRotationMatrix();
    const Vec3 a_world(accel_m_s2(s), 0, 0);
    return Reading{R.transpose() * (a_world / kG + Vec3::UnitZ()), Vec3(0, rate_deg_s(s), 0), s > 0.3 && s < release};
  });
  const CaptureAnalysis a = analyse_capture(trace, quick_options());
  BOOST_TEST_INFO((a.reasons.empty() ? std::string("") : a.reasons.front()));
  BOOST_REQUIRE(a.can_throw());
  BOOST_TEST(to_string(a.timing.stats.clock) == std::string("stamps_as_given"));  // the steps were kept as given
  const double dv = accel_m_s2.integral(release);
  BOOST_TEST(std::abs(a.nominal.measured_speed_m_s - dv) < kRoundoff * dv);
  RigidState exact;
  exact.orientation = Quat(Eigen::AngleAxisd(angle_rad(release), Vec3::UnitY()).toRotationMatrix() *
                           a.options.mounting.stone_axes());
  exact.velocity_m_s = Vec3(dv, 0, 0);
  const AttitudeAngles angles = attitude_angles(exact);
  BOOST_TEST(std::abs(a.nominal.attack_angle_deg - angles.attack_angle_deg) < kRoundoff);
  BOOST_TEST(std::abs(a.nominal.roll_angle_deg - angles.roll_angle_deg) < kRoundoff);
  BOOST_TEST(std::abs(angles.attack_angle_deg) + std::abs(angles.roll_angle_deg) > 10.0);  // the turn is seen
  // The rise: the stone offset turned with the remote (the remote itself moves horizontally).
  const Vec3 offset = a.options.mounting.stone_offset_m;
  const double rise = (Eigen::AngleAxisd(angle_rad(release), Vec3::UnitY()) * offset - offset).z();
  BOOST_TEST(std::abs(a.nominal.measured.rise_m - rise) < kRoundoff);
}

BOOST_AUTO_TEST_CASE(the_still_part_is_measured_in_time_not_in_samples) {
  // Oracle: the definition (min_still_s = 0.2 s of time). A still stretch of 0.19 s sampled at
  // 2 ms (95 samples) is too short; one of 0.21 s sampled at 30 ms (8 samples) is long enough.
  auto capture = [](double still_s, double still_step_s) {
    std::vector<double> t;
    for (double s = 0; s <= still_s + 1e-12; s += still_step_s) t.push_back(s);
    for (int k = 1; k <= 20; ++k) t.push_back(still_s + 0.01 * k);  // the swing, 10 ms steps
    return make_trace(t, [still_s](double s) {
      const bool moving = s > still_s + 1e-9;
      return Reading{Vec3(moving ? 2.0 : 0.0, 0, 1), Vec3(0, 0, moving ? 300.0 : 0.0), s < still_s + 0.15};
    });
  };
  CaptureOptions o = quick_options();
  const CaptureAnalysis dense = analyse_capture(capture(0.19, 0.002), o);
  BOOST_TEST(!dense.still_found);
  BOOST_TEST(to_string(dense.verdict) == std::string("unusable"));
  const CaptureAnalysis sparse = analyse_capture(capture(0.21, 0.03), o);
  BOOST_TEST(sparse.still_found);
  BOOST_TEST(sparse.still_t1_s - sparse.still_t0_s >= o.min_still_s);
}

BOOST_AUTO_TEST_CASE(the_virtual_thrower_maps_the_measured_throw_and_both_are_kept) {
  // Oracle: the mapping's definition (virtual_thrower.hpp) applied to the measured throw of a
  // capture whose release is exact (the push and coast of the test above, without the turn).
  const std::vector<double> t = irregular_times(1.2);
  const Triangle push = on_samples(t, 0.7, 0.8, 0.9, 30.0);
  const Trace trace = make_trace(t, [&](double s) {
    return Reading{Vec3(push(s) / kG, 0, 1), Vec3(0, 0, 0), s > 0.3 && s < 1.0};
  });
  CaptureOptions o = unturned_options();
  o.thrower.speed_scale = 2.0;
  o.thrower.finger_spin_rev_s = 12.0;
  o.thrower.release_height_m = 0.25;
  const CaptureAnalysis a = analyse_capture(trace, o);
  BOOST_REQUIRE(a.can_throw());
  BOOST_TEST(std::abs(a.nominal.measured_speed_m_s - push.integral(1.0)) < kRoundoff);
  BOOST_TEST(std::abs(a.nominal.speed_m_s - 2.0 * a.nominal.measured_speed_m_s) < kRoundoff);
  BOOST_TEST(std::abs(a.nominal.measured_spin_rev_s) < kRoundoff);  // the remote did not turn
  BOOST_TEST(std::abs(a.nominal.spin_rev_s - 12.0) < kRoundoff);     // the fingers' spin, added
  BOOST_TEST(a.nominal.height_m == 0.25);
  // The ensemble spreads the height within ±height_uncertainty_m, no further.
  BOOST_TEST(a.height_m.low >= 0.25 - o.thrower.height_uncertainty_m);
  BOOST_TEST(a.height_m.high <= 0.25 + o.thrower.height_uncertainty_m);
  BOOST_TEST(a.height_m.high > a.height_m.low);
  // still_part_height: the still part at still_height_m plus the measured rise (zero here).
  o.thrower.height_mapping = HeightMapping::still_part_height;
  const CaptureAnalysis b = analyse_capture(trace, o);
  BOOST_TEST(std::abs(b.nominal.height_m - o.thrower.still_height_m) < kRoundoff);
}

BOOST_AUTO_TEST_CASE(thrower_settings_are_checked_and_named) {
  // Oracle: the documented keys and ranges; a bad one names "thrower.KEY" and where it came from.
  VirtualThrowerOptions o;
  apply_thrower_setting(o, "release_height_m=0.4", "--thrower");
  apply_thrower_setting(o, "height_mapping=still_part_height", "--thrower");
  BOOST_TEST(o.release_height_m == 0.4);
  BOOST_TEST(to_string(o.height_mapping) == std::string("still_part_height"));
  auto message = [&](const std::string& s) {
    try {
      apply_thrower_setting(o, s, "throw.csv:3");
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  BOOST_TEST(message("release_hieght_m=0.4").find("thrower.release_hieght_m") != std::string::npos);
  BOOST_TEST(message("speed_scale=-1").find("throw.csv:3") != std::string::npos);
  BOOST_TEST(message("speed_scale=fast").find("not a number") != std::string::npos);
  BOOST_TEST(o.release_height_m == 0.4);  // a refused setting changes nothing
  const auto settings = thrower_settings(o);
  VirtualThrowerOptions back;
  for (const auto& s : settings) apply_thrower_setting(back, s, "round trip");
  BOOST_TEST(thrower_settings(back) == settings, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(the_verdict_follows_the_rules_thresholds) {
  // Oracle: the rules' definitions: the same findings judged under two jitter thresholds on either
  // side of the measured jitter give a caveat under one and none under the other.
  std::vector<double> t;
  for (int k = 0; k < 150; ++k) t.push_back(0.01 * k + (k % 2 ? 0.002 : 0.0));  // ±1 ms about 100 Hz
  const Trace trace = make_trace(t, [](double s) {
    return Reading{Vec3(Triangle{0.7, 0.8, 0.9, 20.0}(s) / kG, 0, 1), Vec3(0, 0, 0), s > 0.3 && s < 1.0};
  });
  CaptureOptions o = unturned_options();
  CaptureAnalysis a = analyse_capture(trace, o);
  BOOST_REQUIRE(a.can_throw());
  const double jitter = a.timing.stats.jitter_s;
  BOOST_TEST(std::abs(jitter - 0.002) < 0.0001);  // intervals alternate 12 and 8 ms
  BOOST_TEST(to_string(a.timing.stats.clock) == std::string("regular_reports"));  // every stamp within 1 ms of 100 Hz
  o.rules.jitter_caveat_s = 0.5 * jitter;
  a = analyse_capture(trace, o);
  BOOST_TEST(to_string(a.verdict) == std::string("usable with caveats"));
  BOOST_TEST(a.reasons.back().find("jitter") != std::string::npos);
  o.rules.jitter_caveat_s = 2 * jitter;
  a = analyse_capture(trace, o);
  BOOST_TEST(to_string(a.verdict) == std::string("usable"));
}

BOOST_AUTO_TEST_CASE(a_throw_no_human_could_make_is_unusable_naming_the_quantity) {
  // Oracle: the rules' plausibility bounds (capture_verdict.hpp: release speed 1–45 m/s, hand
  // within 3 m of the still part). The analytic throw (a 20 m/s² triangle over 0.2 s: 2 m/s, a few
  // cm of travel) is usable; the same findings with the WiiYourself numbers (47.5 m/s, 70 m)
  // are unusable, and bounds moved past the analytic throw's own values make it unusable with a
  // reason naming the quantity. A recording with no button column gets a caveat saying so.
  std::vector<double> t;
  for (int k = 0; k < 150; ++k) t.push_back(0.01 * k);
  const Trace trace = make_trace(t, [](double s) {
    return Reading{Vec3(Triangle{0.7, 0.8, 0.9, 20.0}(s) / kG, 0, 1), Vec3(0, 0, 0), s > 0.3 && s < 1.0};
  });
  CaptureOptions o = unturned_options();
  CaptureAnalysis a = analyse_capture(trace, o);
  BOOST_REQUIRE(a.can_throw());
  BOOST_TEST(to_string(a.verdict) == std::string("usable"));
  Record in = capture_verdict_inputs(a, o.rules);
  in.set("release_speed_m_s", 47.5);
  BOOST_TEST(decide("capture_verdict", in) == "unusable");
  in = capture_verdict_inputs(a, o.rules);
  in.set("hand_displacement_m", 70.0);
  BOOST_TEST(decide("capture_verdict", in) == "unusable");
  in = capture_verdict_inputs(a, o.rules);
  in.set("has_buttons", 0.0);
  in.set("release_at_end", 1.0);
  const CaptureConditions no_button = capture_conditions(in);
  BOOST_TEST((std::find(no_button.caveats.begin(), no_button.caveats.end(), "no_release_signal") != no_button.caveats.end()));

  o.rules.min_release_speed_m_s = 3.0;  // above the analytic 2 m/s
  a = analyse_capture(trace, o);
  BOOST_TEST(to_string(a.verdict) == std::string("unusable"));
  BOOST_TEST(a.reasons.front().find("release speed") != std::string::npos, a.reasons.front());
  o = unturned_options();
  o.rules.max_hand_displacement_m = 1e-4;  // below the analytic throw's travel
  a = analyse_capture(trace, o);
  BOOST_TEST(to_string(a.verdict) == std::string("unusable"));
  BOOST_TEST(a.reasons.front().find("hand displacement") != std::string::npos, a.reasons.front());
}

BOOST_AUTO_TEST_CASE(a_swing_the_gyro_did_not_see_is_unusable) {
  // Oracle: the swing's largest rate off the still part's mean, in closed form. The analytic throw
  // (a 20 m/s² triangle over 0.2 s) recorded with a gyro that reads a constant 3 deg/s throughout
  // (a MotionPlus stream stuck on its first report) shows 0 deg/s of rotation in the swing: below
  // the rule's 20 deg/s, unusable, and the reason says why. The same throw with the wrist turning
  // (a triangle of 300 deg/s about z over the swing, on the samples) shows 300 deg/s, and is not.
  std::vector<double> t;
  for (int k = 0; k < 150; ++k) t.push_back(0.01 * k);
  const Triangle push{0.7, 0.8, 0.9, 20.0}, turn{0.7, 0.8, 0.9, 300.0};
  CaptureOptions o;
  o.members = 8;
  const CaptureAnalysis stuck = analyse_capture(make_trace(t, [&](double s) {
    return Reading{Vec3(push(s) / kG, 0, 1), Vec3(3, 0, 0), s > 0.3 && s < 1.0};
  }), o);
  BOOST_TEST(stuck.swing_peak_rate_deg_s == 0.0, boost::test_tools::tolerance(1e-9));
  BOOST_TEST(to_string(stuck.verdict) == std::string("unusable"));
  BOOST_REQUIRE(!stuck.reasons.empty());
  BOOST_TEST(stuck.reasons.front().find("the MotionPlus shows no rotation through the swing") != std::string::npos,
             stuck.reasons.front());
  const CaptureAnalysis turning = analyse_capture(make_trace(t, [&](double s) {
    return Reading{Vec3(push(s) / kG, 0, 1), Vec3(0, 0, turn(s)), s > 0.3 && s < 1.0};
  }), o);
  BOOST_TEST(turning.swing_peak_rate_deg_s == 300.0, boost::test_tools::tolerance(1e-9));
  for (const std::string& r : turning.reasons) BOOST_TEST(r.find("no rotation") == std::string::npos, r);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(capture_options)

BOOST_AUTO_TEST_CASE(a_clip_level_a_still_remote_reaches_is_refused) {
  // --saturation-g 0.5 marked every sample clipped and the capture "had no still part", a note
  // calling the clipped samples "outside the swing". Oracle: the still part's own rule, |a| within
  // still_accel_tol_g of 1 g, so a clip level must lie above 1 + still_accel_tol_g.
  CaptureOptions o;
  std::string why;
  BOOST_TEST(o.is_valid(&why), why);  // the defaults
  o.saturation_g = 1 + o.still_accel_tol_g;
  BOOST_TEST(!o.is_valid(&why));
  BOOST_TEST(why.find("saturation_g must be above") != std::string::npos, why);
  o.saturation_g = 1 + 2 * o.still_accel_tol_g;
  BOOST_TEST(o.is_valid(&why), why);
}

BOOST_AUTO_TEST_SUITE_END()
