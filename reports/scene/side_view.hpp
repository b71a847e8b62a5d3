#pragma once
// The movie's side view (reports/scene/frame_plot.hpp, third panel): the stone at true scale, seen
// from the side in the vertical plane through its centre along the throw, with the water's surface
// along that plane. A frame's dot cannot show what decides a skip (the stone's attack angle and
// tilt, how deep it is in the water); this panel does, at the scale the stone has.
//   s: distance along the view's horizontal direction e from the stone's centre (cm);
//   z: height above the still level (cm).
// The view's direction is fixed for a movie: the throw's horizontal velocity at the start (world x
// for a throw without one), so that the camera does not turn with the stone's path.
#include <ostream>
#include <string>
#include <vector>

#include "model/stone/stone.hpp"
#include "model/stone/rigid_state.hpp"

namespace stoneskip {

// The horizontal unit vector along v; world x where v has no horizontal part (|v_xy| ≤ 1e-12 m/s).
Vec3 side_view_direction(const Vec3& velocity_m_s);

// The window around a stone of radius R (its largest vertex distance) whose centre is at height z:
// the still level and the stone both in view, with a margin of 0.3 R, while the centre is within
// kSideViewReach R of the still level; beyond it (high in flight, sunk deep), 4 R around the stone
// alone, and `level_note` says where the still level is ("level 12.3 cm below").
// The window has the panel's shape, kSideViewAspect times as high as wide (the panel is drawn at
// true scale), at least 5 R wide and centred on the stone; the height that shape adds is shared
// above and below.
struct SideWindow {
  double s0_cm = 0, s1_cm = 0, z0_cm = 0, z1_cm = 0;
  std::string level_note;
};
constexpr double kSideViewReach = 4.0;
constexpr double kSideViewAspect = 1.6;
SideWindow side_window(double z_m, double radius_m);

// The stone's faces projected on the (s, z) plane, in cm: per triangle its three corners and the
// first again (a closed outline), then a blank line. Drawn filled, the faces give the stone's
// silhouette; their edges show its facets.
void write_side_faces(std::ostream& out, const Stone& stone, const RigidState& state, const Vec3& direction);

// The points s (cm) at which the water's surface is sampled across a window: `count` evenly spaced
// from s0 to s1.
std::vector<double> side_samples_cm(const SideWindow& w, int count);

}  // namespace stoneskip
