#include "tools/io/column_units.hpp"

#include <array>
#include <utility>

namespace stoneskip {

namespace {

// Suffix → unit, longest suffixes first so "_m_s" wins over "_s" and "_kg_m_s" over "_m_s".
// "volume_time_m3_s" is a product (m³ · s) and "_N_s" an impulse (N · s): the names where "_s"
// multiplies.
// "_per_s" is a rate (not "s"), "_m_s2" an acceleration, "_m2_s2" and "_rev2_s2" squares of speeds.
constexpr std::array<std::pair<const char*, const char*>, 30> kSuffixes{{
    {"_impulse_m3_s", "m^3 s"},
    {"_time_m3_s", "m^3 s"},
    {"_rev2_s2", "rev^2/s^2"},
    {"_m2_s2", "m^2/s^2"},
    {"_m_s2", "m/s^2"},
    {"_per_s", "1/s"},
    {"_percent", "%"},
    {"_hz", "Hz"},
    {"_px", "px"},
    {"_N_s", "N s"},
    {"_kg_m_s", "kg m/s"},
    {"_kg_m2", "kg m^2"},
    {"_kg_m3", "kg/m^3"},
    {"_rev_s", "rev/s"},
    {"_rad_s", "rad/s"},
    {"_deg_s", "deg/s"},
    {"_m_s", "m/s"},
    {"_m2", "m^2"},
    {"_m3", "m^3"},
    {"_deg", "deg"},
    {"_rad", "rad"},
    {"_ms", "ms"},
    {"_us", "us"},
    {"_kg", "kg"},
    {"_J", "J"},
    {"_W", "W"},
    {"_N", "N"},
    {"_g", "g_n"},  // accelerometer axes in standard gravity (9.80665 m/s²)
    {"_s", "s"},
    {"_m", "m"},
}};

// Names whose meaning, and so unit, is set by their table: the writer gives the unit.
constexpr std::array<const char*, 8> kContextual{{"value", "error", "x", "low", "high", "lo", "hi", "h"}};

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() > suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

std::string column_unit(const std::string& name) {
  for (const char* c : kContextual)
    if (name == c) return "";
  for (const auto& [suffix, unit] : kSuffixes)
    if (ends_with(name, suffix)) return unit;
  return "1";
}

}  // namespace stoneskip
