#pragma once
// The part of a triangle below the water surface (model/README.md §1.4 step 2): the polygon where the
// signed depth d = η − z is ≥ 0, cut along the edges where d, interpolated linearly, crosses
// zero. Exact for still water (d is then linear over the triangle).
#include "model/stone/mesh.hpp"

namespace stoneskip {

struct ClippedArea {
  double area_m2 = 0;
  Vec3 centroid_m = Vec3::Zero();  // meaningful when area_m2 > 0
};

ClippedArea clip_submerged(const Vec3& p0, const Vec3& p1, const Vec3& p2, double d0, double d1, double d2);

// The wetted polygon itself (convex, at most 4 vertices, in the triangle's winding order; count 0
// when the triangle is dry), for integrals over it other than area and centroid.
struct ClippedPolygon {
  Vec3 vertices[4];
  int count = 0;
};
ClippedPolygon clip_submerged_polygon(const Vec3& p0, const Vec3& p1, const Vec3& p2, double d0, double d1, double d2);
// Area and centroid of a clipped polygon.
ClippedArea area_of(const ClippedPolygon& poly);
// The same for a polygon in the plane of the unit normal n (a face's normal): each fan triangle's
// area is ½ |(a1 − a0) × (a2 − a0) · n|, no square root; equal to area_of to round-off.
ClippedArea area_of(const ClippedPolygon& poly, const Vec3& unit_normal);

}  // namespace stoneskip
