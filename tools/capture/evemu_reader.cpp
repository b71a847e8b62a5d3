#include "tools/capture/evemu_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>

#include "tools/capture/capture_header.hpp"
#include "tools/capture/capture_text.hpp"
#include "tools/capture/capture_times.hpp"
#include "tools/io/input_error.hpp"

namespace stoneskip {

namespace {
enum class Device { none, keys, accel, gyro, other };

constexpr int kEvSyn = 0x00, kEvKey = 0x01, kEvAbs = 0x03;
constexpr int kSynReport = 0x00;
constexpr int kAbsRx = 0x03, kAbsRy = 0x04, kAbsRz = 0x05;
constexpr int kBtnA = 0x130, kBtnB = 0x131;
constexpr long long kMaxMotionPlusValue = 8192LL * 18000 / 440;  // 335 127

std::string seconds(double s) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", s);
  return b;
}

std::string stamp(double s) {
  char b[40];
  std::snprintf(b, sizeof b, "%.6f", s);
  return b;
}

struct Frame {
  double t_s;
  std::array<double, 3> v;
  long line;  // the SYN_REPORT line that closed the frame
};
struct KeyEvent {
  double t_s;
  unsigned mask;
  bool down;
};

Device classify(std::string_view name) {
  if (name.find("Motion Plus") != std::string_view::npos) return Device::gyro;
  if (name.find("Accelerometer") != std::string_view::npos) return Device::accel;
  if (name == "Nintendo Wii Remote") return Device::keys;
  return Device::other;
}
// evdev passes on only what changed (input core drops an ABS value equal to the last one, and a
// SYN_REPORT with nothing before it): a report whose three accelerometer values repeat leaves
// no accelerometer frame, though its MotionPlus frame is there. Such a report is not lost: its
// accelerometer reading is the last one, held. Only where it can have repeated: inside the
// accelerometer's recording (not before its first frame or after its last: a recording that
// stops is not a still remote), and where the remote has turned less than kMaxHeldTurn_deg since
// that reading (gravity alone then moves by under 2 counts, g·1° ≈ 0.017 g at about 104 counts
// per g; a swing turns several degrees a report). Otherwise the report counts as lost. Without a
// MotionPlus such reports cannot be told from lost ones.
//
// Adds the held frames to accel_frames (in time order) and returns how many.
long hold_unchanged_readings(std::vector<Frame>& accel_frames, const std::vector<Frame>& gyro_frames,
                             double counts_per_deg_s, double same_report_s) {
  constexpr double kMaxHeldTurn_deg = 1.0;
  // The rate's zero: the driver subtracts 8192, not the device's own rest value (seen 7997-8084,
  // 5-10 deg/s off), so the turn is measured from the median of each axis, a capture being
  // mostly still.
  std::array<double, 3> zero{};
  for (int i = 0; i < 3 && !gyro_frames.empty(); ++i) {
    std::vector<double> v;
    for (const Frame& f : gyro_frames) v.push_back(f.v[i]);
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    zero[i] = v[v.size() / 2];
  }
  std::vector<Frame> held;
  std::size_t a = 0;
  for (const Frame& gf : gyro_frames) {
    while (a < accel_frames.size() && accel_frames[a].t_s < gf.t_s - same_report_s) ++a;
    const bool has_accel = a < accel_frames.size() && accel_frames[a].t_s <= gf.t_s + same_report_s;
    if (has_accel || a == 0 || a == accel_frames.size()) continue;  // its own frame, or outside the recording
    const Frame& last = accel_frames[a - 1];  // the reading held, and when it was made
    // The driver's MotionPlus values are 9 × slow-mode counts (fast mode rescaled to them).
    const double dx = gf.v[0] - zero[0], dy = gf.v[1] - zero[1], dz = gf.v[2] - zero[2];
    const double rate_deg_s = std::sqrt(dx * dx + dy * dy + dz * dz) / 9.0 / counts_per_deg_s;
    if (rate_deg_s * (gf.t_s - last.t_s) >= kMaxHeldTurn_deg) continue;
    held.push_back({gf.t_s, last.v, gf.line});
  }
  const long held_reports = static_cast<long>(held.size());
  if (!held.empty()) {
    std::vector<Frame> merged;
    merged.reserve(accel_frames.size() + held.size());
    std::merge(accel_frames.begin(), accel_frames.end(), held.begin(), held.end(), std::back_inserter(merged),
               [](const Frame& x, const Frame& y) { return x.t_s < y.t_s; });
    accel_frames = std::move(merged);
  }
  return held_reports;
}

}  // namespace

Trace read_evemu(const std::string& text, const std::string& file) {
  Trace t;
  t.source = file;
  t.format = "evemu";
  Device device = Device::none;
  bool saw_keys = false;
  std::array<double, 3> accel{}, gyro{};
  bool accel_changed = false, gyro_changed = false;
  // Each device's last event time: its events go forward in time, also across a second block of
  // the same device (a recording split in two); the other devices' blocks have their own clocks' order.
  std::array<double, 5> last_time_of{-1e300, -1e300, -1e300, -1e300, -1e300};
  std::array<long, 5> last_line_of{0, 0, 0, 0, 0};
  double last_time = -1e300;
  long last_time_line = 0;
  bool block_started = false;  // an event seen since the last 'N:' line
  std::vector<Frame> accel_frames, gyro_frames;
  std::vector<KeyEvent> keys;
  for (const TextLine& line : split_capture_lines(text, file)) {
    std::string_view s = trim(line.text);
    if (skip_blank_or_header(t, s, file, line.number)) continue;
    if (s.size() < 2 || s[1] != ':') {
      malformed_line(file, line, "not an evemu line (expected 'X: ...')", t.warnings);
      continue;
    }
    const char tag = s[0];
    std::string_view rest = trim(s.substr(2));
    if (tag == 'N') {
      device = classify(rest);
      if (device == Device::keys) saw_keys = true;
      if (device == Device::other)
        t.warnings.push_back(input_location(file, line.number, "") + ": device '" + std::string(rest) + "' ignored");
      last_time = device == Device::other ? -1e300 : last_time_of[static_cast<std::size_t>(device)];
      last_time_line = device == Device::other ? 0 : last_line_of[static_cast<std::size_t>(device)];
      accel_changed = gyro_changed = false;
      block_started = false;
      continue;
    }
    if (tag != 'E') continue;  // I:, P:, B:, A:, L:, S: describe the device
    if (device == Device::none) throw_input_error(file, line.number, "", "event before any device ('N:') line");
    const auto comment = rest.find('#');
    if (comment != std::string_view::npos) rest = rest.substr(0, comment);
    const auto f = split_fields(rest, false);
    if (f.size() != 4) {
      malformed_line(file, line, "an event needs 4 fields (time type code value), found " + std::to_string(f.size()),
                     t.warnings);
      continue;
    }
    const auto time = parse_real(f[0]);
    const auto type = parse_integer(f[1], 16), code = parse_integer(f[2], 16), value = parse_integer(f[3], 10);
    if (!time || !type || !code || !value) {
      malformed_line(file, line, "an event is 'E: seconds type(hex) code(hex) value'", t.warnings);
      continue;
    }
    if (*time < last_time) {
      char what[200];
      if (block_started)
        std::snprintf(what, sizeof what, "time goes backwards (%.15g s after %.15g s on line %ld)", *time, last_time,
                      last_time_line);
      else  // a second block of a device already recorded (the same recording twice?)
        std::snprintf(what, sizeof what,
                      "time goes backwards (%.15g s after %.15g s on line %ld, the last event of this device's earlier "
                      "block)",
                      *time, last_time, last_time_line);
      throw_input_error(file, line.number, "", what);
    }
    block_started = true;
    last_time = *time;
    last_time_line = line.number;
    if (device != Device::other) {
      last_time_of[static_cast<std::size_t>(device)] = *time;
      last_line_of[static_cast<std::size_t>(device)] = line.number;
    }
    if (device == Device::other) continue;
    if (*type == kEvAbs && (device == Device::accel || device == Device::gyro)) {
      const int axis = *code == kAbsRx ? 0 : *code == kAbsRy ? 1 : *code == kAbsRz ? 2 : -1;
      if (axis < 0) continue;
      // The driver's ranges (hid-wiimote-modules.c): the accelerometer writes its 10-bit reading
      // − 0x200, so −512..511; the MotionPlus (raw − 8192)·9 in slow mode and
      // (raw − 8192)·18000/440 in fast mode, raw 14 bits, so at most 335 127 in magnitude.
      if (device == Device::accel ? (*value < -512 || *value > 511) : std::llabs(*value) > kMaxMotionPlusValue)
        throw_input_error(file, line.number, "",
                          std::string(device == Device::accel ? "accelerometer" : "MotionPlus") + " value " +
                              std::to_string(*value) + " is outside the driver's range " +
                              (device == Device::accel ? "-512..511" : "-335127..335127"));
      if (device == Device::accel) {
        accel[axis] = double(*value);
        accel_changed = true;
      } else {
        // ABS_RX yaw → Z, ABS_RY roll → Y, ABS_RZ pitch → X.
        gyro[2 - axis] = double(*value);
        gyro_changed = true;
      }
    } else if (*type == kEvKey && device == Device::keys) {
      if (*code == kBtnA || *code == kBtnB) keys.push_back({*time, *code == kBtnA ? kButtonA : kButtonB, *value != 0});
    } else if (*type == kEvSyn && *code == kSynReport) {
      if (device == Device::accel && accel_changed) accel_frames.push_back({*time, accel, line.number});
      if (device == Device::gyro && gyro_changed) gyro_frames.push_back({*time, gyro, line.number});
    }
  }
  if (accel_frames.empty())
    throw_input_error(file, 0, "", "no events from a 'Nintendo Wii Remote Accelerometer' device");
  if (!saw_keys)
    t.warnings.push_back(file + ": no 'Nintendo Wii Remote' key device recorded: the button (release) is unknown");
  std::stable_sort(keys.begin(), keys.end(), [](const KeyEvent& a, const KeyEvent& b) { return a.t_s < b.t_s; });
  t.has_gyro = !gyro_frames.empty();
  const CaptureCalibration& c = t.calibration;
  // The range mode the driver hid: it writes (raw − 8192)·9 in slow mode, an exact multiple of 9,
  // and (raw − 8192)·18000/440 (integer division) in fast mode, which rarely is one (hid-wiimote-
  // modules.c, wiimod_mp_in_mp). A value beyond the slow range is fast whatever it is; a run of
  // fewer than kMinSlowRun multiples of 9 between fast frames is fast too (a fast value is a
  // multiple of 9 about one time in nine).
  constexpr std::size_t kMinSlowRun = 3;
  std::vector<std::array<bool, 3>> gyro_fast(gyro_frames.size());
  for (int i = 0; i < 3; ++i) {
    for (std::size_t f = 0; f < gyro_frames.size(); ++f)
      gyro_fast[f][i] = std::fmod(gyro_frames[f].v[i], 9.0) != 0.0 || std::abs(gyro_frames[f].v[i]) > 9.0 * 8192;
    for (std::size_t f = 0; f < gyro_frames.size();) {
      if (gyro_fast[f][i]) {
        ++f;
        continue;
      }
      std::size_t e = f;
      while (e < gyro_frames.size() && !gyro_fast[e][i]) ++e;
      if (f > 0 && e < gyro_frames.size() && e - f < kMinSlowRun)
        for (std::size_t k = f; k < e; ++k) gyro_fast[k][i] = true;
      f = e;
    }
  }
  constexpr double kSameReport_s = 2e-3;  // accelerometer and MotionPlus events of one HID report
  const long held_reports = hold_unchanged_readings(accel_frames, gyro_frames, t.calibration.gyro_slow_counts_per_deg_s,
                                                     kSameReport_s);
  // A MotionPlus that turns or merely sits still changes some count every report (its noise is
  // several counts; the driver writes (raw − 8192)·9), so ten reports without one of its frames are
  // not held values but a stream that is not there: before its first frame (the driver adds the
  // MotionPlus device after the remote's) or after its last (unplugged, or the recording cut), the
  // rate would be invented (zero, or the last frame's held for the rest of the throw). Such
  // accelerometer frames at either end are left out, and a silence inside the recording is warned of.
  constexpr double kGyroSilence_s = 0.1;
  std::vector<char> unseen(accel_frames.size(), 0);  // no MotionPlus frame within kGyroSilence_s before
  std::vector<std::size_t> frame_of(accel_frames.size(), 0);  // the MotionPlus frame each sample's rate is from
  std::size_t g = 0, k = 0;
  unsigned buttons = 0;
  for (const Frame& a : accel_frames) {
    TraceSample x;
    x.line = a.line;
    x.t_s = a.t_s;  // counted from the first sample's below
    for (int i = 0; i < 3; ++i) x.accel_g[i] = c.accel_g_from_report(i, a.v[i] + 0x200);
    while (g + 1 < gyro_frames.size() && gyro_frames[g + 1].t_s <= a.t_s + kSameReport_s) ++g;
    if (t.has_gyro) {
      unseen[t.samples.size()] = gyro_frames[g].t_s > a.t_s + kSameReport_s || a.t_s - gyro_frames[g].t_s > kGyroSilence_s;
      frame_of[t.samples.size()] = g;
    }
    if (t.has_gyro && gyro_frames[g].t_s <= a.t_s + kSameReport_s) {
      for (int i = 0; i < 3; ++i) {
        const double counts = gyro_frames[g].v[i] / 9.0;  // slow-mode counts from zero
        x.rate_deg_s[i] = c.gyro_sign[i] * counts / c.gyro_slow_counts_per_deg_s;
        x.gyro_fast[i] = gyro_fast[g][i];
        if (std::abs(counts) >= 8191.0 * c.gyro_fast_factor) x.flags |= kGyroSaturated;
      }
    }
    while (k < keys.size() && keys[k].t_s <= a.t_s) {
      buttons = keys[k].down ? (buttons | keys[k].mask) : (buttons & ~keys[k].mask);
      ++k;
    }
    x.buttons = buttons;
    t.samples.push_back(x);
  }
  if (t.has_gyro) {
    std::size_t first = 0, last = t.samples.size();
    while (first < last && unseen[first]) ++first;
    while (last > first && unseen[last - 1]) --last;
    if (first == last)
      throw_input_error(file, gyro_frames.front().line, "",
                        "no accelerometer frame lies within " + seconds(kGyroSilence_s) +
                            " s after a MotionPlus frame: the two streams do not overlap");
    const auto where = [&](std::size_t i) { return input_location(file, t.samples[i].line, ""); };
    if (first > 0)
      t.warnings.push_back(where(first) + ": the MotionPlus stream starts here; the " + std::to_string(first) +
                           " accelerometer frame(s) before it have no rotation and are left out");
    if (last < t.samples.size())
      t.warnings.push_back(where(last - 1) + ": the MotionPlus stream ends here (no frame for " +
                           seconds(kGyroSilence_s) + " s after); the " + std::to_string(t.samples.size() - last) +
                           " accelerometer frame(s) after it have no rotation and are left out");
    // A silence inside: its samples keep the last frame's rate, flagged held (the analysis judges
    // a held rate in the swing, capture_verdict.hpp); the first silence is named by the MotionPlus
    // frames around it.
    bool named = false;
    for (std::size_t i = first; i < last; ++i) {
      if (!unseen[i]) continue;
      t.samples[i].flags |= kGyroHeld;
      // The silence began at its last frame: the samples since, within the first 0.1 s, are held too.
      const double from_s = gyro_frames[frame_of[i]].t_s + kSameReport_s;
      for (std::size_t j = i; j > first && frame_of[j - 1] == frame_of[i] && t.samples[j - 1].t_s > from_s &&
                              !(t.samples[j - 1].flags & kGyroHeld);
           --j)
        t.samples[j - 1].flags |= kGyroHeld;
      if (named) continue;
      named = true;
      const Frame& before = gyro_frames[frame_of[i]];
      const bool after = frame_of[i] + 1 < gyro_frames.size();
      const Frame& next = after ? gyro_frames[frame_of[i] + 1] : before;
      t.warnings.push_back(input_location(file, before.line, "") + ": no MotionPlus frame from here (t = " +
                           stamp(before.t_s) + " s) to line " + std::to_string(next.line) + " (t = " +
                           stamp(next.t_s) + " s), " + seconds(next.t_s - before.t_s) +
                           " s: the rate is held from this frame over that time (samples flagged H)");
    }
    t.samples.erase(t.samples.begin() + static_cast<std::ptrdiff_t>(last), t.samples.end());
    t.samples.erase(t.samples.begin(), t.samples.begin() + static_cast<std::ptrdiff_t>(first));
  }
  count_times_from_first(t);  // capture_times.hpp
  if (held_reports > 0)
    t.notes.push_back(std::to_string(held_reports) + " report" + (held_reports == 1 ? "" : "s") +
                      " with MotionPlus data but no accelerometer frame (evdev passes on only changed values): the "
                      "accelerometer reading held from the previous report");
  return t;
}

}  // namespace stoneskip
