#pragma once
// The stone between a scene's frames, for the movie's slow motion (reports/scene/scene_movie.hpp):
// the stepper's states at its steps' starts (solvers/scene/coupled_scene.hpp, StoneStepRecorder),
// and the pose at any time between two of them — the position linear in time, the orientation by
// spherical linear interpolation (slerp) of the two quaternions. Both are exact for a stone moving
// at constant velocity and turning at a constant rate about a fixed axis, by less than half a turn
// between two states; otherwise their error is second order in the step, which in contact is a
// fraction of a millisecond. A stone turning more than half a turn in one step (a step of 1 ms
// turns a stone at 10 rev/s 3.6°; 65 rev/s needs steps above 7.7 ms) is drawn turning the short
// way, backwards.
#include <vector>

#include "model/stone/rigid_state.hpp"

namespace stoneskip {

struct StonePose {
  double t_s = 0;
  Vec3 position_m = Vec3::Zero();
  Quat orientation = Quat::Identity();
};

// The pose at t from poses in increasing time; before the first, the first; after the last, the
// last (a stone that has ended stays where it ended). Empty poses: an identity pose at t.
StonePose pose_at(const std::vector<StonePose>& poses, double t_s);

}  // namespace stoneskip
