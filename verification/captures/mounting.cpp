#include "verification/captures/mounting.hpp"

#include <cmath>
#include <cstdio>

#include "verification/captures/strict_numbers.hpp"
#include "tools/io/input_error.hpp"

namespace stoneskip {

Mat3 Mounting::stone_axes() const {
  const Vec3 z = stone_normal.normalized();
  const Vec3 x = (stone_forward - stone_forward.dot(z) * z).normalized();
  Mat3 m;
  m.col(0) = x;
  m.col(1) = z.cross(x);
  m.col(2) = z;
  return m;
}

namespace {
Vec3 parse_vec(const std::string& value, const std::string& where, const std::string& key) {
  const auto f = split_fields(value, true);
  if (f.size() != 3) throw_input_error(where, 0, key, "expected three numbers x,y,z, got '" + value + "'");
  Vec3 v;
  for (int i = 0; i < 3; ++i) {
    const auto x = parse_real(f[i]);
    if (!x) throw_input_error(where, 0, key, "not a number: '" + std::string(f[i]) + "'");
    v[i] = *x;
  }
  return v;
}
}  // namespace

void apply_mounting_setting(Mounting& m, const std::string& setting, const std::string& where) {
  const auto [key, value] = split_setting(setting, where);
  const std::string full = "mounting." + key;
  if (key == "stone_normal" || key == "stone_forward") {
    const Vec3 v = parse_vec(value, where, full);
    if (v.norm() < 1e-6) throw_input_error(where, 0, full, "must not be the zero vector");
    (key == "stone_normal" ? m.stone_normal : m.stone_forward) = v.normalized();
  } else if (key == "stone_offset_m") {
    // Plausibility: the stone is in the hand that holds the remote.
    m.stone_offset_m = parse_vec(value, where, full);
    if (!(m.stone_offset_m.norm() <= 1.0)) throw_input_error(where, 0, full, "must be at most 1 m long, the stone being in the hand (got " + value + ")");
  } else if (key == "lever_arm_m") {
    // Plausibility: a forearm to a whole arm; zero would make the lever-arm speed 0.
    m.lever_arm_m = parse_vec(value, where, full);
    if (!(m.lever_arm_m.norm() >= 0.05 && m.lever_arm_m.norm() <= 3.0))
      throw_input_error(where, 0, full, "must be 0.05 to 3 m long, pivot of the swing to the stone (got " + value + ")");
  } else if (key == "lever_arm_rel_uncertainty") {
    const auto x = parse_real(value);
    if (!x || *x < 0 || *x > 1) throw_input_error(where, 0, full, "must be a number in [0, 1]");
    m.lever_arm_rel_uncertainty = *x;
  } else {
    throw_input_error(where, 0, full,
                      "unknown mounting key (known: stone_normal, stone_forward, stone_offset_m, lever_arm_m, "
                      "lever_arm_rel_uncertainty)");
  }
}

void check_mounting(const Mounting& m, const std::string& where) {
  const Vec3 z = m.stone_normal.normalized();
  if ((m.stone_forward - m.stone_forward.dot(z) * z).norm() < 1e-3)
    throw_input_error(where, 0, "mounting.stone_forward",
                      "must not be parallel to mounting.stone_normal (with every setting applied)");
}

std::vector<std::string> mounting_settings(const Mounting& m) {
  auto vec = [](const Vec3& v) {
    char b[128];
    std::snprintf(b, sizeof b, "%.6g,%.6g,%.6g", v.x(), v.y(), v.z());
    return std::string(b);
  };
  char u[64];
  std::snprintf(u, sizeof u, "%.6g", m.lever_arm_rel_uncertainty);
  return {"stone_normal=" + vec(m.stone_normal), "stone_forward=" + vec(m.stone_forward),
          "stone_offset_m=" + vec(m.stone_offset_m), "lever_arm_m=" + vec(m.lever_arm_m),
          std::string("lever_arm_rel_uncertainty=") + u};
}

}  // namespace stoneskip
