#include "verification/stones/throw_history.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stoneskip {

ThrowHistory make_history(const ThrowProblem& p, ThrowResult result, const std::string& label) {
  ThrowHistory h;
  h.label = label;
  h.solver = result.solver;
  h.convention = p.environment.convention;
  h.table.columns = {"t_s",    "momentum_kg_m_s", "energy_J",  "fluid_power_W", "x_m",           "y_m",
                     "z_m",    "attack_deg",      "roll_deg",  "spin_rev_s",    "wetted_area_m2"};
  const double m = p.stone.mass.mass_kg;
  for (const auto& s : result.trajectory) {
    const AttitudeAngles a = attitude_angles(s.state);
    const Vec3 n = s.state.orientation.normalized() * Vec3::UnitZ();
    h.table.add_row({s.t_s, m * s.state.velocity_m_s.norm(), s.energy_J, fluid_power_W(p.stone, p.environment, s.state),
                     s.state.position_m.x(), s.state.position_m.y(), s.state.position_m.z(), a.attack_angle_deg,
                     a.roll_angle_deg, s.angular_velocity_rad_s.dot(n) / (2 * std::numbers::pi), s.wetted_area_m2});
  }
  if (!result.contacts.empty() && !result.trajectory.empty()) {
    const ContactRecord& k = result.contacts.front();
    const auto nearest = std::min_element(result.trajectory.begin(), result.trajectory.end(), [&](const auto& a, const auto& b) {
      return std::abs(a.t_s - k.start_s) < std::abs(b.t_s - k.start_s);
    });
    const Mat3 R = nearest->state.orientation.normalized().toRotationMatrix();
    double lo = 1e300, hi = -1e300;
    for (const Vec3& v : p.stone.body_mesh.vertices) {
      const double z = (R * v).z();
      lo = std::min(lo, z);
      hi = std::max(hi, z);
    }
    // Vertical entry speed from the contact's entry speed and path angle (below the horizontal: down).
    const double down_m_s = k.entry_speed_m_s * std::sin(k.entry_path_angle_deg * std::numbers::pi / 180);
    if (down_m_s > 0 && hi > lo) h.plunge_s = (hi - lo) / down_m_s;
  }
  result.trajectory.clear();
  result.trajectory.shrink_to_fit();
  h.result = std::move(result);
  return h;
}

}  // namespace stoneskip
