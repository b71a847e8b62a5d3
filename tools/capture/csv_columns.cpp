#include "tools/capture/csv_columns.hpp"

#include <algorithm>
#include <cctype>
#include <map>

namespace stoneskip {

const char* to_string(CsvUnit u) {
  switch (u) {
    case CsvUnit::none: return "";
    case CsvUnit::s: return "s";
    case CsvUnit::ms: return "ms";
    case CsvUnit::us: return "us";
    case CsvUnit::g: return "g";
    case CsvUnit::m_s2: return "m/s2";
    case CsvUnit::deg_s: return "deg/s";
    case CsvUnit::rad_s: return "rad/s";
    case CsvUnit::deg: return "deg";
    case CsvUnit::hex: return "hex";
    case CsvUnit::dec: return "dec";
  }
  return "?";
}

const std::vector<CsvFieldInfo>& csv_fields() {
  using F = CsvField;
  using U = CsvUnit;
  static const std::vector<CsvFieldInfo> table{
      {F::time, "t", "host time (unit from the header, else detected)", {U::none, U::s, U::ms, U::us}},
      {F::sequence, "seq", "row or sample number (read, not used)", {U::none}},
      {F::ax, "ax", "acceleration along X", {U::none, U::g, U::m_s2}},
      {F::ay, "ay", "acceleration along Y", {U::none, U::g, U::m_s2}},
      {F::az, "az", "acceleration along Z", {U::none, U::g, U::m_s2}},
      {F::wx, "wx", "angular rate about X (pitch), right-handed", {U::none, U::deg_s, U::rad_s}},
      {F::wy, "wy", "angular rate about Y (roll), right-handed", {U::none, U::deg_s, U::rad_s}},
      {F::wz, "wz", "angular rate about Z (yaw), right-handed", {U::none, U::deg_s, U::rad_s}},
      {F::speed_pitch, "speed_pitch", "WiiYourself! MotionPlus.Speed.Pitch (sign reversed: about -X)", {U::deg_s, U::rad_s}},
      {F::speed_roll, "speed_roll", "WiiYourself! MotionPlus.Speed.Roll (about -Y)", {U::deg_s, U::rad_s}},
      {F::speed_yaw, "speed_yaw", "WiiYourself! MotionPlus.Speed.Yaw (about -Z)", {U::deg_s, U::rad_s}},
      {F::raw_pitch, "raw_pitch", "MotionPlus raw pitch word (14 bits)", {U::hex, U::dec}},
      {F::raw_roll, "raw_roll", "MotionPlus raw roll word (14 bits)", {U::hex, U::dec}},
      {F::raw_yaw, "raw_yaw", "MotionPlus raw yaw word (14 bits)", {U::hex, U::dec}},
      {F::slow_pitch, "slow_pitch", "MotionPlus pitch in slow mode (0/1)", {U::none}},
      {F::slow_roll, "slow_roll", "MotionPlus roll in slow mode (0/1)", {U::none}},
      {F::slow_yaw, "slow_yaw", "MotionPlus yaw in slow mode (0/1)", {U::none}},
      {F::fast_pitch, "fast_pitch", "MotionPlus pitch in fast mode (0/1)", {U::none}},
      {F::fast_roll, "fast_roll", "MotionPlus roll in fast mode (0/1)", {U::none}},
      {F::fast_yaw, "fast_yaw", "MotionPlus yaw in fast mode (0/1)", {U::none}},
      {F::buttons, "buttons", "WiiYourself! Button.Bits (B 0x0400, A 0x0800)", {U::hex, U::dec}},
      {F::button_a, "button_a", "button A held (0/1)", {U::none}},
      {F::button_b, "button_b", "button B held (0/1)", {U::none}},
      {F::orientation_pitch, "pitch", "accelerometer orientation pitch (read, not used)", {U::deg}},
      {F::orientation_roll, "roll", "accelerometer orientation roll (read, not used)", {U::deg}},
  };
  return table;
}

const CsvFieldInfo& csv_field_info(CsvField f) { return csv_fields()[std::size_t(f)]; }

namespace {

// The table of recognised names (normalised words) → field.
const std::map<std::string, CsvField>& names() {
  static const std::map<std::string, CsvField> table = [] {
    using F = CsvField;
    std::map<std::string, CsvField> m;
    auto add = [&](const std::string& name, F f) { m.emplace(name, f); };
    for (const char* n : {"time", "t", "timestamp", "time stamp", "elapsed", "elapsed time", "host time", "current time",
                          "tick count"})
      add(n, F::time);
    for (const char* n : {"sample", "sample number", "seq", "sequence", "sequence number", "index", "n", "row", "report",
                          "report number", "count", "frame"})
      add(n, F::sequence);
    const char* axes[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i) {
      const std::string x = axes[i];
      const F acc = F(int(F::ax) + i), rate = F(int(F::wx) + i);
      // Not "linear acceleration": a phone's sensor of that name has gravity removed, which the
      // analysis needs (a specific force); such a column is left unused, beside the accelerometer's.
      for (const char* p : {"acc", "accel", "acceleration", "accelerometer", "a"}) {
        add(std::string(p) + " " + x, acc);
        add(std::string(p) + x, acc);
      }
      for (const char* p : {"gyro", "gyroscope", "gyr", "rate", "angular rate", "angular velocity", "omega", "w",
                            "rot", "rotation rate"}) {
        add(std::string(p) + " " + x, rate);
        if (std::string(p).find(' ') == std::string::npos) add(std::string(p) + x, rate);
      }
      add("g" + x, rate);  // "gx": a gyro axis ("g x" would read as a unit)
    }
    const char* motions[3] = {"pitch", "roll", "yaw"};
    for (int i = 0; i < 3; ++i) {
      const std::string a = motions[i];
      add(a + " rate", F(int(F::wx) + i));
      for (const char* p : {"speed", "motionplus speed", "motion plus speed", "mp speed", "wmp speed"}) {
        add(std::string(p) + " " + a, F(int(F::speed_pitch) + i));
        add(a + " " + p, F(int(F::speed_pitch) + i));
      }
      add("speed" + a, F(int(F::speed_pitch) + i));
      for (const char* p : {"raw", "motionplus raw", "motion plus raw", "mp raw", "wmp raw", "mp", "wmp", "motionplus",
                            "motion plus"}) {
        add(std::string(p) + " " + a, F(int(F::raw_pitch) + i));
        add(a + " " + p, F(int(F::raw_pitch) + i));
      }
      add("raw" + a, F(int(F::raw_pitch) + i));
      for (const char* p : {"slow", "mp slow", "motionplus slow", "slow mode"}) {
        add(std::string(p) + " " + a, F(int(F::slow_pitch) + i));
        add(a + " " + p, F(int(F::slow_pitch) + i));
      }
      for (const char* p : {"fast", "mp fast", "motionplus fast", "fast mode"}) {
        add(std::string(p) + " " + a, F(int(F::fast_pitch) + i));
        add(a + " " + p, F(int(F::fast_pitch) + i));
      }
    }
    for (const char* n : {"buttons", "button", "button bits", "buttons bits", "bits", "btn", "btns", "button state"})
      add(n, F::buttons);
    for (const char* n : {"a", "button a", "btn a", "a button"}) add(n, F::button_a);
    for (const char* n : {"b", "button b", "btn b", "b button"}) add(n, F::button_b);
    for (const char* p : {"", "orientation ", "acceleration orientation ", "acc ", "accel ", "accelerometer "}) {
      add(std::string(p) + "pitch", F::orientation_pitch);
      add(std::string(p) + "roll", F::orientation_roll);
    }
    return m;
  }();
  return table;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = char(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string_view trim_view(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// Words: split at non-alphanumerics and camelCase boundaries, lowercased.
std::vector<std::string> words(std::string_view s) {
  std::vector<std::string> out;
  std::string w;
  auto flush = [&] {
    if (!w.empty()) out.push_back(lower(w));
    w.clear();
  };
  for (std::size_t i = 0; i < s.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (!std::isalnum(c)) {
      // ^ and digits stay with a unit word ("s^2"); everything else separates.
      if (c == '^' && !w.empty()) {
        w += char(c);
        continue;
      }
      flush();
      continue;
    }
    if (!w.empty() && std::isupper(c) && std::islower(static_cast<unsigned char>(w.back()))) flush();
    w += char(c);
  }
  flush();
  return out;
}

std::string join(const std::vector<std::string>& w, std::size_t n, const char* sep) {
  std::string s;
  for (std::size_t i = 0; i < n; ++i) s += (i ? sep : "") + w[i];
  return s;
}

}  // namespace

std::vector<std::string> csv_field_names(CsvField f) {
  std::vector<std::string> out;
  for (const auto& [name, field] : names())
    if (field == f) out.push_back(name);
  std::sort(out.begin(), out.end(), [](const std::string& a, const std::string& b) {
    return a.size() != b.size() ? a.size() < b.size() : a < b;
  });
  return out;
}

std::optional<CsvUnit> parse_csv_unit(std::string_view text) {
  std::string u;
  for (char c : lower(trim_view(text)))
    if (c != ' ') u += c == '_' ? '/' : c;
  // The degree sign and micro sign in UTF-8.
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"\xc2\xb0", "deg"}, {"\xc2\xb5", "u"}, {"\xce\xbc", "u"}}) {
    for (std::size_t p; (p = u.find(from)) != std::string::npos;) u.replace(p, from.size(), to);
  }
  static const std::map<std::string, CsvUnit> units{
      {"s", CsvUnit::s},         {"sec", CsvUnit::s},        {"secs", CsvUnit::s},        {"seconds", CsvUnit::s},
      {"ms", CsvUnit::ms},       {"msec", CsvUnit::ms},      {"milliseconds", CsvUnit::ms}, {"us", CsvUnit::us},
      {"usec", CsvUnit::us},     {"microseconds", CsvUnit::us}, {"g", CsvUnit::g},        {"m/s2", CsvUnit::m_s2},
      {"m/s^2", CsvUnit::m_s2},  {"ms2", CsvUnit::m_s2},     {"ms^2", CsvUnit::m_s2},     {"m/s/s", CsvUnit::m_s2},
      {"mps2", CsvUnit::m_s2},   {"deg/s", CsvUnit::deg_s},  {"degs", CsvUnit::deg_s},    {"dps", CsvUnit::deg_s},
      {"deg/sec", CsvUnit::deg_s}, {"degrees/s", CsvUnit::deg_s}, {"rad/s", CsvUnit::rad_s}, {"rads", CsvUnit::rad_s},
      {"rad/sec", CsvUnit::rad_s}, {"deg", CsvUnit::deg},    {"degrees", CsvUnit::deg},   {"hex", CsvUnit::hex},
      {"dec", CsvUnit::dec},     {"decimal", CsvUnit::dec}};
  const auto it = units.find(u);
  if (it == units.end()) return std::nullopt;
  return it->second;
}

HeaderParts split_header(std::string_view header) {
  HeaderParts h;
  std::string_view s = trim_view(header);
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = trim_view(s.substr(1, s.size() - 2));
  // 1. Device suffix: '#', optional letters, optional spaces, 1–3 digits (not 0).
  if (const auto hash = s.rfind('#'); hash != std::string_view::npos) {
    const std::string_view d = trim_view(s.substr(hash + 1));
    std::size_t i = 0;
    while (i < d.size() && std::isalpha(static_cast<unsigned char>(d[i]))) ++i;
    while (i < d.size() && d[i] == ' ') ++i;
    const std::string_view digits = d.substr(i);
    if (!digits.empty() && digits.size() <= 3 &&
        std::all_of(digits.begin(), digits.end(), [](char ch) { return std::isdigit(static_cast<unsigned char>(ch)); }) &&
        std::stoi(std::string(digits)) > 0) {
      h.remote = std::stoi(std::string(digits));
      s = trim_view(s.substr(0, hash));
    }
  }
  // 2. Unit in brackets.
  if (!s.empty() && (s.back() == ']' || s.back() == ')')) {
    const char open = s.back() == ']' ? '[' : '(';
    const auto p = s.rfind(open);
    if (p != std::string_view::npos) {
      h.unit_text = std::string(trim_view(s.substr(p + 1, s.size() - p - 2)));
      h.has_bracket_unit = true;
      s = trim_view(s.substr(0, p));
    }
  }
  h.name = std::string(s);
  return h;
}

std::optional<RecognisedColumn> recognise_column(std::string_view header) {
  const HeaderParts h = split_header(header);
  RecognisedColumn c;
  c.remote = h.remote;
  const bool bracket = h.has_bracket_unit;
  if (bracket) {
    const auto u = parse_csv_unit(h.unit_text);
    if (!u) return std::nullopt;  // a unit we do not know: not a column we can read
    c.unit = *u;
  }
  const std::string_view s = h.name;
  // 3–4. Words, looked up whole, then with trailing unit words.
  const std::vector<std::string> w = words(s);
  if (w.empty()) return std::nullopt;
  const auto& table = names();
  if (const auto it = table.find(join(w, w.size(), " ")); it != table.end()) {
    c.field = it->second;
    return c;
  }
  if (bracket) return std::nullopt;
  for (std::size_t unit_words = 1; unit_words <= 2 && unit_words < w.size(); ++unit_words) {
    const std::size_t keep = w.size() - unit_words;
    const std::vector<std::string> tail(w.begin() + std::ptrdiff_t(keep), w.end());
    const auto u = parse_csv_unit(join(tail, tail.size(), "/"));
    const auto it = table.find(join(w, keep, " "));
    if (u && it != table.end()) {
      c.field = it->second;
      c.unit = *u;
      return c;
    }
  }
  return std::nullopt;
}

bool unit_allowed(const RecognisedColumn& c) {
  if (c.unit == CsvUnit::none) return true;
  const auto& units = csv_field_info(c.field).units;
  return std::find(units.begin(), units.end(), c.unit) != units.end();
}

std::optional<CsvField> csv_field_from_key(std::string_view key) {
  for (const auto& f : csv_fields())
    if (key == f.key) return f.field;
  return std::nullopt;
}

}  // namespace stoneskip
