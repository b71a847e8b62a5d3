#include "model/stone/triangle_clip.hpp"

namespace stoneskip {

ClippedArea clip_submerged(const Vec3& p0, const Vec3& p1, const Vec3& p2, double d0, double d1, double d2) {
  ClippedArea out;
  const Vec3* p[3] = {&p0, &p1, &p2};
  const double d[3] = {d0, d1, d2};
  if (d0 < 0 && d1 < 0 && d2 < 0) return out;
  if (d0 >= 0 && d1 >= 0 && d2 >= 0) {
    out.area_m2 = 0.5 * (p1 - p0).cross(p2 - p0).norm();
    out.centroid_m = (p0 + p1 + p2) / 3.0;
    return out;
  }
  // Sutherland–Hodgman against the half-space d ≥ 0: at most 4 vertices.
  Vec3 poly[4];
  int n = 0;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const bool in_i = d[i] >= 0, in_j = d[j] >= 0;
    if (in_i) poly[n++] = *p[i];
    if (in_i != in_j) {
      const double s = d[i] / (d[i] - d[j]);  // d crosses zero linearly along the edge
      poly[n++] = *p[i] + s * (*p[j] - *p[i]);
    }
  }
  // Fan from poly[0]: area-weighted centroid of the sub-triangles (convex polygon).
  double area = 0;
  Vec3 moment = Vec3::Zero();
  for (int k = 1; k + 1 < n; ++k) {
    const double a = 0.5 * (poly[k] - poly[0]).cross(poly[k + 1] - poly[0]).norm();
    area += a;
    moment += a * (poly[0] + poly[k] + poly[k + 1]) / 3.0;
  }
  out.area_m2 = area;
  if (area > 0) out.centroid_m = moment / area;
  return out;
}

}  // namespace stoneskip
