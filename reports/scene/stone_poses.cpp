#include "reports/scene/stone_poses.hpp"

#include <algorithm>

namespace stoneskip {

StonePose pose_at(const std::vector<StonePose>& poses, double t_s) {
  if (poses.empty()) return StonePose{t_s, Vec3::Zero(), Quat::Identity()};
  if (t_s <= poses.front().t_s) return poses.front();
  if (t_s >= poses.back().t_s) return poses.back();
  // The first pose after t, and the one before it (strictly later: equal times are not bracketed).
  const auto after = std::upper_bound(poses.begin(), poses.end(), t_s, [](double t, const StonePose& p) { return t < p.t_s; });
  const StonePose& b = *after;
  const StonePose& a = *(after - 1);
  const double span = b.t_s - a.t_s;
  const double u = span > 0 ? (t_s - a.t_s) / span : 0.0;
  StonePose p;
  p.t_s = t_s;
  p.position_m = a.position_m + u * (b.position_m - a.position_m);
  // Eigen's slerp takes the shorter arc (q and −q are one orientation).
  p.orientation = a.orientation.normalized().slerp(u, b.orientation.normalized());
  return p;
}

}  // namespace stoneskip
