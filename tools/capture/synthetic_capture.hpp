#pragma once
// Synthetic captures with a known truth: a side-arm throw about a moving pivot, recorded as a real
// Wii Remote with MotionPlus would record it (model/README.md §4): the accelerometer clips at ±clip_g and is
// quantised to 10 bits (Y and Z lose their lowest bit in the report), the MotionPlus switches to
// fast mode above fast_above_deg_s (back below slow_below_deg_s), reports come at ≈ rate_hz with
// host-clock jitter, some are lost and some repeated.
//
// The motion (world frame, z up): the arm, the remote and the stone turn together about the axis
// k = (sin β, 0, cos β) through a pivot that itself moves along the release direction
// d = (cos β, 0, −sin β). The turn rate rises as Ω s(τ) (s = 3τ² − 2τ³, τ = (t − t_swing)/T) and
// the pivot speed as V s(τ), so both peak at the release; then both fall back over the
// follow-through. At the release the stone moves along d with speed V + Ω|lever|, its normal is
// tilted by the attack angle, and it spins at Ω cos(α + β) about its normal (what a remote on the
// forearm can see); the fingers may add finger_spin_rev_s, which no sensor sees (truth only).
// Everything a sensor reads follows analytically.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "verification/captures/mounting.hpp"

namespace stoneskip {

struct SyntheticThrow {
  double swing_rate_rad_s = 14.0;   // Ω at release
  double swing_duration_s = 0.25;   // T
  double pivot_speed_m_s = 1.5;     // V at release
  double pivot_elevation_deg = 0.0; // the pivot's path raised above d by this angle (the trunk
                                    // rising or dropping): the lever arm then misses the direction too
  double path_angle_deg = 10.0;     // β
  double attack_angle_deg = 15.0;   // α
  double release_height_m = 0.9;    // the stone's centre at release
  double still_s = 0.8;             // before the swing
  double press_at_s = 0.3;          // the button goes down
  double follow_through_s = 0.25;
  double after_s = 0.2;             // still again at the end
  double finger_spin_rev_s = 0.0;   // added by the fingers at release: in the truth, not in the readings
  Mounting mounting;                // the truth (the lever arm is exact)
};

// A skipping throw as published (model/README.md §3), as the arm of a side-arm thrower makes it:
//   * speed 8–15 m/s: Bocquet (Am. J. Phys. 71:150, 2003) takes 12 m/s as a good throw; the
//     world-record throws are near 19 m/s;
//   * spin 10–20 rev/s: Bocquet's example is 14 rev/s (hand throws; Clanet's launcher reached 65);
//   * attack angle near Clanet's optimum α ≈ 20° and a small path angle β (Clanet, Hersen &
//     Bocquet, Nature 427:29, 2004; Rosellini et al., J. Fluid Mech. 543:137, 2005);
//   * release "a few tens of centimetres" above the water, side-arm, the thrower crouching.
// The arm: a swing about the shoulder (the mounting's lever arm, 0.6 m) whose pivot moves forward
// with pivot_share of the speed (the trunk's turn), over swing_duration_s = 0.2 s (7–20 g,
// model/README.md §4). The arm's turn gives the stone Ω cos(α + β) of spin; the rest of spin_rev_s is the
// fingers' (finger_spin_rev_s).
struct SkippingThrowSpec {
  double speed_m_s = 12.0;
  double spin_rev_s = 14.0;
  double attack_angle_deg = 20.0;
  double path_angle_deg = 5.0;
  double release_height_m = 0.3;
  double pivot_share = 0.15;
  double swing_duration_s = 0.2;
  Mounting mounting;  // how the remote is strapped (its lever arm sets the swing rate for the speed)
};
SyntheticThrow skipping_throw(const SkippingThrowSpec& spec);

struct SyntheticSensor {
  double rate_hz = 100.0;
  double jitter_s = 0.002;          // host stamps: ± uniform
  double latency_s = 0.004;
  double drop_probability = 0.015;
  double repeat_probability = 0.01;
  double clip_g = 3.6;
  double accel_noise_g = 0.005;
  double gyro_noise_deg_s = 0.2;
  std::array<int, 3> accel_zero_counts{506, 513, 518};
  std::array<int, 3> accel_one_g_counts{610, 617, 621};
  std::array<double, 3> gyro_zero_counts{8050, 8120, 7995};
  double gyro_slow_counts_per_deg_s = 20.0;
  double gyro_fast_factor = 2000.0 / 440.0;
  double fast_above_deg_s = 350.0;
  double slow_below_deg_s = 250.0;
  std::uint8_t report_id = 0x35;    // 0x35 or 0x37
  std::uint64_t seed = 1;
};

struct SyntheticTruth {
  double release_t_s = 0;           // remote clock
  // The stone at release as the remote can measure it: spin about its normal from the arm, and the
  // stone centre's rise from the still part.
  double speed_m_s = 0, path_angle_deg = 0, attack_angle_deg = 0, spin_rev_s = 0, rise_m = 0;
  // The velocity's two parts at release: the arm's turn about the pivot |Ω k × L| (what angular
  // rate × lever arm can see) and the pivot's own speed V (the trunk's turn, which it cannot).
  double arm_speed_m_s = 0, pivot_speed_m_s = 0;
  // The skipping stone the throw stands for: height above the water, the fingers' spin, the total.
  double height_m = 0, finger_spin_rev_s = 0, total_spin_rev_s = 0;
  double still_s = 0;               // the still part before the swing
  long reports_sent = 0, dropped_reports = 0, repeated_reports = 0;
  int range_switches = 0;
  int clipped_samples = 0;          // samples with an axis beyond clip_g
  std::vector<double> received_stamps_s;  // host stamps of the kept (non-repeated) reports
  std::vector<std::array<bool, 3>> written_fast;  // MotionPlus fast mode of each sample written (gesture rows)
  std::string toml() const;         // the sidecar .truth.toml
};

// The throw and what each sensor sees at time t (remote clock).
struct SyntheticSample {
  Vec3 accel_g = Vec3::Zero();       // specific force in the remote frame, unclipped
  Vec3 rate_deg_s = Vec3::Zero();    // remote frame
  bool button = false;
};
SyntheticSample synthetic_sample(const SyntheticThrow& th, double t_s);
double synthetic_duration_s(const SyntheticThrow& th);
double synthetic_release_time_s(const SyntheticThrow& th);

// The stone centre's position (world, release at the origin) at time t.
Vec3 synthetic_stone_position(const SyntheticThrow& th, double t_s);

// A raw report log (report_log.hpp) and its truth.
std::string synthetic_report_log(const SyntheticThrow& th, const SyntheticSensor& sensor, SyntheticTruth& truth);
// The same throw in the wiiuse gesture format (press to release, no drops) and as evemu-record text.
std::string synthetic_gesture(const SyntheticThrow& th, const SyntheticSensor& sensor, SyntheticTruth& truth);
std::string synthetic_evemu(const SyntheticThrow& th, const SyntheticSensor& sensor, SyntheticTruth& truth);

// A WiiYourself!-style CSV log of two remotes (header_csv.hpp reads it): the thrower's remote
// (#WM1, `sensor`) and a second remote lying face up on a table (#WM2, `idle`). A row is written
// whenever either remote reports something new (WiiYourself! calls back on a change only), with
// both remotes' latest state: host time in integer milliseconds (timeGetTime), the accelerometer's
// pitch and roll, Acc X/Y/Z in g from the 8 high bits (as WiiYourself! computes them), the
// MotionPlus raw words in hex (%04hx), WiiYourself!'s Speed Yaw/Pitch/Roll (−(raw − 0x1F7F)·0.05 or
// 0.25 deg/s) and Button.Bits in hex (B 0x0400). Irregular times: two unsynchronised 100 Hz
// streams, host jitter, millisecond rounding and lost reports.
std::string synthetic_wiiyourself_csv(const SyntheticThrow& th, const SyntheticSensor& sensor, const SyntheticSensor& idle,
                                      SyntheticTruth& truth);

}  // namespace stoneskip
