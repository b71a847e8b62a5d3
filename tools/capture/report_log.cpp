#include "tools/capture/report_log.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "tools/capture/capture_header.hpp"
#include "tools/capture/capture_text.hpp"
#include "tools/capture/capture_times.hpp"
#include "tools/capture/wiimote_report.hpp"
#include "tools/io/input_error.hpp"

namespace stoneskip {

namespace {
int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// Hex tokens → bytes; false if a token is not an even-length run of hex digits.
bool parse_hex_bytes(const std::vector<std::string_view>& fields, std::size_t first, std::vector<std::uint8_t>& out) {
  out.clear();
  for (std::size_t k = first; k < fields.size(); ++k) {
    const std::string_view f = fields[k];
    if (f.size() % 2 != 0) return false;
    for (std::size_t i = 0; i < f.size(); i += 2) {
      const int hi = hex_digit(f[i]), lo = hex_digit(f[i + 1]);
      if (hi < 0 || lo < 0) return false;
      out.push_back(std::uint8_t(hi * 16 + lo));
    }
  }
  return true;
}

char hex_id(std::uint8_t id, char* buf) {
  std::snprintf(buf, 8, "0x%02x", id);
  return 0;
}

// Whether a block's accelerometer counts are those a calibration holds.
bool same_counts(const CalibrationBlock& b, const CaptureCalibration& c) {
  for (int i = 0; i < 3; ++i)
    if (b.zero_counts[i] != c.accel_zero_counts[i] || b.one_g_counts[i] != c.accel_one_g_counts[i]) return false;
  return true;
}
bool same_counts(const CalibrationBlock& a, const CalibrationBlock& b) {
  return a.zero_counts == b.zero_counts && a.one_g_counts == b.one_g_counts;
}

std::string block_counts(const CalibrationBlock& b) {
  char s[96];
  std::snprintf(s, sizeof s, "zero-g %d,%d,%d, one-g %d,%d,%d", b.zero_counts[0], b.zero_counts[1], b.zero_counts[2],
                b.one_g_counts[0], b.one_g_counts[1], b.one_g_counts[2]);
  return s;
}

// A 0x21 calibration reply seen in the log, and its line.
struct SeenBlock {
  std::optional<CalibrationBlock> block;
  long line = 0;
};

// Repeats: the same bytes as the previous report less than half the file's typical interval later
// (the median over reports that differ from their predecessor, which no repeat is); half the
// nominal period where there is no such interval. Against the nominal 100 Hz, identical reports of
// a remote still at 200 Hz were taken for repeats.
void flag_repeats(Trace& t, const std::vector<char>& same_as_previous, const std::vector<double>& since_previous_s) {
  std::vector<double> intervals;
  for (std::size_t k = 0; k < t.samples.size(); ++k)
    if (!same_as_previous[k] && since_previous_s[k] > 0) intervals.push_back(since_previous_s[k]);
  double typical_s = 1.0 / t.nominal_rate_hz;
  if (!intervals.empty()) {
    std::nth_element(intervals.begin(), intervals.begin() + intervals.size() / 2, intervals.end());
    typical_s = intervals[intervals.size() / 2];
  }
  for (std::size_t k = 0; k < t.samples.size(); ++k)
    if (same_as_previous[k] && since_previous_s[k] < 0.5 * typical_s) t.samples[k].flags |= kRepeated;
}

// The remote's calibration block, once the whole file is read. The header's calibration (wherever
// its lines stand) wins, and a block that disagrees is said to. Otherwise the block is the
// calibration: one remote has one, so the same block read again is fine, and a different one (two
// remotes in one log, or a corrupt read) cannot be applied to every sample: refused, naming both;
// and a block whose one-g lies no remote's distance from its zero-g is refused (where the header
// states the calibration, such a block is only not used).
void apply_device_block(Trace& t, const SeenBlock& first, const SeenBlock& differing, const std::string& file) {
  if (!first.block) return;
  CaptureCalibration& c = t.calibration;
  if (c.accel_from_header) {
    for (const SeenBlock* b : {&first, &differing})
      if (b->block && !same_counts(*b->block, c))
        t.warnings.push_back(input_location(file, b->line, "") + ": the remote's calibration block (" +
                             block_counts(*b->block) + ") differs from the header's calibration; the header's is used");
    return;
  }
  if (differing.block)
    throw_input_error(file, differing.line, "",
                      "a second calibration block differs from the one on line " + std::to_string(first.line) + " (" +
                          block_counts(*first.block) + " against " + block_counts(*differing.block) +
                          "): one remote has one calibration; keep the right one");
  const CalibrationBlock& b = *first.block;
  const std::array<double, 3> zero{double(b.zero_counts[0]), double(b.zero_counts[1]), double(b.zero_counts[2])},
      one{double(b.one_g_counts[0]), double(b.one_g_counts[1]), double(b.one_g_counts[2])};
  if (const std::string problem = one_g_spacing_problem(zero, one); !problem.empty())
    throw_input_error(file, first.line, "", "calibration block: " + problem);  // the block is all there is
  if (!b.checksum_ok)
    t.warnings.push_back(input_location(file, first.line, "") + ": calibration block checksum does not match; used anyway");
  for (int i = 0; i < 3; ++i) {
    c.accel_zero_counts[i] = first.block->zero_counts[i];
    c.accel_one_g_counts[i] = first.block->one_g_counts[i];
  }
  c.accel_from_device = true;
}

// Counts → g and deg/s. Samples without MotionPlus data hold the previous rate; returns how many.
long calibrate_samples(Trace& t, const std::vector<char>& sample_has_gyro) {
  const CaptureCalibration& c = t.calibration;
  Eigen::Vector3d last_rate = Eigen::Vector3d::Zero();
  std::array<bool, 3> last_fast{};
  long without_gyro = 0;
  for (std::size_t k = 0; k < t.samples.size(); ++k) {
    TraceSample& x = t.samples[k];
    for (int i = 0; i < 3; ++i) x.accel_g[i] = c.accel_g_from_report(i, x.accel_g[i]);
    if (!t.has_gyro) continue;
    if (sample_has_gyro[k]) {
      for (int i = 0; i < 3; ++i) x.rate_deg_s[i] = c.gyro_deg_s(i, x.rate_deg_s[i], x.gyro_fast[i]);
      last_rate = x.rate_deg_s;
      last_fast = x.gyro_fast;
    } else {
      ++without_gyro;
      x.rate_deg_s = last_rate;
      x.gyro_fast = last_fast;
    }
  }
  return without_gyro;
}
}  // namespace

Trace read_report_log(const std::string& text, const std::string& file) {
  Trace t;
  t.source = file;
  t.format = "report_log";
  std::vector<std::uint8_t> bytes, previous;
  double previous_time = 0;
  long previous_time_line = 0;
  bool have_time = false;
  long without_accel = 0;
  // Reports longer than any the remote sends (22 bytes with the id; a logger may pad shorter ones
  // up to that, and may prefix the HID header 0xa1): the bytes past 22 are not the remote's.
  constexpr std::size_t kLongestReport = 22;
  long overlong = 0;
  std::size_t first_overlong_line = 0;
  std::vector<char> sample_has_gyro;
  std::vector<char> same_as_previous;     // per sample: its bytes are the previous data report's
  std::vector<double> since_previous_s;   // per sample: host time since the previous data report
  SeenBlock device_block;     // the first 0x21 calibration reply, applied after the scan
  SeenBlock differing_block;  // the first later one that differs from it
  for (const TextLine& line : split_capture_lines(text, file)) {
    const std::string_view s = trim(line.text);
    if (skip_blank_or_header(t, s, file, line.number)) continue;
    const auto fields = split_fields(s, false);
    const auto time = parse_real(fields[0]);
    if (!time) {
      malformed_line(file, line, "the first field must be the host time in seconds, got '" + std::string(fields[0]) + "'",
                     t.warnings);
      continue;
    }
    if (!parse_hex_bytes(fields, 1, bytes)) {
      malformed_line(file, line, "report bytes must be hex (pairs of digits 0-9a-f)", t.warnings);
      continue;
    }
    if (bytes.empty()) {
      malformed_line(file, line, "no report bytes after the time", t.warnings);
      continue;
    }
    if (have_time && *time < previous_time) {
      char what[200];  // both lines: an absurd time on the earlier one shows here as the later's fault
      std::snprintf(what, sizeof what, "time goes backwards (%.15g s after %.15g s on line %ld)", *time, previous_time,
                    previous_time_line);
      throw_input_error(file, line.number, "", what);
    }
    const DecodedReport r = decode_report(bytes.data(), bytes.size());
    char id[8];
    hex_id(r.id, id);
    if (!r.length_ok) {
      t.warnings.push_back(input_location(file, line.number, "") + ": truncated report " + id + " (" +
                           std::to_string(bytes.size()) + " bytes, needs " + std::to_string(r.needed_bytes) +
                           "): skipped");
      continue;
    }
    if (bytes.size() - (bytes[0] == 0xa1 ? 1 : 0) > kLongestReport && overlong++ == 0) first_overlong_line = line.number;
    if (r.kind == ReportKind::unknown) {
      t.warnings.push_back(input_location(file, line.number, "") + ": unknown report type " + id + ": skipped");
      continue;
    }
    if (r.kind == ReportKind::memory_read) {
      if (r.read_error == 0 && (r.read_address == 0x0016 || r.read_address == 0x0020) && r.read_data.size() >= 10) {
        const auto block = decode_calibration_block(r.read_data.data(), r.read_data.size());
        if (!device_block.block) device_block = {*block, line.number};
        else if (!differing_block.block && !same_counts(*device_block.block, *block)) differing_block = {*block, line.number};
      }
      continue;
    }
    if (r.kind != ReportKind::data) continue;  // status, acknowledge
    if (!r.has_accel) {
      ++without_accel;
      continue;
    }
    TraceSample x;
    x.line = line.number;
    x.t_s = *time;  // from the first sample's once all are read (below)
    x.buttons = r.buttons;
    for (int i = 0; i < 3; ++i) x.accel_g[i] = r.accel_raw[i];  // calibrated below (the block may come later)
    if (r.has_motionplus) {
      t.has_gyro = true;
      for (int i = 0; i < 3; ++i) {
        x.gyro_fast[i] = !r.gyro_slow[i];
        x.rate_deg_s[i] = r.gyro_raw[i];  // scaled below
        if (r.gyro_raw[i] == 0 || r.gyro_raw[i] == 0x3fff) x.flags |= kGyroSaturated;
      }
    }
    // A repeat (the same report logged twice) is decided after the scan (flag_repeats).
    same_as_previous.push_back(have_time && bytes == previous);
    since_previous_s.push_back(have_time ? *time - previous_time : 0.0);
    previous = bytes;
    previous_time = *time;
    previous_time_line = line.number;
    have_time = true;
    t.samples.push_back(x);
    sample_has_gyro.push_back(r.has_motionplus);
  }
  if (t.samples.empty()) throw_input_error(file, 0, "", "no accelerometer reports (0x31, 0x33, 0x35, 0x37) found");
  count_times_from_first(t);  // capture_times.hpp
  flag_repeats(t, same_as_previous, since_previous_s);
  apply_device_block(t, device_block, differing_block, file);
  const long without_gyro = calibrate_samples(t, sample_has_gyro);
  if (overlong > 0)
    t.warnings.push_back(input_location(file, first_overlong_line, "") + ": " + std::to_string(overlong) +
                         (overlong == 1 ? " report is" : " reports are") + " longer than " +
                         std::to_string(kLongestReport) +
                         " bytes, the longest a Wii Remote sends (this line is the first): the bytes past " +
                         std::to_string(kLongestReport) + " were ignored");
  if (without_accel > 0)
    t.warnings.push_back(file + ": " + std::to_string(without_accel) + " reports without accelerometer data skipped");
  if (without_gyro > 0)
    t.warnings.push_back(file + ": " + std::to_string(without_gyro) +
                         " accelerometer reports without MotionPlus data: the previous rate was held");
  return t;
}

}  // namespace stoneskip
