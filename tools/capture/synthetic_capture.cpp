#include "tools/capture/synthetic_capture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <random>

#include "model/stone/throw.hpp"
#include "tools/capture/wiimote_report.hpp"
#include "tools/io/portable_random.hpp"

namespace stoneskip {

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kG = 9.81;

// s(τ) = 3τ² − 2τ³ and its integral and derivative.
double ramp(double x) { return x * x * (3 - 2 * x); }
double ramp_integral(double x) { return x * x * x - 0.5 * x * x * x * x; }
double ramp_slope(double x) { return 6 * x * (1 - x); }

// A quantity that rises as peak·s(τ) over the swing and falls back over the follow-through:
// value (displacement from release), rate, and its derivative.
struct Profile {
  double pos, rate, accel;
};
Profile profile(const SyntheticThrow& th, double peak, double t) {
  const double t_sw = th.still_s, T = th.swing_duration_s, t_r = t_sw + T, Tf = th.follow_through_s;
  if (t < t_sw) return {peak * T * (0 - 0.5), 0, 0};
  if (t <= t_r) {
    const double x = (t - t_sw) / T;
    return {peak * T * (ramp_integral(x) - 0.5), peak * ramp(x), peak * ramp_slope(x) / T};
  }
  if (t <= t_r + Tf) {
    const double x = (t - t_r) / Tf;
    return {peak * Tf * (x - ramp_integral(x)), peak * (1 - ramp(x)), -peak * ramp_slope(x) / Tf};
  }
  return {peak * Tf * 0.5, 0, 0};
}

struct Geometry {
  Vec3 k, d;
  Mat3 R_stone_r, R_remote_r, M;
  Vec3 lever_world_r;
};
Geometry geometry(const SyntheticThrow& th) {
  Geometry g;
  const double b = th.path_angle_deg * kDeg, a = th.attack_angle_deg * kDeg;
  g.k = Vec3(std::sin(b), 0, std::cos(b));
  g.d = Vec3(std::cos(b), 0, -std::sin(b));
  g.R_stone_r = Eigen::AngleAxisd(-a, Vec3::UnitY()).toRotationMatrix();  // model/README.md §1.7
  g.M = th.mounting.stone_axes();
  g.R_remote_r = g.R_stone_r * g.M.transpose();
  g.lever_world_r = g.R_remote_r * th.mounting.lever_arm_m;
  return g;
}

// The pivot's path: d raised by pivot_elevation_deg in the vertical plane of d (d itself at 0).
Vec3 pivot_direction(const SyntheticThrow& th, const Geometry& g) {
  if (th.pivot_elevation_deg == 0) return g.d;
  const double b = (th.path_angle_deg - th.pivot_elevation_deg) * kDeg;
  return Vec3(std::cos(b), 0, -std::sin(b));
}

std::string hex(const std::vector<std::uint8_t>& b) {
  std::string s;
  char x[4];
  for (std::size_t i = 0; i < b.size(); ++i) {
    std::snprintf(x, sizeof x, i ? " %02x" : "%02x", b[i]);
    s += x;
  }
  return s;
}

// The sensor chain shared by the three writers: one reading per report of the remote.
struct Reading {
  double t_s;          // remote clock
  double stamp_s;      // host clock
  bool dropped, repeated;
  std::array<int, 3> accel_raw;
  std::array<int, 3> gyro_raw;
  std::array<bool, 3> slow;
  bool button;
};

// The sensor chain on any motion: one reading per report of the remote over [0, end], the host
// stamps offset by clock_offset_s; the recording counters go into truth.
std::vector<Reading> sense(const std::function<SyntheticSample(double)>& at, double end, const SyntheticSensor& s,
                           SyntheticTruth& truth, bool allow_loss, double clock_offset_s = 0) {
  // The same noise for a seed whatever standard library built the program (portable_random.hpp).
  PortableDraws<std::mt19937_64> rng(s.seed);
  std::vector<Reading> out;
  std::array<bool, 3> fast{false, false, false};
  truth.reports_sent = truth.dropped_reports = truth.repeated_reports = 0;
  truth.range_switches = truth.clipped_samples = 0;
  truth.received_stamps_s.clear();
  truth.written_fast.clear();
  const long reports = long(std::floor(end * s.rate_hz)) + 1;
  for (long n = 0; n < reports; ++n) {
    const double t = double(n) / s.rate_hz;
    const SyntheticSample x = at(t);
    Reading r{};
    r.t_s = t;
    r.stamp_s = 12.5 + clock_offset_s + t + s.latency_s + s.jitter_s * (2 * rng.unit() - 1);
    r.button = x.button;
    bool clipped = false;
    for (int i = 0; i < 3; ++i) {
      double a = x.accel_g[i];
      if (std::abs(a) > s.clip_g) clipped = true;
      a = std::clamp(a, -s.clip_g, s.clip_g) + s.accel_noise_g * rng.gauss();
      const double counts = s.accel_zero_counts[i] + a * (s.accel_one_g_counts[i] - s.accel_zero_counts[i]);
      r.accel_raw[i] = int(std::clamp(std::lround(counts), 0L, 1023L));
      const double w = x.rate_deg_s[i];
      const bool was = fast[i];
      if (!fast[i] && std::abs(w) > s.fast_above_deg_s) fast[i] = true;
      else if (fast[i] && std::abs(w) < s.slow_below_deg_s) fast[i] = false;
      if (fast[i] != was) ++truth.range_switches;
      r.slow[i] = !fast[i];
      const double scale = s.gyro_slow_counts_per_deg_s / (fast[i] ? s.gyro_fast_factor : 1.0);
      const double g = s.gyro_zero_counts[i] + (w + s.gyro_noise_deg_s * rng.gauss()) * scale;
      r.gyro_raw[i] = int(std::clamp(std::lround(g), 0L, 16383L));
    }
    truth.clipped_samples += clipped;
    ++truth.reports_sent;
    // Loss and repeats are drawn for every report so the same seed gives the same motion noise.
    const bool drop = rng.unit() < s.drop_probability && allow_loss && n > 0 && n + 1 < reports;  // a lost first or last report leaves no trace
    const bool repeat = rng.unit() < s.repeat_probability && allow_loss;
    const double repeat_delay_s = 2e-4 + 8e-4 * rng.unit();
    if (drop) {
      ++truth.dropped_reports;
      continue;
    }
    out.push_back(r);
    truth.received_stamps_s.push_back(r.stamp_s);
    if (repeat) {
      Reading again = r;
      again.repeated = true;
      again.stamp_s += repeat_delay_s;
      out.push_back(again);
      ++truth.repeated_reports;
    }
  }
  return out;
}

std::vector<Reading> record(const SyntheticThrow& th, const SyntheticSensor& s, SyntheticTruth& truth, bool allow_loss) {
  const auto out = sense([&th](double t) { return synthetic_sample(th, t); }, synthetic_duration_s(th), s, truth, allow_loss);
  // The truth at the release.
  const Geometry g = geometry(th);
  const double t_r = synthetic_release_time_s(th);
  truth.release_t_s = t_r;
  const Profile turn = profile(th, th.swing_rate_rad_s, t_r), pivot = profile(th, th.pivot_speed_m_s, t_r);
  RigidState st;
  st.velocity_m_s = pivot.rate * pivot_direction(th, g) + turn.rate * g.k.cross(g.lever_world_r);
  st.orientation = Quat(g.R_stone_r);
  const AttitudeAngles ang = attitude_angles(st);
  truth.speed_m_s = st.velocity_m_s.norm();
  truth.arm_speed_m_s = std::abs(turn.rate) * g.k.cross(g.lever_world_r).norm();
  truth.pivot_speed_m_s = std::abs(pivot.rate);
  truth.path_angle_deg = ang.path_angle_deg;
  truth.attack_angle_deg = ang.attack_angle_deg;
  truth.spin_rev_s = (g.R_stone_r.transpose() * (turn.rate * g.k)).z() / (2 * std::numbers::pi);
  truth.rise_m = synthetic_stone_position(th, t_r).z() - synthetic_stone_position(th, 0.0).z();
  truth.height_m = th.release_height_m;
  truth.finger_spin_rev_s = th.finger_spin_rev_s;
  truth.total_spin_rev_s = truth.spin_rev_s + (truth.spin_rev_s < 0 ? -1.0 : 1.0) * th.finger_spin_rev_s;
  truth.still_s = th.still_s;
  return out;
}
}  // namespace

double synthetic_release_time_s(const SyntheticThrow& th) { return th.still_s + th.swing_duration_s; }
double synthetic_duration_s(const SyntheticThrow& th) {
  return th.still_s + th.swing_duration_s + th.follow_through_s + th.after_s;
}

Vec3 synthetic_stone_position(const SyntheticThrow& th, double t) {
  const Geometry g = geometry(th);
  const Profile turn = profile(th, th.swing_rate_rad_s, t), pivot = profile(th, th.pivot_speed_m_s, t);
  return pivot.pos * pivot_direction(th, g) + Eigen::AngleAxisd(turn.pos, g.k) * g.lever_world_r - g.lever_world_r;
}

SyntheticThrow skipping_throw(const SkippingThrowSpec& spec) {
  SyntheticThrow th;
  th.mounting = spec.mounting;
  th.attack_angle_deg = spec.attack_angle_deg;
  th.path_angle_deg = spec.path_angle_deg;
  th.release_height_m = spec.release_height_m;
  th.swing_duration_s = spec.swing_duration_s;
  th.pivot_speed_m_s = spec.pivot_share * spec.speed_m_s;
  // |V d + Ω k × L| = speed for Ω (the positive root).
  const Geometry g = geometry(th);
  const Vec3 u = g.k.cross(g.lever_world_r);
  const double V = th.pivot_speed_m_s, du = g.d.dot(u), uu = u.squaredNorm();
  th.swing_rate_rad_s = (-V * du + std::sqrt(V * V * du * du - uu * (V * V - spec.speed_m_s * spec.speed_m_s))) / uu;
  const double arm_spin = std::abs((g.R_stone_r.transpose() * (th.swing_rate_rad_s * g.k)).z()) / (2 * std::numbers::pi);
  th.finger_spin_rev_s = std::max(0.0, spec.spin_rev_s - arm_spin);
  return th;
}

SyntheticSample synthetic_sample(const SyntheticThrow& th, double t) {
  const Geometry g = geometry(th);
  const Profile turn = profile(th, th.swing_rate_rad_s, t), pivot = profile(th, th.pivot_speed_m_s, t);
  const Mat3 rot = Eigen::AngleAxisd(turn.pos, g.k).toRotationMatrix();
  const Mat3 R_remote = rot * g.R_remote_r;
  const Vec3 rho = R_remote * (th.mounting.lever_arm_m - th.mounting.stone_offset_m);  // pivot → remote
  const Vec3 a = pivot.accel * pivot_direction(th, g) + turn.accel * g.k.cross(rho) + turn.rate * turn.rate * g.k.cross(g.k.cross(rho));
  SyntheticSample s;
  s.accel_g = R_remote.transpose() * (a + kG * Vec3::UnitZ()) / kG;  // specific force, in g
  s.rate_deg_s = R_remote.transpose() * (turn.rate * g.k) / kDeg;
  s.button = t >= th.press_at_s && t < synthetic_release_time_s(th);
  return s;
}

std::string synthetic_report_log(const SyntheticThrow& th, const SyntheticSensor& s, SyntheticTruth& truth) {
  const auto readings = record(th, s, truth, true);
  std::string out = "# stoneskip synthetic capture: raw report log (tools/capture/synthetic_capture.cpp)\n";
  // The calibration block as the remote returns it: a 0x21 reply to a 16-byte read at 0x0016.
  std::vector<std::uint8_t> reply{0x21, 0x00, 0x00, 0xf0, 0x00, 0x16};
  const auto block = encode_calibration_block(s.accel_zero_counts, s.accel_one_g_counts);
  reply.insert(reply.end(), block.begin(), block.end());
  reply.insert(reply.end(), {0x40, 0x00, 0x00, 0x00, 0x00, 0x00});
  char line[256];
  std::snprintf(line, sizeof line, "%.6f ", readings.front().stamp_s - 0.05);
  out += line + hex(reply) + "\n";
  for (const Reading& r : readings) {
    const auto bytes = encode_report(s.report_id, r.button ? kButtonB : 0u, r.accel_raw, r.gyro_raw, r.slow);
    std::snprintf(line, sizeof line, "%.6f ", r.stamp_s);
    out += line + hex(bytes) + "\n";
  }
  return out;
}

std::string synthetic_gesture(const SyntheticThrow& th, const SyntheticSensor& s, SyntheticTruth& truth) {
  const auto readings = record(th, s, truth, false);
  std::string out;
  char line[160];
  for (const Reading& r : readings) {
    if (!r.button) continue;
    truth.written_fast.push_back({!r.slow[0], !r.slow[1], !r.slow[2]});
    double a[3];
    for (int i = 0; i < 3; ++i)
      a[i] = double(r.accel_raw[i] - s.accel_zero_counts[i]) / double(s.accel_one_g_counts[i] - s.accel_zero_counts[i]);
    std::snprintf(line, sizeof line, "%.4f %.4f %.4f %d %d %d\n", a[0], a[1], a[2], r.gyro_raw[0], r.gyro_raw[1],
                  r.gyro_raw[2]);
    out += line;
  }
  return out;
}

std::string synthetic_evemu(const SyntheticThrow& th, const SyntheticSensor& s, SyntheticTruth& truth) {
  const auto readings = record(th, s, truth, true);
  char line[200];
  auto device = [&](const char* name, const char* product) {
    std::string h = std::string("# EVEMU 1.3\n# Input device name: \"") + name + "\"\nN: " + name + "\nI: 0005 057e " +
                    product + " 8001\n";
    return h;
  };
  auto event = [&](double t, int type, int code, long value) {
    const long us = std::lround(t * 1e6);
    std::snprintf(line, sizeof line, "E: %ld.%06ld %04x %04x %ld\n", us / 1000000, us % 1000000, type, code, value);
    return std::string(line);
  };
  std::string out = "# stoneskip synthetic capture: evemu-record of the three hid-wiimote devices, concatenated\n";
  std::snprintf(line, sizeof line, "# calibration.accel_zero_counts: %d,%d,%d\n# calibration.accel_one_g_counts: %d,%d,%d\n",
                s.accel_zero_counts[0], s.accel_zero_counts[1], s.accel_zero_counts[2], s.accel_one_g_counts[0],
                s.accel_one_g_counts[1], s.accel_one_g_counts[2]);
  out += line;
  out += device("Nintendo Wii Remote", "0306");
  bool down = false;
  for (const Reading& r : readings) {
    if (r.repeated || r.button == down) continue;
    down = r.button;
    out += event(r.stamp_s, 1, 0x131, down ? 1 : 0) + event(r.stamp_s, 0, 0, 0);
  }
  out += device("Nintendo Wii Remote Accelerometer", "0306");
  std::array<long, 3> last{-99999, -99999, -99999};
  for (const Reading& r : readings) {
    if (r.repeated) continue;  // a repeated report changes no value: the input core emits nothing
    std::string frame;
    for (int i = 0; i < 3; ++i) {
      const long v = r.accel_raw[i] - 0x200;
      if (v != last[i]) frame += event(r.stamp_s, 3, 3 + i, v);
      last[i] = v;
    }
    if (!frame.empty()) out += frame + event(r.stamp_s, 0, 0, 0);
  }
  out += device("Nintendo Wii Remote Motion Plus", "0306");
  last = {-99999999, -99999999, -99999999};
  for (const Reading& r : readings) {
    if (r.repeated) continue;
    std::string frame;
    // hid-wiimote-modules.c: ABS_RX yaw, ABS_RY roll, ABS_RZ pitch; x9 slow, x(2000*9)/440 fast.
    const int order[3] = {2, 1, 0};
    for (int c = 0; c < 3; ++c) {
      const int i = order[c];
      long v = r.gyro_raw[i] - 8192;
      v = r.slow[i] ? v * 9 : (v * 2000 * 9) / 440;
      if (v != last[c]) frame += event(r.stamp_s + 1e-6, 3, 3 + c, v);
      last[c] = v;
    }
    if (!frame.empty()) out += frame + event(r.stamp_s + 1e-6, 0, 0, 0);
  }
  return out;
}

std::string synthetic_wiiyourself_csv(const SyntheticThrow& th, const SyntheticSensor& s, const SyntheticSensor& idle,
                                      SyntheticTruth& truth) {
  // The thrower's reports, and those of a remote lying face up on the table, on its own clock.
  const auto thrower = record(th, s, truth, true);
  SyntheticTruth idle_counts;
  const auto table = sense([](double) { return SyntheticSample{Vec3::UnitZ(), Vec3::Zero(), false}; },
                           synthetic_duration_s(th), idle, idle_counts, true, 0.0037);
  // What WiiYourself! holds for a remote after a report (wiimote.cpp: ParseAccel uses the 8 high
  // bits and the 8-bit calibration; EstimateOrientationFrom updates pitch and roll only near 1 g;
  // ParseExtension converts the MotionPlus words; Button.Bits reads the two bytes little-endian).
  struct State {
    double pitch_deg = 0, roll_deg = 0;
    std::string fields;  // everything after the orientation, as written
  };
  auto update = [](State& st, const Reading& r, const SyntheticSensor& sensor) {
    double a[3];
    for (int i = 0; i < 3; ++i) {
      const int zero8 = sensor.accel_zero_counts[i] >> 2, one8 = sensor.accel_one_g_counts[i] >> 2;
      a[i] = double((r.accel_raw[i] >> 2) - zero8) / double(one8 - zero8);
    }
    const double len2 = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    if (std::abs(len2 - 1.0) <= 0.2) {
      const double inv = 1.0 / std::sqrt(len2);
      st.pitch_deg = -std::asin(std::clamp(a[1] * inv, -1.0, 1.0)) / kDeg;
      st.roll_deg = std::atan2(a[0] * inv, a[2] * inv) / kDeg;
    }
    // WiiYourself! order: yaw (Z), pitch (X), roll (Y).
    const int order[3] = {2, 0, 1};
    char b[256];
    int n = std::snprintf(b, sizeof b, "%f,%f,%f", a[0], a[1], a[2]);
    for (int i : order) n += std::snprintf(b + n, sizeof b - std::size_t(n), ",%04hx", (unsigned short)r.gyro_raw[i]);
    for (int i : order)
      n += std::snprintf(b + n, sizeof b - std::size_t(n), ",%8.3f",
                         -(r.gyro_raw[i] - 0x1F7F) * (r.slow[i] ? 0.05 : 0.25));
    std::snprintf(b + n, sizeof b - std::size_t(n), ",%04x", r.button ? 0x0400u : 0u);
    st.fields = b;
  };
  std::string out = "Sample,Time";
  for (int remote = 1; remote <= 2; ++remote)
    for (const char* c : {"Pitch", "Roll", "Acc X", "Acc Y", "Acc Z", "Raw Yaw", "Raw Pitch", "Raw Roll", "Speed Yaw",
                          "Speed Pitch", "Speed Roll", "Buttons"})
      out += std::string(",") + c + " #WM" + std::to_string(remote);
  out += "\n";
  // Both streams in host-time order; a row whenever a remote's state changes, once both reported.
  struct Event {
    double stamp_s;
    int remote;
    const Reading* r;
  };
  std::vector<Event> events;
  for (const Reading& r : thrower)
    if (!r.repeated) events.push_back({r.stamp_s, 1, &r});
  for (const Reading& r : table)
    if (!r.repeated) events.push_back({r.stamp_s, 2, &r});
  std::stable_sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.stamp_s < b.stamp_s; });
  State state[2];
  bool seen[2] = {false, false};
  constexpr long long kBootMs = 5234117;  // timeGetTime() counts from the host's boot
  long row = 0;
  char line[160];
  for (const Event& e : events) {
    State& st = state[e.remote - 1];
    const std::string before = st.fields;
    update(st, *e.r, e.remote == 1 ? s : idle);
    const bool changed = st.fields != before || !seen[e.remote - 1];
    seen[e.remote - 1] = true;
    if (!changed || !seen[0] || !seen[1]) continue;
    std::snprintf(line, sizeof line, "%ld,%lld", row++, kBootMs + std::llround(1e3 * e.stamp_s));
    out += line;
    for (const State& x : state) {
      std::snprintf(line, sizeof line, ",%f,%f,", x.pitch_deg, x.roll_deg);
      out += line + x.fields;
    }
    out += "\n";
  }
  truth.repeated_reports = 0;  // an unchanged report makes no row
  return out;
}

std::string SyntheticTruth::toml() const {
  char b[2048];
  std::snprintf(b, sizeof b,
                "# The truth behind a synthetic capture (tools/capture/synthetic_capture.cpp).\n"
                "# [throw]: the stone at release as the remote can measure it (spin about the stone's normal\n"
                "# from the arm; rise of the stone's centre since the still part). [stone]: the skipping stone\n"
                "# the throw stands for (height above the water; the fingers' spin, which no sensor sees).\n"
                "# arm_speed_m_s: the arm's turn about its pivot (what angular rate x lever arm can see);\n"
                "# pivot_speed_m_s: the pivot's own speed (the trunk's turn), the rest of the velocity.\n"
                "[throw]\nspeed_m_s = %.9g\npath_angle_deg = %.9g\nattack_angle_deg = %.9g\nspin_rev_s = %.9g\n"
                "rise_m = %.9g\nrelease_t_s = %.9g\narm_speed_m_s = %.9g\npivot_speed_m_s = %.9g\n\n[stone]\nheight_m = %.9g\nfinger_spin_rev_s = %.9g\n"
                "total_spin_rev_s = %.9g\n\n[recording]\nstill_s = %.9g\nreports_sent = %ld\ndropped_reports = %ld\n"
                "repeated_reports = %ld\nrange_switches = %d\nclipped_samples = %d\n",
                speed_m_s, path_angle_deg, attack_angle_deg, spin_rev_s, rise_m, release_t_s, arm_speed_m_s,
                pivot_speed_m_s, height_m, finger_spin_rev_s,
                total_spin_rev_s, still_s, reports_sent, dropped_reports, repeated_reports, range_switches,
                clipped_samples);
  return b;
}

}  // namespace stoneskip
