#include "verification/captures/virtual_thrower.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>

#include "tools/io/input_error.hpp"
#include "verification/captures/strict_numbers.hpp"

namespace stoneskip {

namespace {
// The numeric settings by name (the order of thrower_settings).
constexpr std::pair<const char*, double VirtualThrowerOptions::*> kNumbers[] = {
    {"release_height_m", &VirtualThrowerOptions::release_height_m},
    {"still_height_m", &VirtualThrowerOptions::still_height_m},
    {"height_uncertainty_m", &VirtualThrowerOptions::height_uncertainty_m},
    {"speed_scale", &VirtualThrowerOptions::speed_scale},
    {"spin_scale", &VirtualThrowerOptions::spin_scale},
    {"finger_spin_rev_s", &VirtualThrowerOptions::finger_spin_rev_s}};
}  // namespace

const char* to_string(HeightMapping m) {
  return m == HeightMapping::fixed_release_height ? "fixed_release_height" : "still_part_height";
}

bool VirtualThrowerOptions::is_valid(std::string* why) const {
  auto fail = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (!(release_height_m > 0 && release_height_m < 100)) return fail("thrower.release_height_m must be in (0, 100) m");
  if (!(still_height_m > -100 && still_height_m < 100)) return fail("thrower.still_height_m must be in (-100, 100) m");
  if (!(height_uncertainty_m >= 0 && height_uncertainty_m < 10))
    return fail("thrower.height_uncertainty_m must be in [0, 10) m");
  if (!(speed_scale > 0 && speed_scale <= 100)) return fail("thrower.speed_scale must be in (0, 100]");
  if (!(spin_scale >= 0 && spin_scale <= 100)) return fail("thrower.spin_scale must be in [0, 100]");
  if (!(std::abs(finger_spin_rev_s) <= 1000)) return fail("thrower.finger_spin_rev_s must be within ±1000 rev/s");
  return true;
}

void apply_thrower_setting(VirtualThrowerOptions& o, const std::string& setting, const std::string& where) {
  const auto [key, value] = split_setting(setting, where);
  const std::string full = "thrower." + key;
  if (key == "height_mapping") {
    if (value == "fixed_release_height") o.height_mapping = HeightMapping::fixed_release_height;
    else if (value == "still_part_height") o.height_mapping = HeightMapping::still_part_height;
    else throw_input_error(where, 0, full, "expected fixed_release_height or still_part_height, got '" + value + "'");
    return;
  }
  double VirtualThrowerOptions::*field = nullptr;
  for (const auto& [name, member] : kNumbers)
    if (key == name) field = member;
  if (!field)
    throw_input_error(where, 0, full,
                      "unknown thrower key (known: height_mapping, release_height_m, still_height_m, "
                      "height_uncertainty_m, speed_scale, spin_scale, finger_spin_rev_s)");
  const auto x = parse_real(value);
  if (!x) throw_input_error(where, 0, full, "not a number: '" + value + "'");
  VirtualThrowerOptions probe = o;
  probe.*field = *x;
  std::string why;
  if (!probe.is_valid(&why)) throw_input_error(where, 0, full, why);
  o = probe;
}

std::vector<std::string> thrower_settings(const VirtualThrowerOptions& o) {
  std::vector<std::string> out{std::string("height_mapping=") + to_string(o.height_mapping)};
  for (const auto& [name, member] : kNumbers) {
    char b[96];
    std::snprintf(b, sizeof b, "%s=%.6g", name, o.*member);
    out.push_back(b);
  }
  return out;
}

VirtualThrow map_to_virtual(const MeasuredThrow& m, const VirtualThrowerOptions& o, double height_offset_m) {
  VirtualThrow v;
  v.velocity_m_s = o.speed_scale * m.velocity_m_s;
  v.omega_body_rad_s = m.omega_body_rad_s;
  // The finger spin turns the stone the way the hand already does (a thrower adds to the spin,
  // never against it); with no measured spin, positive (counter-clockwise seen from above).
  const double sense = m.omega_body_rad_s.z() < 0 ? -1.0 : 1.0;
  v.omega_body_rad_s.z() = o.spin_scale * m.omega_body_rad_s.z() + sense * 2.0 * std::numbers::pi * o.finger_spin_rev_s;
  v.height_m = (o.height_mapping == HeightMapping::fixed_release_height ? o.release_height_m : o.still_height_m + m.rise_m) +
               height_offset_m;
  return v;
}

}  // namespace stoneskip
