#include "model/stone/fluid_forces.hpp"

#include <vector>

#include "model/stone/triangle_clip.hpp"
#include "model/stone/water_laws.hpp"

namespace stoneskip {

WaterLoads water_loads(const Stone& stone, const Environment& env, const RigidState& s, const WaterSurface* surface) {
  WaterLoads out;
  const auto& verts = stone.body_mesh.vertices;
  const int nv = static_cast<int>(verts.size());
  out.vertex_count = nv;
  // Still water: a stone whose bounding sphere is above z = 0 cannot touch it.
  if (!surface && s.position_m.z() - stone.bounding_radius_m > 0) {
    out.deepest_depth_m = -(s.position_m.z() - stone.bounding_radius_m);
    return out;
  }
  const Mat3 R = s.orientation.normalized().toRotationMatrix();
  const Vec3 omega = R * (stone.inertia_body_inv * (R.transpose() * s.angular_momentum_kg_m2_s));

  // Vertex positions and signed depths d_j = η(x_j, y_j) − z_j (spec §1.4 step 1). The buffers are
  // reused between calls: no allocation in a step loop once they have grown.
  thread_local std::vector<Vec3> world;
  thread_local std::vector<double> depth;
  world.resize(nv);
  depth.resize(nv);
  double deepest = -1e300;
  for (int k = 0; k < nv; ++k) {
    world[k] = s.position_m + R * verts[k];
    const double eta = surface ? surface->height_m(world[k].x(), world[k].y()) : 0.0;
    depth[k] = eta - world[k].z();
    deepest = std::max(deepest, depth[k]);
    if (depth[k] > 0) ++out.submerged_vertices;
  }
  out.deepest_depth_m = deepest;
  if (deepest <= 0) return out;

  const bool paper = env.convention == Convention::paper;
  const auto& tris = stone.body_mesh.triangles;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    const auto& t = tris[i];
    const ClippedArea c = clip_submerged(world[t[0]], world[t[1]], world[t[2]], depth[t[0]], depth[t[1]], depth[t[2]]);
    if (c.area_m2 <= 0) continue;
    ++out.wet_triangles;
    out.wetted_area_m2 += c.area_m2;
    const Vec3 n = R * stone.face_normals_body[i];
    const Vec3 r = c.centroid_m - s.position_m;  // lever arm (spec §1.4 step 3)
    // Lee & Baek 2013 Eq. 1: printed v + r × ω; physical v + ω × r.
    const Vec3 vi = paper ? Vec3(s.velocity_m_s + r.cross(omega)) : Vec3(s.velocity_m_s + omega.cross(r));
    // Eq. 2: printed on every submerged face; physical: the case's water law, zero unless the face
    // advances into the water (model/stone/water_laws.hpp).
    const Vec3 F = paper ? printed_face_force_N(env, n, vi, c.area_m2) : face_force_N(env, n, vi, c.area_m2);
    if (F.isZero(0)) continue;
    out.force_N += F;
    // Eq. 3: printed F × r; physical r × F.
    out.torque_N_m += paper ? Vec3(F.cross(r)) : Vec3(r.cross(F));
  }
  return out;
}

AirLoads air_loads(const Stone& stone, const Environment& env, const RigidState& s) {
  AirLoads out;
  const Vec3 n = s.orientation.normalized() * Vec3::UnitZ();  // disk normal: body z in world
  const double u = s.velocity_m_s.dot(n);
  const double k = env.air_coefficient * env.air_density_kg_m3 * stone.disk_area_m2;
  // Lee & Baek 2013 Eq. 6 prints (v·n)²: always along −n; physical u|u| opposes the motion.
  const double mag = env.convention == Convention::paper ? u * u : u * std::abs(u);
  out.force_N = -k * mag * n;
  return out;
}

}  // namespace stoneskip
