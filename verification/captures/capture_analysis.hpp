#pragma once
// From a trace to the throw it records (spec §4, §1.7). Steps, in order:
//   1. timing: repeats dropped, gaps and jitter counted, clock de-jittered (capture_timing.hpp);
//   2. saturation: an accelerometer axis at or beyond saturation_g is clipped (ADXL330: rated
//      ±3 g, real remotes clip near ±3.5–4.6 g);
//   3. the release: the last release of the action button (B by default); the true release lies
//      between the last sample with the button down and the first with it up. Gesture files: the
//      file's end;
//   4. the still part: the latest stretch before the release, at least min_still_s long, where the
//      acceleration and the rate stay within still_accel_tol_g / still_rate_tol_deg_s of their
//      means. It gives the gravity direction, the check |a| = 1 g, and the gyro bias (in slow-mode
//      counts, so it applies in fast mode scaled by the fast factor);
//   5. orientation: gravity sets the initial attitude (the heading is free), then the bias-corrected
//      rates are integrated (quaternion, midpoint rate with the commutation correction);
//   6. linear acceleration a = g0 (R f − |f_still| ez), integrated (trapezoid) from the end of the
//      still part to the velocity and position of the remote;
//   7. the release state of the stone: v = v_remote + ω × R r_offset (accelerometer), and
//      v_lever = R (ω × lever_arm) (the swing about a fixed pivot); the heading is turned so the
//      horizontal velocity points along +x; attack and path angles as model/stone/throw.hpp;
//      spin = the rate about the stone's normal; height = start height + the stone's rise.
// When the accelerometer clipped during the swing its velocity is only a lower bound: the throw
// then takes the lever-arm velocity, and the speed interval spans the accelerometer's bounds
// (clipped spans at the clip level … at max_accel_g) and the lever-arm interval.
// Uncertainty (capture_uncertainty.cpp): the whole chain is re-run on perturbed copies (noise,
// quantisation, release time within its interval, gyro scale, lever arm, start height, clipped
// spans filled with random bumps up to max_accel_g); intervals are the 2.5–97.5 % range.
#include <random>
#include <string>
#include <vector>

#include "model/stone/stone.hpp"
#include "verification/captures/capture_timing.hpp"
#include "verification/captures/capture_trace.hpp"
#include "verification/captures/mounting.hpp"

namespace stoneskip {

struct CaptureOptions {
  Mounting mounting;                         // after the file's header and the command line
  unsigned release_button = kButtonB;
  double saturation_g = 3.4;                 // |a| at or beyond this on an axis: clipped
  double max_accel_g = 20.0;                 // what a clipped span may have hidden (spec §4: 7–20 g)
  double gravity_m_s2 = 9.81;
  double min_still_s = 0.2;
  double still_accel_tol_g = 0.06;
  double still_rate_tol_deg_s = 4.0;
  double calibration_tol_g = 0.05;           // still-part check |a| = 1 g
  double start_height_m = 1.0;               // stone centre's height during the still part
  double start_height_uncertainty_m = 0.1;
  double accel_noise_g = 0.01;               // per-sample noise (1 σ) for the ensemble
  double gyro_noise_deg_s = 0.3;
  double gyro_scale_rel_uncertainty = 0.05;  // ± (uniform); spec §4: sources disagree at 10 %
  int members = 64;                          // ensemble size
  unsigned seed = 20130101;
};

struct Interval {
  double nominal = 0, low = 0, high = 0;
  bool contains(double x) const { return x >= low && x <= high; }
};

// The stone at release (world frame with the heading turned so horizontal velocity is along +x).
struct ReleaseKinematics {
  double t_s = 0;
  Vec3 accel_velocity_m_s = Vec3::Zero();  // from the integrated acceleration
  Vec3 lever_velocity_m_s = Vec3::Zero();  // from ω × lever arm
  Vec3 velocity_m_s = Vec3::Zero();        // the one used (lever arm when clipped)
  Quat stone_orientation = Quat::Identity();  // stone body → world
  Vec3 omega_body_rad_s = Vec3::Zero();    // in the stone's body frame
  double height_m = 0;
  double speed_m_s = 0, accel_speed_m_s = 0, lever_speed_m_s = 0;
  double attack_angle_deg = 0, path_angle_deg = 0, roll_angle_deg = 0, spin_rev_s = 0;
  bool finite() const;
};

// One way of filling clipped spans when re-running the chain.
enum class ClipFill { as_recorded, random_bump, at_max };

struct Perturbation {
  bool random = false;         // noise, gyro scale, lever arm, height, release time
  ClipFill fill = ClipFill::as_recorded;
  std::uint64_t seed = 0;
};

struct SaturatedSpan {
  int axis = 0;                 // 0 X, 1 Y, 2 Z
  double t0_s = 0, t1_s = 0;    // first and last saturated sample
  int samples = 0;
};

// Series for plots (kept samples, times relative to the first).
struct ProcessedSeries {
  std::vector<double> t_s;
  std::vector<Vec3> accel_g, rate_deg_s;  // as recorded (rate bias-corrected)
  std::vector<Vec3> world_accel_m_s2, remote_velocity_m_s;  // zero before the still part ends
  std::vector<double> stone_speed_m_s;    // |v_remote + ω × R r_offset|
  std::vector<unsigned> buttons;
  std::vector<std::uint32_t> flags;
};

enum class Verdict { usable, usable_with_caveats, unusable };
const char* to_string(Verdict v);

struct CaptureAnalysis {
  std::string source, format;
  Trace trace;
  CaptureOptions options;
  TimedSamples timing;
  // saturation
  std::array<int, 3> saturated_samples{0, 0, 0};
  int saturated_any = 0;
  double saturated_fraction = 0;     // kept samples with any axis clipped / kept samples
  int saturated_in_swing = 0;        // between the still part's end and the release
  int swing_samples = 0;
  bool clipped = false;              // clipped during the swing
  bool gyro_saturated_in_swing = false;
  std::vector<SaturatedSpan> spans;
  // release
  bool press_found = false, release_found = false, release_at_end = false;
  double release_t_s = 0, release_t_low_s = 0, release_t_high_s = 0;
  std::size_t release_sample = 0;   // last kept sample with the button down (kept index)
  // still part
  bool still_found = false;
  double still_t0_s = 0, still_t1_s = 0;
  std::size_t still_begin = 0, still_end = 0;  // kept indices [begin, end]
  double still_accel_g = 0;          // |mean a|
  double still_accel_error_g = 0;    // |mean a| − 1
  Vec3 gyro_bias_deg_s = Vec3::Zero();  // slow-mode deg/s
  int gyro_range_switches = 0;
  // the throw
  ReleaseKinematics nominal;
  ReleaseKinematics accel_lower, accel_upper;  // clipped spans as recorded / at max_accel_g
  Interval speed_m_s, accel_speed_m_s, lever_speed_m_s, attack_angle_deg, path_angle_deg, spin_rev_s, height_m;
  double speed_difference_m_s = 0;   // |v_accel| − |v_lever| (nominal)
  std::vector<ReleaseKinematics> ensemble;
  ProcessedSeries series;
  // verdict
  Verdict verdict = Verdict::unusable;
  std::vector<std::string> reasons;  // unusable reasons first, then caveats
  std::vector<std::string> notes;    // information that does not change the verdict
  bool can_throw() const { return verdict != Verdict::unusable; }
};

CaptureAnalysis analyse_capture(const Trace& trace, const CaptureOptions& options);

// Mounting from the file's header settings, then the command line's (both "key=value").
Mounting resolve_mounting(const Trace& trace, const std::vector<std::string>& overrides);

}  // namespace stoneskip
