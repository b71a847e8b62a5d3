#pragma once
// The part of a triangle below the water surface (model/README.md §1.4 step 2): the polygon where the
// signed depth d = η − z is ≥ 0, cut along the edges where d, interpolated linearly, crosses
// zero. Exact for still water (d is then linear over the triangle).
//
// Defined here, inline: they run for every wet face in every contact right-hand side, and the
// call and the copy of the returned polygon cost about 6 % of one (measured on the 3 cm prism
// skipping, the default physical law; the same arithmetic, so the same bits).
#include <cmath>

#include "model/stone/mesh.hpp"

namespace stoneskip {

struct ClippedArea {
  double area_m2 = 0;
  Vec3 centroid_m = Vec3::Zero();  // meaningful when area_m2 > 0
};

// The wetted polygon itself (convex, at most 4 vertices, in the triangle's winding order; count 0
// when the triangle is dry), for integrals over it other than area and centroid.
struct ClippedPolygon {
  Vec3 vertices[4];
  int count = 0;
};

inline ClippedPolygon clip_submerged_polygon(const Vec3& p0, const Vec3& p1, const Vec3& p2, double d0, double d1,
                                             double d2) {
  ClippedPolygon out;
  const Vec3* p[3] = {&p0, &p1, &p2};
  const double d[3] = {d0, d1, d2};
  if (d0 < 0 && d1 < 0 && d2 < 0) return out;
  // Sutherland–Hodgman against the half-space d ≥ 0: at most 4 vertices.
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const bool in_i = d[i] >= 0, in_j = d[j] >= 0;
    if (in_i) out.vertices[out.count++] = *p[i];
    if (in_i != in_j) {
      const double s = d[i] / (d[i] - d[j]);  // d crosses zero linearly along the edge
      out.vertices[out.count++] = *p[i] + s * (*p[j] - *p[i]);
    }
  }
  return out;
}

// Area and centroid of a clipped polygon.
inline ClippedArea area_of(const ClippedPolygon& poly) {
  ClippedArea out;
  // Fan from vertex 0: area-weighted centroid of the sub-triangles (convex polygon).
  double area = 0;
  Vec3 moment = Vec3::Zero();
  for (int k = 1; k + 1 < poly.count; ++k) {
    const Vec3& a0 = poly.vertices[0];
    const Vec3& a1 = poly.vertices[k];
    const Vec3& a2 = poly.vertices[k + 1];
    const double a = 0.5 * (a1 - a0).cross(a2 - a0).norm();
    area += a;
    moment += a * (a0 + a1 + a2) / 3.0;
  }
  out.area_m2 = area;
  if (area > 0) out.centroid_m = moment / area;
  return out;
}

// The same for a polygon in the plane of the unit normal n (a face's normal): each fan triangle's
// area is ½ |(a1 − a0) × (a2 − a0) · n|, no square root; equal to area_of to round-off.
inline ClippedArea area_of(const ClippedPolygon& poly, const Vec3& n) {
  ClippedArea out;
  double area = 0;
  Vec3 moment = Vec3::Zero();
  const Vec3& a0 = poly.vertices[0];
  for (int k = 1; k + 1 < poly.count; ++k) {
    const Vec3& a1 = poly.vertices[k];
    const Vec3& a2 = poly.vertices[k + 1];
    const double a = 0.5 * std::abs((a1 - a0).cross(a2 - a0).dot(n));
    area += a;
    moment += a * (a0 + a1 + a2);  // 3 × the fan triangle's moment: one division at the end
  }
  out.area_m2 = area;
  if (area > 0) out.centroid_m = moment / (3 * area);
  return out;
}

inline ClippedArea clip_submerged(const Vec3& p0, const Vec3& p1, const Vec3& p2, double d0, double d1, double d2) {
  ClippedArea out;
  if (d0 >= 0 && d1 >= 0 && d2 >= 0) {
    out.area_m2 = 0.5 * (p1 - p0).cross(p2 - p0).norm();
    out.centroid_m = (p0 + p1 + p2) / 3.0;
    return out;
  }
  return area_of(clip_submerged_polygon(p0, p1, p2, d0, d1, d2));
}

}  // namespace stoneskip
