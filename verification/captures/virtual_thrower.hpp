#pragma once
// The virtual thrower: from the hand motion a capture measures to the virtual stone the solvers
// throw (documented in tools/capture/README.md, "The virtual thrower").
//
// A person throws a remote in a room, not a stone over a lake. The capture measures, for the stone
// held at the mounting's offset from the remote (mounting.hpp, stone_offset_m): its velocity, its
// attitude (attack, path and roll angles), its angular velocity, and its rise from the still part
// to the release — all in the room. What the room cannot give is mapped here:
//   * the height: where the water is. fixed_release_height (default) puts the stone's centre
//     release_height_m above the water whatever the hand did (a person in a room cannot release
//     at water level); still_part_height puts the still part at still_height_m and adds the
//     measured rise (for a capture made at the water's edge);
//   * scaling: speed_scale multiplies the measured velocity, spin_scale the measured spin about
//     the stone's normal; default 1 (the throw as measured: the seed's interface uses the remote's
//     motion as the stone's, Lee & Baek 2013 §3.3);
//   * finger_spin_rev_s: spin the fingers give a real stone at release, which a remote strapped to
//     the forearm or wrist cannot see (published hand throws spin at 10–20 rev/s, Clanet, Hersen &
//     Bocquet 2004; Bocquet 2003's example 14 rev/s; an arm swing alone gives 2–4 rev/s); default 0:
//     nothing that was not measured is added unless asked.
// Attack, path and roll angles are not changed by the mapping. The analysis keeps both the throw
// as measured and as mapped (ReleaseKinematics).
#include <string>
#include <vector>

#include "model/stone/mesh.hpp"

namespace stoneskip {

enum class HeightMapping { fixed_release_height, still_part_height };
const char* to_string(HeightMapping m);

struct VirtualThrowerOptions {
  HeightMapping height_mapping = HeightMapping::fixed_release_height;
  // Stone centre above the virtual water at release. 0.3 m: skippers crouch and release side-arm
  // "a few tens of centimetres" above the water (Clanet, Hersen & Bocquet 2004; Rosellini et al.
  // 2005); the stone then meets the water at the shallow path angle the optimum needs.
  double release_height_m = 0.3;
  // still_part_height: the stone centre's height during the still part. 1 m: a hand held still at
  // the hip of a standing adult.
  double still_height_m = 1.0;
  // ± (uniform) on the virtual height in the ensemble: how well a person can say where the hand is.
  double height_uncertainty_m = 0.1;
  double speed_scale = 1.0;       // measured velocity × this
  double spin_scale = 1.0;        // measured spin about the stone's normal × this
  double finger_spin_rev_s = 0.0; // added about the stone's normal (same sense as the measured spin)

  // False with the reason when a value is out of range.
  bool is_valid(std::string* why) const;
};

// Applies "key=value" (keys as the field names; height_mapping = fixed_release_height |
// still_part_height). Throws InputError naming `where` and "thrower.KEY" for an unknown key or a
// bad value.
void apply_thrower_setting(VirtualThrowerOptions& o, const std::string& setting, const std::string& where);
// Every setting as "key=value" (for headers and reports).
std::vector<std::string> thrower_settings(const VirtualThrowerOptions& o);

// The stone at release as the capture measured it in the room (heading turned so the horizontal
// velocity points along +x) …
struct MeasuredThrow {
  Vec3 velocity_m_s = Vec3::Zero();
  Vec3 omega_body_rad_s = Vec3::Zero();  // stone body frame; z is the stone's normal
  double rise_m = 0;                     // stone centre: release height − still-part height
};
// … and the virtual stone's initial values it maps to.
struct VirtualThrow {
  Vec3 velocity_m_s = Vec3::Zero();
  Vec3 omega_body_rad_s = Vec3::Zero();
  double height_m = 0;  // stone centre above the virtual water
};

// The mapping. height_offset_m is the ensemble's draw within ±height_uncertainty_m (0: nominal).
VirtualThrow map_to_virtual(const MeasuredThrow& measured, const VirtualThrowerOptions& o, double height_offset_m = 0);

}  // namespace stoneskip
