#pragma once
// Reading any capture: the format is recognised from the content (or forced by name), the right
// reader runs, and the resulting trace is checked for sane numbers.
//   trace_csv   stoneskip's own trace (trace_csv.hpp)
//   report_log  raw HID report log (report_log.hpp)
//   evemu       evemu-record text of hid-wiimote devices (evemu_reader.hpp)
//   gesture     wiiuse gesture-recorder rows (gesture_reader.hpp)
//   csv         any CSV with a column line, columns found by name (header_csv.hpp)
#include <string>
#include <vector>

#include "tools/capture/header_csv.hpp"
#include "verification/captures/capture_trace.hpp"

namespace stoneskip {

const std::vector<std::string>& capture_format_names();

// The format's name, or "" if none matches.
std::string detect_capture_format(const std::string& text);

struct CaptureReadOptions {
  std::string format;    // "" or "auto": recognised from the content
  HeaderCsvOptions csv;  // --remote and --columns (the csv format only)
};

// Parses text (format detected unless forced). Throws InputError naming the file.
Trace parse_capture(const std::string& text, const std::string& file, const CaptureReadOptions& options);
Trace parse_capture(const std::string& text, const std::string& file, const std::string& format = "");
// Reads the file and parses it.
Trace read_capture(const std::string& path, const CaptureReadOptions& options);
Trace read_capture(const std::string& path, const std::string& format = "");

}  // namespace stoneskip
