#include "tools/capture/capture_format.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <vector>

#include "tools/capture/capture_header.hpp"
#include "tools/capture/capture_text.hpp"
#include "tools/capture/capture_times.hpp"
#include "tools/capture/evemu_reader.hpp"
#include "tools/capture/gesture_reader.hpp"
#include "tools/capture/report_log.hpp"
#include "tools/capture/trace_csv.hpp"
#include "tools/io/atomic_file.hpp"
#include "tools/io/input_error.hpp"

namespace stoneskip {

const std::vector<std::string>& capture_format_names() {
  static const std::vector<std::string> names{"trace_csv", "report_log", "evemu", "gesture", "csv"};
  return names;
}

namespace {
bool is_hex(std::string_view f) {
  if (f.empty()) return false;
  for (char c : f)
    if (!std::isxdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

// A UTF-8 byte-order mark (Windows editors write one) is not part of the first line.
std::string without_bom(const std::string& text) {
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  return std::string_view(text).substr(0, kBom.size()) == kBom ? text.substr(kBom.size()) : text;
}

// Looks at up to the first 50 meaningful lines (lines as the readers split them: LF, CR LF or a
// lone CR).
std::string detect(const std::vector<TextLine>& lines) {
  int looked = 0;
  for (const TextLine& l : lines) {
    if (looked >= 50) break;
    const std::string_view line = trim(l.text);
    if (line.empty()) continue;
    if (line.rfind("# stoneskip trace", 0) == 0 || line.rfind("t_s,", 0) == 0) return "trace_csv";
    if (line.rfind("# EVEMU", 0) == 0 || line.rfind("N: ", 0) == 0 || line.rfind("E: ", 0) == 0) return "evemu";
    if (line.front() == '#') continue;
    ++looked;
    if (is_header_csv_column_line(std::string(line))) return "csv";
    const auto f = split_fields(line, false);
    if (f.size() == 6) {
      bool numbers = true;
      for (auto x : f) numbers = numbers && parse_real(x).has_value();
      if (numbers) return "gesture";
    }
    if (f.size() >= 2 && parse_real(f[0])) {
      bool hex = true;
      for (std::size_t i = 1; i < f.size(); ++i) hex = hex && is_hex(f[i]) && f[i].size() % 2 == 0;
      if (hex) {
        std::string_view first = f[1];
        if (first.size() >= 2 && (first.substr(0, 2) == "a1" || first.substr(0, 2) == "A1")) {
          first = first.size() > 2 ? first.substr(2) : (f.size() > 2 ? f[2] : std::string_view());
        }
        if (first.size() >= 2 && (first[0] == '2' || first[0] == '3')) return "report_log";
      }
    }
    return "";
  }
  return "";
}

// Times within kMaxDuration_s of the samples' median time (a file may stamp them in Unix time; the
// median, not the first, so that an absurd first time is the one named), readings within bounds
// no sensor reaches: the first sample outside is named by its line and quantity.
void check_sane(const Trace& t) {
  constexpr double kMaxDuration_s = kMaxCaptureTimeSpread_s, kMaxAccel_g = 1e3, kMaxRate_deg_s = 1e6;
  const double t0 = median_time_s(t);
  // A jump between neighbouring samples larger than a capture may span: of the two, the one
  // further from the median is named, with its neighbour (a file whose later half was shifted put
  // the median there, and the check below named the first sample, a good one). A single absurd
  // time followed by a sane one is caught earlier, by the readers' "time goes backwards", which
  // names both lines.
  const auto where = [&](std::size_t k) { return t.samples[k].line > 0 ? "line " + std::to_string(t.samples[k].line)
                                                                       : "sample " + std::to_string(k + 1); };
  for (std::size_t k = 1; k < t.samples.size(); ++k) {
    const double a = t.samples[k - 1].t_s, b = t.samples[k].t_s;
    if (!std::isfinite(a) || !std::isfinite(b) || std::abs(b - a) <= kMaxDuration_s) continue;
    const bool later = std::abs(b - t0) >= std::abs(a - t0);
    const std::size_t named = later ? k : k - 1, other = later ? k - 1 : k;
    char what[240];
    std::snprintf(what, sizeof what,
                  "time %.15g s is not within %g s of the neighbouring sample's time (%.15g s, %s): a capture spans "
                  "less, so one of the two is wrong",
                  t.samples[named].t_s, kMaxDuration_s, t.samples[other].t_s, where(other).c_str());
    const std::string sample = t.samples[named].line > 0 ? "" : "sample " + std::to_string(named + 1) + ": ";
    throw_input_error(t.source, t.samples[named].line, "", sample + what);
  }
  for (std::size_t k = 0; k < t.samples.size(); ++k) {
    const TraceSample& x = t.samples[k];
    char what[200] = "";
    if (!std::isfinite(x.t_s) || !(std::abs(x.t_s - t0) <= kMaxDuration_s))
      std::snprintf(what, sizeof what, "time %.15g s is not within %g s of the samples' median time (%.15g s)", x.t_s,
                    kMaxDuration_s, t0);
    else if (!x.accel_g.allFinite() || !(x.accel_g.cwiseAbs().maxCoeff() <= kMaxAccel_g))
      std::snprintf(what, sizeof what, "acceleration (%.6g, %.6g, %.6g) g exceeds %g g on an axis", x.accel_g.x(),
                    x.accel_g.y(), x.accel_g.z(), kMaxAccel_g);
    else if (!x.rate_deg_s.allFinite() || !(x.rate_deg_s.cwiseAbs().maxCoeff() <= kMaxRate_deg_s))
      std::snprintf(what, sizeof what, "angular rate (%.6g, %.6g, %.6g) deg/s exceeds %g deg/s on an axis",
                    x.rate_deg_s.x(), x.rate_deg_s.y(), x.rate_deg_s.z(), kMaxRate_deg_s);
    if (what[0] == 0) continue;
    const std::string sample = x.line > 0 ? "" : "sample " + std::to_string(k + 1) + ": ";
    throw_input_error(t.source, x.line, "", sample + what);
  }
}
}  // namespace

std::string detect_capture_format(const std::string& text) {
  try {
    return detect(split_capture_lines(without_bom(text), ""));
  } catch (const InputError&) {
    return "";  // binary data: no format
  }
}

Trace parse_capture(const std::string& file_text, const std::string& file, const CaptureReadOptions& o) {
  const std::string text = without_bom(file_text);
  std::string format = o.format;
  const bool csv_options = o.csv.remote != 0 || !o.csv.columns.empty();
  if (format.empty() || format == "auto") {
    // Binary data is reported as such (split_capture_lines throws), not as an unknown format.
    format = detect(split_capture_lines(text, file));
    if (format.empty() && !o.csv.columns.empty()) format = "csv";  // mapped columns: it is a CSV
    if (format.empty())
      throw_input_error(file, 0, "",
                        "unrecognised capture format (trace_csv, report_log, evemu, gesture, csv); use --format NAME "
                        "or --columns");
  }
  if (csv_options && format != "csv")
    throw_input_error(file, 0, o.csv.remote != 0 ? "--remote" : "--columns",
                      "applies to the csv format only (this file reads as " + format + ")");
  Trace t;
  if (format == "trace_csv") t = read_trace_csv(text, file);
  else if (format == "report_log") t = read_report_log(text, file);
  else if (format == "evemu") t = read_evemu(text, file);
  else if (format == "gesture") t = read_gesture(text, file);
  else if (format == "csv") t = read_header_csv(text, file, o.csv);
  else throw_input_error(file, 0, "--format", "unknown format '" + format + "' (trace_csv, report_log, evemu, gesture, csv)");
  refuse_half_calibration(t, file);
  check_sane(t);
  return t;
}

Trace parse_capture(const std::string& text, const std::string& file, const std::string& format) {
  CaptureReadOptions o;
  o.format = format;
  return parse_capture(text, file, o);
}

Trace read_capture(const std::string& path, const CaptureReadOptions& options) {
  return parse_capture(read_text_file(path), path, options);
}

Trace read_capture(const std::string& path, const std::string& format) {
  return parse_capture(read_text_file(path), path, format);
}

}  // namespace stoneskip
