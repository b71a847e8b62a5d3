#pragma once
// stoneskip's own trace format (documented in tools/capture/README.md): a CSV file with a header
// of "# key: value" metadata (capture_header.hpp plus source, timestamps, has_gyro, has_buttons,
// gyro_mode), one column-name line, then one row per sample:
//
//   t_s,ax_g,ay_g,az_g,wx_deg_s,wy_deg_s,wz_deg_s,fast_x,fast_y,fast_z,buttons,flags
//
// fast_* are 0/1 (MotionPlus range mode), buttons the core button word (decimal or 0x hex),
// flags letters X Y Z (accelerometer axis saturated), P (gyro saturated), R (repeated report),
// G (reports lost before this one), H (the MotionPlus rate held over a silence) or '-'. Every reader's trace can be written out in this form.
#include <string>

#include "verification/captures/capture_trace.hpp"

namespace stoneskip {

inline constexpr const char* kTraceCsvMagic = "# stoneskip trace v1";
inline constexpr const char* kTraceCsvColumns =
    "t_s,ax_g,ay_g,az_g,wx_deg_s,wy_deg_s,wz_deg_s,fast_x,fast_y,fast_z,buttons,flags";

Trace read_trace_csv(const std::string& text, const std::string& file);
std::string trace_csv_text(const Trace& trace);

}  // namespace stoneskip
