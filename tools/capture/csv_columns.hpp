#pragma once
// The column names the header-driven CSV reader (header_csv.hpp) recognises, and how a header
// field is normalised before it is looked up (tools/capture/README.md, "Header-driven CSV"):
//   1. a device suffix "#WM2", "#wm 2" or "#2" at the end gives the remote's number;
//   2. a unit in brackets or parentheses at the end ("[g]", "(ms)", "[deg/s]") is the unit;
//   3. the rest is split into lowercase words at spaces, '_', '.', '-', '/', ':' and camelCase
//      boundaries ("AccX" → "acc x", "MotionPlus.Speed.Yaw" → "motionplus speed yaw");
//   4. the words are looked up in the table; if they are not found and no bracketed unit was given,
//      trailing unit words are tried as the unit ("t_s" → "t" in s, "wx_deg_s" → "wx" in deg/s).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace stoneskip {

// What a column holds. Axes: X pitch, Y roll, Z yaw (capture_trace.hpp).
enum class CsvField {
  time,                                  // host time
  sequence,                              // a row or sample number (read, not used)
  ax, ay, az,                            // specific force, remote frame
  wx, wy, wz,                            // angular rate, right-handed about X, Y, Z (stoneskip's sign)
  speed_pitch, speed_roll, speed_yaw,    // WiiYourself! MotionPlus.Speed: −(raw − 0x1F7F)·scale
  raw_pitch, raw_roll, raw_yaw,          // MotionPlus raw 14-bit words
  slow_pitch, slow_roll, slow_yaw,       // MotionPlus slow-mode flag (1 slow)
  fast_pitch, fast_roll, fast_yaw,       // MotionPlus fast-mode flag (1 fast)
  buttons,                               // WiiYourself! Button.Bits word (B 0x0400, A 0x0800)
  button_a, button_b,                    // one button, 0/1
  orientation_pitch, orientation_roll,   // the accelerometer's pitch and roll (read, not used)
};
constexpr int kCsvFieldCount = int(CsvField::orientation_roll) + 1;

enum class CsvUnit { none, s, ms, us, g, m_s2, deg_s, rad_s, deg, hex, dec };
const char* to_string(CsvUnit u);

struct CsvFieldInfo {
  CsvField field;
  const char* key;          // the --columns key: t, ax, raw_yaw, ...
  const char* meaning;      // for the table in the README and error messages
  std::vector<CsvUnit> units;  // allowed units, the first is the default (none: no unit)
};
const std::vector<CsvFieldInfo>& csv_fields();
const CsvFieldInfo& csv_field_info(CsvField f);
// Every recognised name (normalised words) of a field, for the README's table.
std::vector<std::string> csv_field_names(CsvField f);

struct RecognisedColumn {
  CsvField field = CsvField::time;
  int remote = 0;             // 0: no device suffix (shared by every remote)
  CsvUnit unit = CsvUnit::none;  // none: not given (the field's default applies)
};

// A header field taken apart: its device number (0: no suffix), its bracketed unit text ("" when
// none) and the rest (the name as written, trimmed, without quotes).
struct HeaderParts {
  int remote = 0;
  std::string unit_text;
  bool has_bracket_unit = false;
  std::string name;
};
HeaderParts split_header(std::string_view header);

// Recognises a header field; nullopt when its name is not in the table. Throws nothing: a unit
// that the field does not allow is reported by unit_allowed.
std::optional<RecognisedColumn> recognise_column(std::string_view header);
bool unit_allowed(const RecognisedColumn& c);

// "t", "ax", "raw_yaw", … → the field; nullopt for an unknown key.
std::optional<CsvField> csv_field_from_key(std::string_view key);
// A unit as written ("ms", "deg/s", "m/s^2", …) → the unit; nullopt when unknown.
std::optional<CsvUnit> parse_csv_unit(std::string_view text);

}  // namespace stoneskip
