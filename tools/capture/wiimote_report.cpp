#include "tools/capture/wiimote_report.hpp"

namespace stoneskip {

namespace {
// Offsets (counting the id byte) of the accelerometer and extension bytes of each data report.
struct Layout {
  std::size_t size = 0;    // with the id byte
  int accel = -1;          // offset of AA AA AA, -1 if none
  int extension = -1;      // offset of the extension bytes, -1 if none
  int extension_bytes = 0;
  bool buttons = true;
};

Layout layout_of(std::uint8_t id) {
  switch (id) {
    case 0x30: return {3, -1, -1, 0, true};
    case 0x31: return {6, 3, -1, 0, true};
    case 0x32: return {11, -1, 3, 8, true};
    case 0x33: return {18, 3, -1, 0, true};
    case 0x34: return {22, -1, 3, 19, true};
    case 0x35: return {22, 3, 6, 16, true};
    case 0x36: return {22, -1, 13, 9, true};
    case 0x37: return {22, 3, 16, 6, true};
    case 0x3d: return {22, -1, 1, 21, false};
    default: return {};
  }
}

constexpr unsigned kAccelBitsInButtons = 0x6060;  // bits 5–6 of both button bytes
}  // namespace

std::size_t data_report_size(std::uint8_t id) { return layout_of(id).size; }

DecodedReport decode_report(const std::uint8_t* bytes, std::size_t size) {
  DecodedReport r;
  if (size >= 2 && bytes[0] == 0xa1) {  // HID DATA|INPUT transaction header
    ++bytes;
    --size;
  }
  if (size == 0) {
    r.length_ok = false;
    r.needed_bytes = 1;
    return r;
  }
  r.id = bytes[0];
  auto need = [&](std::size_t n) {
    r.needed_bytes = n;
    r.length_ok = size >= n;
    return r.length_ok;
  };
  auto read_buttons = [&] {
    r.has_buttons = true;
    r.buttons = ((unsigned(bytes[1]) << 8) | bytes[2]) & ~kAccelBitsInButtons;
  };
  switch (r.id) {
    case 0x20:
      r.kind = ReportKind::status;
      if (need(7)) read_buttons();
      return r;
    case 0x22:
      r.kind = ReportKind::acknowledge;
      if (need(5)) read_buttons();
      return r;
    case 0x21: {
      r.kind = ReportKind::memory_read;
      if (!need(22)) return r;
      read_buttons();
      const unsigned se = bytes[3];
      r.read_error = int(se & 0x0f);
      r.read_address = (unsigned(bytes[4]) << 8) | bytes[5];
      const std::size_t n = (se >> 4) + 1;
      r.read_data.assign(bytes + 6, bytes + 6 + n);
      return r;
    }
    default: break;
  }
  const Layout l = layout_of(r.id);
  if (l.size == 0) return r;  // unknown (including the interleaved 0x3e/0x3f)
  r.kind = ReportKind::data;
  if (!need(l.size)) return r;
  if (l.buttons) read_buttons();
  if (l.accel >= 0) {
    const unsigned b0 = bytes[1], b1 = bytes[2];
    r.has_accel = true;
    r.accel_raw[0] = int(bytes[l.accel] << 2 | ((b0 >> 5) & 3));      // model/README.md §4
    r.accel_raw[1] = int(bytes[l.accel + 1] << 2 | ((b1 >> 4) & 2));
    r.accel_raw[2] = int(bytes[l.accel + 2] << 2 | ((b1 >> 5) & 2));
  }
  if (l.extension >= 0 && l.extension_bytes >= 6) {
    const std::uint8_t* e = bytes + l.extension;
    if (e[5] & 0x02) {  // MotionPlus data, not a pass-through extension's
      r.has_motionplus = true;
      const int yaw = e[0] | ((e[3] >> 2) << 8);
      const int roll = e[1] | ((e[4] >> 2) << 8);
      const int pitch = e[2] | ((e[5] >> 2) << 8);
      r.gyro_raw = {pitch, roll, yaw};
      r.gyro_slow = {bool(e[3] & 0x01), bool(e[4] & 0x02), bool(e[3] & 0x02)};
    }
  }
  return r;
}

std::string one_g_spacing_problem(const std::array<double, 3>& zero, const std::array<double, 3>& one) {
  for (int i = 0; i < 3; ++i) {
    // Signed: the one-g point is the axis's reading with +1 g along it, above its zero-g point (the
    // ADXL330's output rises with acceleration along the axis, and the remote's EEPROM stores the
    // +1 g reading, wiibrew.org "Wiimote", Accelerometer calibration). One below zero would read
    // every acceleration on that axis with its sign flipped, and a capture so read still looks sound.
    const double s = one[i] - zero[i];
    if (s < 0) {
      char b[300];
      std::snprintf(b, sizeof b,
                    "the one-g count %g on %c is below its zero-g count %g: a remote's one-g point lies %g to %g counts "
                    "above zero-g (the +1 g reading), so this axis would read every acceleration with its sign flipped",
                    one[i], "XYZ"[i], zero[i], kMinOneGCounts, kMaxOneGCounts);
      return b;
    }
    if (s >= kMinOneGCounts && s <= kMaxOneGCounts) continue;
    char b[240];
    std::snprintf(b, sizeof b,
                  "one-g and zero-g counts are %g apart on %c (zero-g %g, one-g %g): a remote's 1 g is %g to %g "
                  "counts (its 10 bits span about ±3.5-4.6 g)",
                  s, "XYZ"[i], zero[i], one[i], kMinOneGCounts, kMaxOneGCounts);
    return b;
  }
  return "";
}

std::optional<CalibrationBlock> decode_calibration_block(const std::uint8_t* b, std::size_t size) {
  if (size < 10) return std::nullopt;
  CalibrationBlock c;
  c.zero_counts = {b[0] << 2 | ((b[3] >> 4) & 3), b[1] << 2 | ((b[3] >> 2) & 3), b[2] << 2 | (b[3] & 3)};
  c.one_g_counts = {b[4] << 2 | ((b[7] >> 4) & 3), b[5] << 2 | ((b[7] >> 2) & 3), b[6] << 2 | (b[7] & 3)};
  unsigned sum = 0x55;
  for (int i = 0; i < 9; ++i) sum += b[i];
  c.checksum_ok = (sum & 0xff) == b[9];
  return c;
}

std::array<std::uint8_t, 10> encode_calibration_block(const std::array<int, 3>& z, const std::array<int, 3>& g) {
  std::array<std::uint8_t, 10> b{};
  for (int i = 0; i < 3; ++i) {
    b[i] = std::uint8_t((z[i] >> 2) & 0xff);
    b[4 + i] = std::uint8_t((g[i] >> 2) & 0xff);
  }
  b[3] = std::uint8_t(((z[0] & 3) << 4) | ((z[1] & 3) << 2) | (z[2] & 3));
  b[7] = std::uint8_t(((g[0] & 3) << 4) | ((g[1] & 3) << 2) | (g[2] & 3));
  b[8] = 0;
  unsigned sum = 0x55;
  for (int i = 0; i < 9; ++i) sum += b[i];
  b[9] = std::uint8_t(sum & 0xff);
  return b;
}

std::vector<std::uint8_t> encode_report(std::uint8_t id, unsigned buttons, const std::array<int, 3>& a,
                                        const std::array<int, 3>& gyro_raw, const std::array<bool, 3>& gyro_slow) {
  const Layout l = layout_of(id);
  std::vector<std::uint8_t> r(l.size == 0 ? 1 : l.size, 0);
  r[0] = id;
  if (l.size == 0) return r;
  if (l.buttons) {
    r[1] = std::uint8_t((buttons >> 8) & 0x9f);
    r[2] = std::uint8_t(buttons & 0x9f);
  }
  if (l.accel >= 0) {
    r[1] |= std::uint8_t((a[0] & 3) << 5);
    r[2] |= std::uint8_t(((a[1] >> 1) & 1) << 5);  // only bit 1 of Y and Z is sent
    r[2] |= std::uint8_t(((a[2] >> 1) & 1) << 6);
    for (int i = 0; i < 3; ++i) r[l.accel + i] = std::uint8_t((a[i] >> 2) & 0xff);
  }
  // IR: 0xff = no object seen.
  const int ir_begin = l.accel >= 0 ? l.accel + 3 : 3;
  const int ir_end = l.extension >= 0 ? l.extension : int(l.size);
  for (int i = ir_begin; i < ir_end; ++i) r[i] = 0xff;
  if (l.extension >= 0 && l.extension_bytes >= 6) {
    std::uint8_t* e = r.data() + l.extension;
    const int pitch = gyro_raw[0] & 0x3fff, roll = gyro_raw[1] & 0x3fff, yaw = gyro_raw[2] & 0x3fff;
    e[0] = std::uint8_t(yaw & 0xff);
    e[1] = std::uint8_t(roll & 0xff);
    e[2] = std::uint8_t(pitch & 0xff);
    e[3] = std::uint8_t(((yaw >> 8) << 2) | (gyro_slow[2] ? 2 : 0) | (gyro_slow[0] ? 1 : 0));
    e[4] = std::uint8_t(((roll >> 8) << 2) | (gyro_slow[1] ? 2 : 0));
    e[5] = std::uint8_t(((pitch >> 8) << 2) | 0x02);
  }
  return r;
}

}  // namespace stoneskip
