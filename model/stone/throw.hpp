#pragma once
// A throw's initial conditions (model/README.md §1.7): speed U, path angle β (velocity below horizontal),
// attack angle α (leading edge up: body x points to (cos α, 0, sin α)), spin Ω about body z
// (rev/s, positive counter-clockwise seen from above), release height z0, optional wobble ω⊥
// about body x. The throw is along +x.
#include "model/stone/rigid_state.hpp"

namespace stoneskip {

struct ThrowParameters {
  double speed_m_s = 0;
  double path_angle_deg = 0;
  double attack_angle_deg = 0;
  double spin_rev_s = 0;
  double height_m = 0;
  double wobble_rad_s = 0;
};

RigidState initial_state(const Stone& stone, const ThrowParameters& p);

// Angles of a state, for contact reports (model/README.md §1.8):
//   path angle: velocity below the horizontal, degrees;
//   attack angle: inclination of the disk (body z) in the vertical plane of the horizontal velocity,
//                 leading edge up positive, degrees (equals α of §1.7 at release);
//   roll angle: its sideways inclination, degrees.
struct AttitudeAngles {
  double path_angle_deg = 0;
  double attack_angle_deg = 0;
  double roll_angle_deg = 0;
};
AttitudeAngles attitude_angles(const RigidState& s);

}  // namespace stoneskip
