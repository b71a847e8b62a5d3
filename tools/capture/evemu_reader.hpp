#pragma once
// Linux input-event recordings (evemu-record text format) of the devices that hid-wiimote creates
// for a Wii Remote (model/README.md §4; drivers/hid/hid-wiimote-modules.c):
//   "Nintendo Wii Remote"                 keys: BTN_A (0x130), BTN_B (0x131), ...
//   "Nintendo Wii Remote Accelerometer"   ABS_RX/RY/RZ = raw − 0x200 (X, Y, Z; uncalibrated)
//   "Nintendo Wii Remote Motion Plus"     ABS_RX = yaw, ABS_RY = roll, ABS_RZ = pitch, in
//                                         (raw − 8192)·9 slow-mode units (fast mode rescaled by
//                                         the driver by 2000/440; the mode is recovered from
//                                         the values: slow-mode ones are multiples of 9)
// evemu-record records one device per run: concatenate the three recordings into one file
// (each starts with its "N:" line). A sample is made at every SYN_REPORT of the accelerometer;
// the rate and the buttons are the latest ones at that time. Calibration: header comments
// (capture_header.hpp), else the nominal calibration with a warning.
#include <string>

#include "verification/captures/capture_trace.hpp"

namespace stoneskip {

Trace read_evemu(const std::string& text, const std::string& file);

}  // namespace stoneskip
