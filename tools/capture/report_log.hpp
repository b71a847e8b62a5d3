#pragma once
// A raw report log: one line per Bluetooth HID input report, the host time in seconds and then
// the report's bytes in hex, id first (an optional leading a1 HID header is skipped), either as
// separate bytes "31 00 00 80 80 9a" or run together "310000808099a" (documented in
// tools/capture/README.md). Header comments as capture_header.hpp; a 0x21 memory-read reply of
// address 0x0016 or 0x0020 in the log is taken as the calibration block.
//
// Reports 0x31, 0x33, 0x35, 0x37 give samples (0x35/0x37 with MotionPlus in the extension bytes);
// 0x20/0x21/0x22 are used or ignored; a report without accelerometer data, a truncated report and
// a report of an unknown type are skipped with a warning naming the line. A report byte-identical
// to the previous one and less than half a nominal period after it is flagged as repeated.
#include <string>

#include "verification/captures/capture_trace.hpp"

namespace stoneskip {

Trace read_report_log(const std::string& text, const std::string& file);

}  // namespace stoneskip
