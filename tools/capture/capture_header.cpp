#include "tools/capture/capture_header.hpp"

#include <cstdio>
#include <vector>

#include "tools/capture/capture_text.hpp"
#include "tools/capture/wiimote_report.hpp"
#include "tools/io/edit_distance.hpp"
#include "tools/io/input_error.hpp"
#include "verification/captures/mounting.hpp"
#include "verification/captures/virtual_thrower.hpp"

namespace stoneskip {

namespace {
std::array<double, 3> three(const std::string& value, const std::string& file, long line, const std::string& key) {
  const auto f = split_fields(value, true);
  if (f.size() != 3) throw_input_error(file, line, key, "expected three numbers x,y,z, got '" + value + "'");
  std::array<double, 3> out{};
  for (int i = 0; i < 3; ++i) {
    const auto x = parse_real(f[i]);
    if (!x) throw_input_error(file, line, key, "not a number: '" + std::string(f[i]) + "'");
    out[i] = *x;
  }
  return out;
}

// Counts a device can report (spec "Facts for the ingestion path"): the accelerometer's reading is
// 10 bits (0..1023), MotionPlus's 14 bits (0..16383). A calibration outside them came from no remote
// (a zero of 5e6 scaled every acceleration to nothing, and the capture was still called usable).
std::array<double, 3> counts(const std::string& value, const std::string& file, long line, const std::string& key,
                             int bits) {
  const auto v = three(value, file, line, key);
  const double top = double((1 << bits) - 1);
  for (double x : v)
    if (!(x >= 0 && x <= top))
      throw_input_error(file, line, key,
                        "each count must lie in 0.." + std::to_string(int(top)) + " (the device's " +
                            std::to_string(bits) + "-bit reading), got '" + value + "'");
  return v;
}

std::array<int, 3> signs(const std::string& value, const std::string& file, long line, const std::string& key) {
  const auto v = three(value, file, line, key);
  std::array<int, 3> s{};
  for (int i = 0; i < 3; ++i) {
    if (v[i] != 1 && v[i] != -1) throw_input_error(file, line, key, "each sign must be 1 or -1");
    s[i] = int(v[i]);
  }
  return s;
}

// A number in [low, high]; `why` says where the bounds come from.
double bounded(const std::string& value, double low, double high, const char* why, const std::string& file, long line,
               const std::string& key) {
  const auto x = parse_real(value);
  if (!x) throw_input_error(file, line, key, "expected a positive number, got '" + value + "'");
  if (!(*x >= low && *x <= high)) {
    char b[96];
    std::snprintf(b, sizeof b, "must be in [%g, %g] (got ", low, high);
    throw_input_error(file, line, key, b + value + "): " + why);
  }
  return *x;
}

std::string join3(const std::array<double, 3>& v) {
  char b[160];
  std::snprintf(b, sizeof b, "%.10g,%.10g,%.10g", v[0], v[1], v[2]);
  return b;
}
std::string join3(const std::array<int, 3>& v) {
  char b[64];
  std::snprintf(b, sizeof b, "%d,%d,%d", v[0], v[1], v[2]);
  return b;
}
}  // namespace

namespace {

bool apply_header_value(Trace& t, const std::string& key, const std::string& value, const std::string& file, long line);

}  // namespace

bool apply_header_key(Trace& t, const std::string& key, const std::string& value, const std::string& file,
                      long line) {
  if (!apply_header_value(t, key, value, file, line)) return false;
  // A key given twice: the last one silently won, and a second calibration line turned a capture's
  // verdict from usable to unusable. Which one holds is not for the reader to guess.
  const auto [at, fresh] = t.header_key_lines.emplace(key, line);
  if (!fresh)
    throw_input_error(file, line, key, "given twice (first on line " + std::to_string(at->second) + "): keep one");
  return true;
}

namespace {

bool apply_header_value(Trace& t, const std::string& key, const std::string& value, const std::string& file, long line) {
  CaptureCalibration& c = t.calibration;
  if (key == "nominal_rate_hz") {
    t.nominal_rate_hz = bounded(value, 1, 1000, "a Wii Remote reports at up to about 100 Hz (tools/capture/README.md); 1000 leaves room for any logger", file, line, key);
    return true;
  }
  if (key.rfind("mounting.", 0) == 0) {
    Mounting probe;  // validate now, so the error names the line
    const std::string setting = key.substr(9) + "=" + value;
    apply_mounting_setting(probe, setting, input_location(file, line, ""));
    t.mounting.push_back(setting);
    return true;
  }
  if (key.rfind("thrower.", 0) == 0) {
    VirtualThrowerOptions probe;  // validate now, so the error names the line
    const std::string setting = key.substr(8) + "=" + value;
    apply_thrower_setting(probe, setting, input_location(file, line, ""));
    t.thrower.push_back(setting);
    return true;
  }
  if (key.rfind("calibration.", 0) != 0) return false;
  const std::string k = key.substr(12);
  // The block and the two count lines say the same thing twice: the later silently overrode the
  // earlier. Which one holds is not for the reader to guess.
  const bool block_key = k == "block", count_key = k == "accel_zero_counts" || k == "accel_one_g_counts";
  for (const char* other : {"calibration.block", "calibration.accel_zero_counts", "calibration.accel_one_g_counts"}) {
    const std::string o = other;
    const bool other_is_block = o == "calibration.block";
    const auto at = t.header_key_lines.find(o);
    if (at != t.header_key_lines.end() && ((block_key && !other_is_block) || (count_key && other_is_block)))
      throw_input_error(file, line, key,
                        "conflicts with " + o + " on line " + std::to_string(at->second) +
                            ": give the calibration block or the two count lines, not both");
  }
  if (k == "block") {
    std::vector<std::uint8_t> bytes;
    for (auto f : split_fields(value, false)) {
      const auto b = parse_integer(f, 16);
      if (!b || *b < 0 || *b > 255 || f.size() > 2) throw_input_error(file, line, key, "expected 10 hex bytes");
      bytes.push_back(std::uint8_t(*b));
    }
    const auto block = decode_calibration_block(bytes.data(), bytes.size());
    if (bytes.size() != 10 || !block) throw_input_error(file, line, key, "expected 10 hex bytes (EEPROM 0x16-0x1f)");
    if (!block->checksum_ok)
      t.warnings.push_back(input_location(file, line, key) + ": calibration block checksum does not match; used anyway");
    for (int i = 0; i < 3; ++i) {
      c.accel_zero_counts[i] = block->zero_counts[i];
      c.accel_one_g_counts[i] = block->one_g_counts[i];
    }
    c.accel_from_device = c.accel_from_header = true;
  } else if (k == "accel_zero_counts") {
    c.accel_zero_counts = counts(value, file, line, key, 10);
    c.accel_from_device = c.accel_from_header = true;
  } else if (k == "accel_one_g_counts") {
    c.accel_one_g_counts = counts(value, file, line, key, 10);
    c.accel_from_device = c.accel_from_header = true;
  } else if (k == "accel_sign") {
    c.accel_sign = signs(value, file, line, key);
  } else if (k == "gyro_zero_counts") {
    c.gyro_zero_counts = counts(value, file, line, key, 14);
  } else if (k == "gyro_slow_counts_per_deg_s") {
    c.gyro_slow_counts_per_deg_s =
        bounded(value, 2, 200, "10 times either way of the MotionPlus's 20 (a slow range of 41 to 4096 deg/s)", file, line, key);
  } else if (k == "gyro_fast_factor") {
    c.gyro_fast_factor = bounded(value, 1, 50,
                                 "fast mode is coarser than slow (2000/440 on the MotionPlus, Linux hid-wiimote), "
                                 "up to about 11 times that",
                                 file, line, key);
  } else if (k == "gyro_sign") {
    c.gyro_sign = signs(value, file, line, key);
  } else {
    throw_input_error(file, line, key, "unknown calibration key");
  }
  // The two count lines are one calibration: checked when the second arrives, whichever comes
  // first (against the nominal half they would pass or fail by the order of the lines).
  const bool both_counts =
      block_key || (count_key && t.header_key_lines.count(k == "accel_zero_counts" ? "calibration.accel_one_g_counts"
                                                                                   : "calibration.accel_zero_counts"));
  if (both_counts)
    if (const std::string problem = one_g_spacing_problem(c.accel_zero_counts, c.accel_one_g_counts); !problem.empty())
      throw_input_error(file, line, key, problem);
  return true;
}

}  // namespace

void refuse_half_calibration(const Trace& t, const std::string& file) {
  const auto zero = t.header_key_lines.find("calibration.accel_zero_counts");
  const auto one = t.header_key_lines.find("calibration.accel_one_g_counts");
  if ((zero == t.header_key_lines.end()) == (one == t.header_key_lines.end())) return;
  const auto& given = zero != t.header_key_lines.end() ? *zero : *one;
  const char* missing = zero != t.header_key_lines.end() ? "calibration.accel_one_g_counts" : "calibration.accel_zero_counts";
  throw_input_error(file, given.second, given.first,
                    std::string("is given without ") + missing +
                        ": the accelerometer's calibration is both lines (or calibration.block), not half of one");
}

std::string header_lines(const Trace& t) {
  const CaptureCalibration& c = t.calibration;
  std::string s;
  char b[64];
  std::snprintf(b, sizeof b, "%.10g", t.nominal_rate_hz);
  s += std::string("# nominal_rate_hz: ") + b + "\n";
  if (c.accel_from_device) {  // the nominal calibration is not written: it would read back as measured
    s += "# calibration.accel_zero_counts: " + join3(c.accel_zero_counts) + "\n";
    s += "# calibration.accel_one_g_counts: " + join3(c.accel_one_g_counts) + "\n";
  }
  s += "# calibration.accel_sign: " + join3(c.accel_sign) + "\n";
  s += "# calibration.gyro_zero_counts: " + join3(c.gyro_zero_counts) + "\n";
  std::snprintf(b, sizeof b, "%.10g", c.gyro_slow_counts_per_deg_s);
  s += std::string("# calibration.gyro_slow_counts_per_deg_s: ") + b + "\n";
  std::snprintf(b, sizeof b, "%.10g", c.gyro_fast_factor);
  s += std::string("# calibration.gyro_fast_factor: ") + b + "\n";
  s += "# calibration.gyro_sign: " + join3(c.gyro_sign) + "\n";
  for (const auto& m : t.mounting) {
    const auto eq = m.find('=');
    s += "# mounting." + m.substr(0, eq) + ": " + m.substr(eq + 1) + "\n";
  }
  for (const auto& m : t.thrower) {
    const auto eq = m.find('=');
    s += "# thrower." + m.substr(0, eq) + ": " + m.substr(eq + 1) + "\n";
  }
  return s;
}

void refuse_misspelt_header_key(const std::string& key, const std::vector<std::string>& more_keys, const std::string& file,
                                long line) {
  std::vector<std::string> known{"nominal_rate_hz"};
  known.insert(known.end(), more_keys.begin(), more_keys.end());
  const auto dot = key.find('.');
  for (const std::string& k : known)
    if (looks_misspelt(key, k))
      throw_input_error(file, line, key,
                        "not a header key: a misspelling of '" + k +
                            "'? (a comment that is no key must not read '# word: …' so close to one)");
  if (dot != std::string::npos)
    for (const char* prefix : {"calibration", "mounting", "thrower"})
      if (looks_misspelt(key.substr(0, dot), prefix))
        throw_input_error(file, line, key,
                          std::string("not a header key: a misspelling of '") + prefix + "." + key.substr(dot + 1) + "'?");
}

bool skip_blank_or_header(Trace& trace, std::string_view trimmed_line, const std::string& file, long line) {
  if (trimmed_line.empty()) return true;
  if (trimmed_line.front() != '#') return false;
  std::string key, value;
  if (header_comment(trimmed_line, key, value) && !apply_header_key(trace, key, value, file, line))
    refuse_misspelt_header_key(key, {}, file, line);
  return true;
}

}  // namespace stoneskip
