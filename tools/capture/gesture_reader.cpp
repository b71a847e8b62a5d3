#include "tools/capture/gesture_reader.hpp"

#include "tools/capture/capture_header.hpp"
#include "tools/capture/capture_text.hpp"
#include "tools/capture/gyro_range.hpp"
#include "tools/io/input_error.hpp"

namespace stoneskip {

Trace read_gesture(const std::string& text, const std::string& file) {
  Trace t;
  t.source = file;
  t.format = "gesture";
  t.has_gyro = true;
  t.has_buttons = false;
  t.nominal_timestamps = true;
  t.gyro_mode_inferred = true;
  t.calibration.accel_from_device = true;  // the recorder wrote calibrated g
  std::vector<std::array<double, 3>> counts;
  for (const TextLine& line : split_capture_lines(text, file)) {
    const std::string_view s = trim(line.text);
    if (skip_blank_or_header(t, s, file, line.number)) continue;
    const auto f = split_fields(s, false);
    if (f.size() != 6) {
      malformed_line(file, line, "expected 6 numbers 'ax ay az pitch roll yaw', found " + std::to_string(f.size()) + " fields",
                     t.warnings);
      continue;
    }
    double v[6];
    int bad = -1;
    for (int i = 0; i < 6 && bad < 0; ++i) {
      const auto r = parse_real(f[i]);
      if (!r) bad = i;
      else v[i] = *r;
    }
    if (bad >= 0) {
      malformed_line(file, line, "field " + std::to_string(bad + 1) + " is not a number: '" + std::string(f[bad]) + "'",
                     t.warnings);
      continue;
    }
    bool in_range = true;
    for (int i = 3; i < 6; ++i) in_range = in_range && v[i] >= 0 && v[i] <= 16383 && v[i] == double(long(v[i]));
    if (!in_range) {
      malformed_line(file, line, "pitch roll yaw must be raw 14-bit counts (integers 0..16383)", t.warnings);
      continue;
    }
    TraceSample x;
    x.line = line.number;
    x.accel_g = Eigen::Vector3d(v[0], v[1], v[2]);
    x.buttons = kButtonB;  // the file spans the press of B
    // pitch → X, roll → Y, yaw → Z.
    for (int i = 0; i < 3; ++i) {
      x.rate_deg_s[i] = v[3 + i];  // raw for now
      if (v[3 + i] == 0 || v[3 + i] == 16383) x.flags |= kGyroSaturated;
    }
    t.samples.push_back(x);
    counts.push_back({v[3] - t.calibration.gyro_zero_counts[0], v[4] - t.calibration.gyro_zero_counts[1],
                      v[5] - t.calibration.gyro_zero_counts[2]});
  }
  if (t.samples.empty()) throw_input_error(file, 0, "", "no samples");
  const auto range = infer_gyro_range(counts, t.calibration.gyro_fast_factor);
  const double period = 1.0 / t.nominal_rate_hz;
  for (std::size_t k = 0; k < t.samples.size(); ++k) {
    TraceSample& x = t.samples[k];
    x.t_s = double(k) * period;
    x.gyro_fast = range.fast[k];
    for (int i = 0; i < 3; ++i) x.rate_deg_s[i] = t.calibration.gyro_deg_s(i, x.rate_deg_s[i], x.gyro_fast[i]);
  }
  return t;
}

}  // namespace stoneskip
