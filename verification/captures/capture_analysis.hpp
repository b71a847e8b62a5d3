#pragma once
// From a trace to the throw it records (model/README.md §4, §1.7). The entry point is analyse_capture:
// CaptureOptions in, CaptureAnalysis out; nothing prints. Steps, in order:
//   1. timing: repeats dropped, the clock chosen from the time column (capture_timing.hpp), gaps,
//      jitter, equal stamps counted;
//   2. saturation: an accelerometer axis at or beyond saturation_g is clipped (ADXL330: rated
//      ±3 g, real remotes clip near ±3.5–4.6 g);
//   3. the release: the last release of the action button (B by default); the true release lies
//      between the last sample with the button down and the first with it up. Files without
//      buttons (gesture): the file's end;
//   4. the still part: the latest stretch before the release, at least min_still_s long (in time,
//      not in samples), where the acceleration and the rate stay within still_accel_tol_g /
//      still_rate_tol_deg_s of their means. It gives the gravity direction, the check |a| = 1 g,
//      and the gyro bias (in slow-mode units, so it applies in fast mode scaled by the fast factor);
//   5. orientation: gravity sets the initial attitude (the heading is free), then the bias-corrected
//      rates are integrated over the actual steps (quaternion, midpoint rate with the commutation
//      correction, Bortz 1971 to second order);
//   6. linear acceleration a = g0 (R f − |f_still| ez), integrated (trapezoid over the actual steps)
//      from the end of the still part to the velocity and position of the remote;
//   7. the release state of the stone as measured: v = v_remote + ω × R r_offset (accelerometer),
//      and v_lever = R (ω × lever_arm) (the swing about a fixed pivot); the heading is turned so the
//      horizontal velocity points along +x; attack and path angles as model/stone/throw.hpp;
//      spin = the rate about the stone's normal; rise = the stone centre's rise since the still part;
//   8. the virtual thrower (virtual_thrower.hpp) maps it to the virtual stone: height above the
//      virtual water, speed and spin scaling, finger spin;
//   9. the verdict (capture_verdict.hpp).
// When the accelerometer clipped during the swing its velocity is only a lower bound: the throw
// then takes the lever-arm velocity, raised to that bound where it is slower (the lever arm misses
// the pivot's own motion), and the speed interval is the accelerometer's bounds (clipped spans as
// recorded … filled at max_accel_g) joined with the members' speeds, each member raised to its own
// bound (its spans as recorded, its other perturbations the same).
// Uncertainty: the whole chain is re-run on perturbed copies (per-sample noise and quantisation,
// a per-member accelerometer bias, release time within its interval, gyro scale, lever arm,
// virtual height, clipped spans filled with random bumps up to max_accel_g, and spans where the
// MotionPlus reached the end of its range with random bumps up to max_rate_deg_s: a saturated
// rate is a lower bound, so spin, attitude and the lever-arm speed may be larger than it shows);
// intervals are the nominal value joined with the 2.5–97.5 % range of the members.
#include <array>
#include <random>
#include <string>
#include <vector>

#include "model/stone/stone.hpp"
#include "verification/captures/capture_timing.hpp"
#include "verification/captures/capture_trace.hpp"
#include "verification/captures/capture_verdict.hpp"
#include "verification/captures/mounting.hpp"
#include "verification/captures/virtual_thrower.hpp"

namespace stoneskip {

struct CaptureOptions {
  Mounting mounting;                         // after the file's header and the command line
  VirtualThrowerOptions thrower;             // after the file's header and the command line
  TimingOptions timing;
  CaptureVerdictRules rules;
  unsigned release_button = kButtonB;
  double saturation_g = 3.4;                 // |a| at or beyond this on an axis: clipped (remotes clip at 3.5–4.6 g)
  double max_accel_g = 20.0;                 // what a clipped span may have hidden (model/README.md §4: 7–20 g)
  // What a span where the MotionPlus reached the end of its range may have hidden: the fastest
  // segment rotation measured in human throwing, the humerus's internal rotation in baseball
  // pitching, 7 500–7 700 deg/s (Seroyer et al., Sports Health 2:135, 2010, citing Fleisig et al.).
  double max_rate_deg_s = 7700.0;
  double gravity_m_s2 = 9.81;
  // The still part: 0.2 s holds 20 reports at 100 Hz, enough to average the noise to ≈ 0.002 g.
  double min_still_s = 0.2;
  double still_accel_tol_g = 0.06;           // a hand held still wavers by a few hundredths of a g
  double still_rate_tol_deg_s = 4.0;         // … and a few deg/s
  // Ensemble perturbations.
  double accel_noise_g = 0.01;               // per sample (1 σ): ADXL330 noise at 100 Hz bandwidth
  // Per member, uniform ± per axis on every sample: the calibration is stored in whole 10-bit counts
  // (rounding ±0.005 g). The still part's mean also gets its own ± half a quantisation step (an
  // undithered constant keeps its rounding: 10-bit X 0.005 g, Y and Z 0.01 g, WiiYourself!'s 8 bits
  // 0.02 g), the step taken from the data when coarser than the calibration's.
  double accel_bias_g = 0.005;
  double gyro_noise_deg_s = 0.3;             // per sample (1 σ)
  double gyro_scale_rel_uncertainty = 0.05;  // ± (uniform); model/README.md §4: sources disagree at 10 %
  int members = 64;                          // ensemble size
  unsigned seed = 20130101;

  // False with the reason (naming the field) when a value is out of range.
  bool is_valid(std::string* why) const;
};

// The intervals (and the ensemble's bounce-count range) span these quantiles of the members.
constexpr double kIntervalLowQuantile = 0.025;
constexpr double kIntervalHighQuantile = 0.975;
// The fewest members whose 2.5 % quantile lies beyond the least of them (0.025 (n − 1) ≥ 1): with
// fewer, the interval's ends are read between the extreme draws and their neighbours, and the
// range the quantiles name is not resolved.
constexpr int kMembersResolvingInterval = 41;

struct Interval {
  double nominal = 0, low = 0, high = 0;
  bool contains(double x) const { return x >= low && x <= high; }
};

// The stone at release. The world frame has its heading turned so the measured horizontal
// velocity is along +x. velocity_m_s, omega_body_rad_s, height_m, speed_m_s and spin_rev_s are the
// virtual stone's (after the virtual thrower); `measured` holds the throw as the remote saw it.
struct ReleaseKinematics {
  double t_s = 0;
  Vec3 accel_velocity_m_s = Vec3::Zero();  // measured, from the integrated acceleration
  Vec3 lever_velocity_m_s = Vec3::Zero();  // measured, from ω × lever arm
  MeasuredThrow measured;                  // velocity: the one used (lever arm when clipped)
  Vec3 velocity_m_s = Vec3::Zero();        // virtual
  Quat stone_orientation = Quat::Identity();  // stone body → world
  Vec3 omega_body_rad_s = Vec3::Zero();    // virtual, in the stone's body frame
  double height_m = 0;                     // virtual: stone centre above the virtual water
  double speed_m_s = 0, accel_speed_m_s = 0, lever_speed_m_s = 0;  // virtual; measured; measured
  double measured_speed_m_s = 0, measured_spin_rev_s = 0;
  double attack_angle_deg = 0, path_angle_deg = 0, roll_angle_deg = 0, spin_rev_s = 0;
  bool speed_floored = false;  // clipped: the lever arm's speed raised to the accelerometer's lower bound
  double speed_floor_m_s = 0;  // clipped: that bound (the run's own: a member's twin, spans as recorded)
  bool finite() const;
};

// One way of filling clipped spans when re-running the chain.
enum class ClipFill { as_recorded, random_bump, at_max };
// An ensemble member's perturbations, or none.
enum class Perturb { none, random };

struct Perturbation {
  Perturb kind = Perturb::none;  // random: noise, bias, gyro scale, lever arm, height, release time
  ClipFill fill = ClipFill::as_recorded;       // accelerometer spans, up to max_accel_g
  ClipFill gyro_fill = ClipFill::as_recorded;  // MotionPlus spans at the end of its range, up to max_rate_deg_s
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
  // The stone centre's position in the room relative to where it was at the start of the still
  // part, in the release state's frame (heading turned: the horizontal release velocity along +x).
  std::vector<Vec3> stone_position_m;
  std::vector<unsigned> buttons;
  std::vector<std::uint32_t> flags;
};

// The summary of one capture.
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
  std::string clipped_axes;          // e.g. "X, Y"
  bool gyro_saturated_in_swing = false;
  // The swing's largest angular rate off the still part's mean (deg/s, each axis at its recorded
  // range): a wrist that throws turns at hundreds of deg/s, a gyro that did not record reads ≈ 0.
  double swing_peak_rate_deg_s = 0;
  // Swing samples whose rate is held over a MotionPlus silence (kGyroHeld), and the first one's time.
  int gyro_held_in_swing = 0;
  double gyro_held_from_s = 0;
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
  bool nominal_computed = false;     // the chain ran (the preconditions held)
  ReleaseKinematics nominal;
  ReleaseKinematics accel_lower, accel_upper;  // clipped spans as recorded / at max_accel_g
  // The virtual stone's (what the solvers get) …
  Interval speed_m_s, attack_angle_deg, path_angle_deg, spin_rev_s, height_m;
  // … and the throw as measured in the room.
  Interval accel_speed_m_s, lever_speed_m_s, measured_speed_m_s, measured_spin_rev_s, rise_m;
  double speed_difference_m_s = 0;   // |v_accel| − |v_lever| (nominal, measured)
  std::vector<ReleaseKinematics> ensemble;
  ProcessedSeries series;
  // verdict
  Verdict verdict = Verdict::unusable;
  std::vector<std::string> reasons;  // unusable reasons first, then caveats
  std::vector<std::string> notes;    // information that does not change the verdict
  bool can_throw() const { return verdict != Verdict::unusable; }
};

CaptureAnalysis analyse_capture(const Trace& trace, const CaptureOptions& options);

// Mounting and virtual thrower from the file's header settings, then the command line's (both
// "key=value").
Mounting resolve_mounting(const Trace& trace, const std::vector<std::string>& overrides);
VirtualThrowerOptions resolve_thrower(const Trace& trace, const std::vector<std::string>& overrides);

}  // namespace stoneskip
