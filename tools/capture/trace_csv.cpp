#include "tools/capture/trace_csv.hpp"

#include <cmath>
#include <cstdio>
#include <set>

#include "tools/capture/capture_header.hpp"
#include "tools/capture/capture_text.hpp"
#include "tools/io/input_error.hpp"

namespace stoneskip {

namespace {
bool parse_bool(const std::string& v, bool& out) {
  if (v == "true" || v == "1") return out = true, true;
  if (v == "false" || v == "0") return out = false, true;
  return false;
}
}  // namespace

Trace read_trace_csv(const std::string& text, const std::string& file) {
  Trace t;
  t.source = file;
  t.format = "trace_csv";
  bool columns_seen = false, has_gyro_given = false;
  for (const TextLine& line : split_capture_lines(text, file)) {
    const std::string_view s = trim(line.text);
    if (s.empty()) continue;
    if (s.front() == '#') {
      // The format's line: this build reads its own version and no other.
      if (!columns_seen && s.rfind("# stoneskip trace", 0) == 0 && s != kTraceCsvMagic)
        throw_input_error(file, line.number, "",
                          "'" + std::string(s.substr(0, 60)) + "' is not a trace version this build reads (it reads '" +
                              kTraceCsvMagic + "')");
      std::string key, value;
      if (columns_seen || !header_comment(s, key, value)) continue;
      bool flag = false;
      static const std::set<std::string> own{"source", "timestamps", "gyro_mode", "has_gyro", "has_buttons", "has_accel"};
      if (own.count(key)) {
        // The trace's own keys, as the shared header keys (capture_header.cpp): a second value would
        // silently win ("has_gyro: true" then "false" made a capture unusable for want of a gyro).
        const auto [at, fresh] = t.header_key_lines.emplace(key, line.number);
        if (!fresh)
          throw_input_error(file, line.number, key, "given twice (first on line " + std::to_string(at->second) + "): keep one");
      }
      if (key == "source") {
        // informational
      } else if (key == "timestamps") {
        if (value != "host" && value != "nominal")
          throw_input_error(file, line.number, key, "expected 'host' or 'nominal'");
        t.nominal_timestamps = value == "nominal";
      } else if (key == "gyro_mode") {
        if (value != "flagged" && value != "inferred")
          throw_input_error(file, line.number, key, "expected 'flagged' or 'inferred'");
        t.gyro_mode_inferred = value == "inferred";
      } else if (key == "has_gyro" || key == "has_buttons" || key == "has_accel") {
        if (!parse_bool(value, flag)) throw_input_error(file, line.number, key, "expected true or false");
        (key == "has_gyro" ? t.has_gyro : key == "has_accel" ? t.has_accel : t.has_buttons) = flag;
        has_gyro_given = has_gyro_given || key == "has_gyro";
      } else if (!apply_header_key(t, key, value, file, line.number)) {
        refuse_misspelt_header_key(key, {"source", "timestamps", "gyro_mode", "has_gyro", "has_buttons", "has_accel"}, file,
                                   line.number);
      }
      continue;
    }
    if (!columns_seen) {
      if (s != kTraceCsvColumns)
        throw_input_error(file, line.number, "",
                          std::string("expected the column line '") + kTraceCsvColumns + "'");
      columns_seen = true;
      continue;
    }
    const auto f = split_fields(s, true);
    if (f.size() != 12) {
      malformed_line(file, line, "expected 12 comma-separated fields, found " + std::to_string(f.size()), t.warnings);
      continue;
    }
    TraceSample x;
    x.line = line.number;
    double v[10];
    bool ok = true;
    int bad = -1;
    for (int i = 0; i < 10 && ok; ++i) {
      const auto r = parse_real(f[i]);
      if (!r) ok = false, bad = i;
      else v[i] = *r;
    }
    if (!ok) {
      malformed_line(file, line, "field " + std::to_string(bad + 1) + " is not a number: '" + std::string(f[bad]) + "'",
                     t.warnings);
      continue;
    }
    x.t_s = v[0];
    x.accel_g = Eigen::Vector3d(v[1], v[2], v[3]);
    x.rate_deg_s = Eigen::Vector3d(v[4], v[5], v[6]);
    for (int i = 0; i < 3; ++i) {
      if (v[7 + i] != 0 && v[7 + i] != 1) {
        malformed_line(file, line, "fast_* must be 0 or 1", t.warnings);
        ok = false;
        break;
      }
      x.gyro_fast[i] = v[7 + i] == 1;
    }
    if (!ok) continue;
    const std::string_view bf = f[10];
    const auto buttons = (bf.size() > 2 && bf[0] == '0' && (bf[1] == 'x' || bf[1] == 'X'))
                             ? parse_integer(bf.substr(2), 16) : parse_integer(bf, 10);
    if (!buttons || *buttons < 0 || *buttons > 0xffff) {
      malformed_line(file, line, "buttons must be an integer 0..0xffff", t.warnings);
      continue;
    }
    x.buttons = unsigned(*buttons);
    if (!flags_from_string(std::string(f[11]), x.flags)) {
      malformed_line(file, line, "flags must be letters from XYZPRG or '-', got '" + std::string(f[11]) + "'", t.warnings);
      continue;
    }
    if (!t.samples.empty() && x.t_s < t.samples.back().t_s) {
      char what[200];  // both lines: an absurd time on the earlier one shows here as the later's fault
      std::snprintf(what, sizeof what, "time goes backwards (%.15g s after %.15g s on line %ld)", x.t_s,
                    t.samples.back().t_s, long(t.samples.back().line));
      throw_input_error(file, line.number, "t_s", what);
    }
    t.samples.push_back(x);
  }
  if (!columns_seen) throw_input_error(file, 0, "", "no column line: not a stoneskip trace");
  if (t.samples.empty()) throw_input_error(file, 0, "", "no samples");
  // "timestamps: nominal" says the times are the nominal rate's, k / nominal_rate_hz from the first
  // (as convert writes them, to the ns of its %.9f); a file so marked over other times had its
  // stamps analysed while its verdict said the nominal rate was assumed.
  if (t.nominal_timestamps) {
    const double period = 1.0 / t.nominal_rate_hz;
    for (std::size_t k = 1; k < t.samples.size(); ++k) {
      const double expected = t.samples.front().t_s + double(k) * period;
      if (std::abs(t.samples[k].t_s - expected) <= 2e-9 + 1e-12 * std::abs(expected)) continue;
      char what[300];
      std::snprintf(what, sizeof what,
                    "'# timestamps: nominal' says the times are k / nominal_rate_hz (%.6g Hz) from the first, but "
                    "this row's is %.9f s, not %.9f s: mark the file 'host', or give its nominal_rate_hz",
                    t.nominal_rate_hz, t.samples[k].t_s, expected);
      throw_input_error(file, t.samples[k].line, "", what);
    }
  }
  if (!has_gyro_given) {
    // No `has_gyro` line: the rate columns say whether a MotionPlus was there.
    for (const TraceSample& x : t.samples) t.has_gyro = t.has_gyro || x.rate_deg_s != Eigen::Vector3d::Zero();
    t.notes.push_back(std::string("no 'has_gyro' header line: ") +
                      (t.has_gyro ? "the rate columns hold non-zero rates, so a MotionPlus is taken as present"
                                  : "every rate is zero, so no MotionPlus is taken as present"));
  }
  return t;
}

std::string trace_csv_text(const Trace& t) {
  std::string s = std::string(kTraceCsvMagic) + "\n";
  s += "# source: " + t.source + " (" + t.format + ")\n";
  s += std::string("# timestamps: ") + (t.nominal_timestamps ? "nominal" : "host") + "\n";
  s += std::string("# has_accel: ") + (t.has_accel ? "true" : "false") + "\n";
  s += std::string("# has_gyro: ") + (t.has_gyro ? "true" : "false") + "\n";
  s += std::string("# has_buttons: ") + (t.has_buttons ? "true" : "false") + "\n";
  s += std::string("# gyro_mode: ") + (t.gyro_mode_inferred ? "inferred" : "flagged") + "\n";
  s += header_lines(t);
  s += kTraceCsvColumns;
  s += "\n";
  char row[512];
  for (const TraceSample& x : t.samples) {
    std::snprintf(row, sizeof row, "%.9f,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d,%d,%d,0x%04x,%s\n", x.t_s, x.accel_g.x(),
                  x.accel_g.y(), x.accel_g.z(), x.rate_deg_s.x(), x.rate_deg_s.y(), x.rate_deg_s.z(), int(x.gyro_fast[0]),
                  int(x.gyro_fast[1]), int(x.gyro_fast[2]), x.buttons, flags_to_string(x.flags).c_str());
    s += row;
  }
  return s;
}

}  // namespace stoneskip
