#pragma once
// The wiiuse gesture-recorder format: one file per press of B (press to release), one row per
// report of six whitespace-separated numbers,
//   ax ay az pitch roll yaw
// the acceleration in g and the raw 14-bit MotionPlus counts (0..16383). There are no
// timestamps and no range flags: samples are placed at the nominal rate (header
// "# nominal_rate_hz:", default 100 Hz; a warning says so), the button is taken as held on every
// row (the release is the file's end), and the range switches are inferred from the jumps
// (gyro_range.hpp).
#include <string>

#include "verification/captures/capture_trace.hpp"

namespace stoneskip {

Trace read_gesture(const std::string& text, const std::string& file);

}  // namespace stoneskip
