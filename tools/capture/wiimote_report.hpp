#pragma once
// Decoding of Wii Remote Bluetooth HID input reports (model/README.md §4; WiiBrew "Wiimote" and
// Linux drivers/hid/hid-wiimote-core.c). A report is its id byte followed by its payload:
//   0x30 BB BB                      0x31 BB BB AA AA AA
//   0x32 BB BB E×8                  0x33 BB BB AA AA AA I×12
//   0x34 BB BB E×19                 0x35 BB BB AA AA AA E×16
//   0x36 BB BB I×10 E×9             0x37 BB BB AA AA AA I×10 E×6
//   0x3d E×21
//   0x20 status, 0x21 memory read reply (carries the calibration block), 0x22 acknowledge.
// Accelerometer (10 bits): X = AX<<2 | (b0>>5 & 3), Y = AY<<2 | (b1>>4 & 2), Z = AZ<<2 | (b1>>5 & 2).
// MotionPlus in extension bytes 0–5: yaw, roll, pitch, 14 bits each (low 8 in bytes 0–2, high 6 in
// bits 7–2 of bytes 3–5); slow-mode flags byte 3 bit 1 (yaw), byte 3 bit 0 (pitch), byte 4 bit 1
// (roll); byte 5 bit 1 set marks MotionPlus data (clear: a pass-through extension's data).
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "verification/captures/capture_trace.hpp"

namespace stoneskip {

enum class ReportKind { data, status, memory_read, acknowledge, unknown };

struct DecodedReport {
  ReportKind kind = ReportKind::unknown;
  std::uint8_t id = 0;
  bool length_ok = true;           // false: shorter than the report type needs (truncated)
  std::size_t needed_bytes = 0;    // with the id byte
  bool has_buttons = false;
  unsigned buttons = 0;            // (byte0 << 8) | byte1, accelerometer bits masked off
  bool has_accel = false;
  std::array<int, 3> accel_raw{};  // 10-bit counts X, Y, Z
  bool has_motionplus = false;
  std::array<int, 3> gyro_raw{};   // 14-bit counts about X (pitch), Y (roll), Z (yaw)
  std::array<bool, 3> gyro_slow{};  // slow-mode flags, same axis order
  // 0x21 memory read reply: address (low 16 bits) and data.
  unsigned read_address = 0;
  int read_error = 0;
  std::vector<std::uint8_t> read_data;
};

// Decodes one report (id first). A leading 0xa1 (the HID "input" transaction header) is skipped.
DecodedReport decode_report(const std::uint8_t* bytes, std::size_t size);

// The payload length (with the id byte) of a data report id 0x30–0x3f; 0 if not a data report.
std::size_t data_report_size(std::uint8_t id);

// The accelerometer calibration block (EEPROM 0x16–0x1f, copy at 0x20): zero-g X, Y, Z high
// bytes, their low bits (bits 5–4 X, 3–2 Y, 1–0 Z), one-g X, Y, Z, their low bits, one unused
// byte, checksum = (sum of the nine bytes + 0x55) mod 256.
struct CalibrationBlock {
  std::array<int, 3> zero_counts{};
  std::array<int, 3> one_g_counts{};
  bool checksum_ok = false;
};
std::optional<CalibrationBlock> decode_calibration_block(const std::uint8_t* bytes, std::size_t size);

// What is wrong with an accelerometer calibration whose one-g count lies below its zero-g count, or
// not kMinOneG..kMaxOneG above it, on some axis ("" when every axis is right). A 10-bit axis spans ±512 counts around its
// zero, so a 1 g of s counts reads ±512/s g: the ADXL330 is rated ±3 g and real remotes clip near
// ±3.5–4.6 g (spec §4), about 110–150 counts per g. Below 26 counts the axis would span ±20 g (the
// most a throw reaches, model/README.md §4), above 400 less than ±1.3 g (a still remote tilted
// would clip).
constexpr double kMinOneGCounts = 26, kMaxOneGCounts = 400;
std::string one_g_spacing_problem(const std::array<double, 3>& zero_counts, const std::array<double, 3>& one_g_counts);
std::array<std::uint8_t, 10> encode_calibration_block(const std::array<int, 3>& zero_counts,
                                                       const std::array<int, 3>& one_g_counts);

// Builds a report of type id (0x31, 0x33, 0x35 or 0x37) from raw values: the inverse of
// decode_report, used by the synthetic capture generator. gyro_raw/gyro_slow are written to the
// extension bytes (0x35, 0x37) with the MotionPlus marker bit; IR bytes are 0xff (no IR object).
std::vector<std::uint8_t> encode_report(std::uint8_t id, unsigned buttons, const std::array<int, 3>& accel_raw,
                                        const std::array<int, 3>& gyro_raw, const std::array<bool, 3>& gyro_slow);

}  // namespace stoneskip
