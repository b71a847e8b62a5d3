#include "reports/scene/side_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace stoneskip {

Vec3 side_view_direction(const Vec3& velocity_m_s) {
  const Vec3 h(velocity_m_s.x(), velocity_m_s.y(), 0.0);
  const double n = h.norm();
  return n > 1e-12 ? Vec3(h / n) : Vec3::UnitX();
}

SideWindow side_window(double z_m, double radius_m) {
  SideWindow w;
  const double R = 100 * radius_m, z = 100 * z_m, margin = 0.3 * R;
  if (std::abs(z) <= kSideViewReach * R) {
    w.z0_cm = std::min(-margin, z - R - margin);
    w.z1_cm = std::max(margin, z + R + margin);
  } else {
    w.z0_cm = z - 2 * R;
    w.z1_cm = z + 2 * R;
    char note[96];
    std::snprintf(note, sizeof note, "level %.3g cm %s", std::abs(z), z > 0 ? "below" : "above");  // short: a narrow panel
    w.level_note = note;
  }
  // The panel is taller than wide: the window takes its shape, the height grown about its middle.
  const double half = std::max(2.5 * R, 0.5 * (w.z1_cm - w.z0_cm) / kSideViewAspect);
  const double grow = 0.5 * (2 * half * kSideViewAspect - (w.z1_cm - w.z0_cm));
  w.z0_cm -= grow;
  w.z1_cm += grow;
  w.s0_cm = -half;
  w.s1_cm = half;
  return w;
}

void write_side_faces(std::ostream& out, const Stone& stone, const RigidState& state, const Vec3& direction) {
  const Mat3 R = state.orientation.normalized().toRotationMatrix();
  const auto& v = stone.body_mesh.vertices;
  char line[64];
  for (const auto& t : stone.body_mesh.triangles) {
    for (int k = 0; k <= 3; ++k) {
      const Vec3 r = R * v[t[k % 3]];  // from the centre of mass, world axes
      std::snprintf(line, sizeof line, "%.6g %.6g\n", 100 * r.dot(direction), 100 * (state.position_m.z() + r.z()));
      out << line;
    }
    out << "\n";
  }
}

std::vector<double> side_samples_cm(const SideWindow& w, int count) {
  std::vector<double> s(static_cast<std::size_t>(std::max(count, 2)));
  for (std::size_t k = 0; k < s.size(); ++k) s[k] = w.s0_cm + (w.s1_cm - w.s0_cm) * double(k) / double(s.size() - 1);
  return s;
}

}  // namespace stoneskip
