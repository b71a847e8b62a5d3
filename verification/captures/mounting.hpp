#pragma once
// How the remote sits on the thrower and where the stone is relative to it (documented in
// tools/capture/README.md). All vectors are in the remote's frame (capture_trace.hpp).
//
//   stone_normal         the stone's symmetry axis (body z)                 default 0,0,1
//   stone_forward        the stone's body x (its leading edge)               default -1,0,0
//   stone_offset_m       remote → stone centre                               default 0,0.15,-0.03
//   lever_arm_m          pivot of the swing (elbow/shoulder) → stone centre  default 0,0.6,0
//   lever_arm_rel_uncertainty   relative uncertainty of the lever arm      default 0.2
//
// The defaults describe a remote strapped on the back of the right forearm, pointing end toward
// the hand, button face up, the stone held flat under the palm, thrown side-arm.
#include <string>
#include <vector>

#include "model/stone/mesh.hpp"

namespace stoneskip {

struct Mounting {
  Vec3 stone_normal{0, 0, 1};
  Vec3 stone_forward{-1, 0, 0};
  Vec3 stone_offset_m{0, 0.15, -0.03};
  Vec3 lever_arm_m{0, 0.6, 0};
  double lever_arm_rel_uncertainty = 0.2;

  // Columns: the stone's body x, y, z axes in remote coordinates (x re-orthogonalised to z).
  Mat3 stone_axes() const;
};

// Applies "key=value" settings (value "x,y,z" for vectors). Throws InputError naming `where` and
// the key for an unknown key or a bad value. `where` is "FILE:LINE" or "--mount". The settings'
// combination is checked only once all are applied (check_mounting), so that a remote strapped on
// its side can be described key by key, in any order.
void apply_mounting_setting(Mounting& m, const std::string& setting, const std::string& where);
// Throws InputError naming `where` when stone_forward is parallel to stone_normal.
void check_mounting(const Mounting& m, const std::string& where);
// Writes every setting back as "key=value" lines (for headers and reports).
std::vector<std::string> mounting_settings(const Mounting& m);

}  // namespace stoneskip
