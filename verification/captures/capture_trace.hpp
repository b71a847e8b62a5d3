#pragma once
// One in-memory trace of a Wii Remote capture, whatever file it came from (model/README.md §4): per sample
// the host time, the acceleration in g per axis, the angular rate in deg/s per axis with the
// MotionPlus range mode it was read in, the core buttons, and flags (saturated axes, repeated
// report, reports lost before it). Every reader produces this; processing reads only this.
//
// The remote's frame (right-handed): X across the button face, Y along the remote toward its
// pointing end, Z out of the button face. A remote lying face up reads a = (0, 0, +1) g.
// Angular rates are right-handed about X (pitch), Y (roll) and Z (yaw).
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace stoneskip {

// The device calibration (model/README.md §4): a[g] = sign (raw − zero)/(one_g − zero); the MotionPlus rate
// [deg/s] = sign (raw − zero)/counts_per_deg_s, with counts_per_deg_s divided by fast_factor in
// fast mode. Sources disagree about the MotionPlus scale at the 10 % level: keep it a parameter.
struct CaptureCalibration {
  std::array<double, 3> accel_zero_counts{512, 512, 512};
  std::array<double, 3> accel_one_g_counts{616, 616, 616};
  std::array<int, 3> accel_sign{1, 1, 1};
  bool accel_from_device = false;  // the EEPROM calibration block was read (not the nominal one)
  bool accel_from_header = false;  // set by the file's header (calibration.block / accel_*): it wins
                                   // over a block the recording itself holds
  std::array<double, 3> gyro_zero_counts{8192, 8192, 8192};
  double gyro_slow_counts_per_deg_s = 20.0;
  double gyro_fast_factor = 2000.0 / 440.0;  // Linux hid-wiimote-modules.c uses 2000/440
  std::array<int, 3> gyro_sign{1, 1, 1};

  double accel_g(int axis, double raw) const {
    return accel_sign[axis] * (raw - accel_zero_counts[axis]) / (accel_one_g_counts[axis] - accel_zero_counts[axis]);
  }
  // A reading from a report: Y and Z come without their lowest bit (model/README.md §4: Y = AY<<2 |
  // (b1>>4 & 2)), so the 10-bit reading lies in [raw, raw + 1]; its mean, raw + ½, is used (taking
  // raw itself would read them half a count, ≈ 0.005 g, low and tilt gravity by ≈ 0.3°).
  double accel_g_from_report(int axis, double raw) const { return accel_g(axis, raw + (axis == 0 ? 0.0 : 0.5)); }
  double accel_lsb_g(int axis) const { return 1.0 / std::abs(accel_one_g_counts[axis] - accel_zero_counts[axis]); }
  double gyro_deg_s(int axis, double raw, bool fast) const {
    return gyro_sign[axis] * (raw - gyro_zero_counts[axis]) / gyro_slow_counts_per_deg_s * (fast ? gyro_fast_factor : 1.0);
  }
  double gyro_lsb_deg_s(bool fast) const { return (fast ? gyro_fast_factor : 1.0) / gyro_slow_counts_per_deg_s; }
  // Half the range of the 14-bit MotionPlus counts, in deg/s.
  double gyro_range_deg_s(bool fast) const { return 8192.0 * gyro_lsb_deg_s(fast); }
};

// Per-sample flags.
enum SampleFlag : std::uint32_t {
  kSaturatedX = 1u << 0,   // accelerometer X at its clipping level
  kSaturatedY = 1u << 1,
  kSaturatedZ = 1u << 2,
  kGyroSaturated = 1u << 3,  // a MotionPlus axis at the end of its 14-bit range
  kRepeated = 1u << 4,     // a repeat of the previous report (dropped by processing)
  kGapBefore = 1u << 5,    // reports were lost between the previous sample and this one
  kGyroHeld = 1u << 6,     // no MotionPlus frame for a silence's length before: the rate is held, not measured
};
constexpr std::uint32_t kAccelSaturated = kSaturatedX | kSaturatedY | kSaturatedZ;
// "XYZPRGH" letters, '-' for none (the trace CSV's flags column).
std::string flags_to_string(std::uint32_t flags);
// Parses the letters back; returns false on an unknown letter.
bool flags_from_string(const std::string& s, std::uint32_t& out);

// Core buttons as the 16-bit big-endian pair of WiiBrew's "BB BB": (byte0 << 8) | byte1.
constexpr unsigned kButtonB = 0x0004;  // byte 1 bit 0x04
constexpr unsigned kButtonA = 0x0008;  // byte 1 bit 0x08

struct TraceSample {
  double t_s = 0;
  Eigen::Vector3d accel_g = Eigen::Vector3d::Zero();
  Eigen::Vector3d rate_deg_s = Eigen::Vector3d::Zero();  // about remote X (pitch), Y (roll), Z (yaw)
  std::array<bool, 3> gyro_fast{false, false, false};    // MotionPlus range mode per axis
  unsigned buttons = 0;
  std::uint32_t flags = 0;
  long line = 0;  // the file's line the sample was read from (0: not from a file)
};

struct Trace {
  std::string source;       // file name as given
  std::string format;       // reader that produced it: trace_csv, report_log, evemu, gesture, csv
  bool has_accel = true;
  bool has_gyro = false;
  bool has_buttons = true;  // false: release at the file's end (gesture format)
  bool nominal_timestamps = false;  // no host timestamps in the file: times from the nominal rate
  bool gyro_mode_inferred = false;  // range modes inferred from jumps (no flags in the file)
  double nominal_rate_hz = 100.0;
  CaptureCalibration calibration;
  std::vector<std::string> mounting;  // "key=value" settings found in the file's header
  std::vector<std::string> thrower;   // "key=value" virtual thrower settings found in the header
  std::map<std::string, long> header_key_lines;  // each header key read, with its line (a key given twice is refused)
  std::vector<std::string> warnings;  // "FILE:LINE: what" for input that was used with a caveat
  std::vector<std::string> notes;     // what the reader chose or skipped (does not change a verdict)
  std::vector<TraceSample> samples;
};

}  // namespace stoneskip
