#include "model/stone/stone.hpp"

#include <cmath>
#include <numbers>

namespace stoneskip {

Stone make_stone(const Mesh& mesh, const MassProperties& mp, double disk_radius_m, std::string description, BodyAxes axes) {
  Stone s;
  s.body_mesh = mesh;
  s.mesh_center_of_mass_m = mp.center_of_mass_m;
  s.body_axes_in_mesh = axes == BodyAxes::principal ? principal_frame(mesh, mp) : Mat3::Identity();
  const Mat3& P = s.body_axes_in_mesh;
  const bool rotated = P != Mat3::Identity();
  for (auto& v : s.body_mesh.vertices) {
    v -= mp.center_of_mass_m;
    if (rotated) v = P.transpose() * v;  // mesh → body coordinates
  }
  s.mass = mp;
  s.mass.center_of_mass_m = Vec3::Zero();
  if (rotated) {
    const Mat3 I = P.transpose() * mp.inertia_kg_m2 * P;
    s.mass.inertia_kg_m2 = 0.5 * (I + I.transpose());
  }
  s.inertia_body_kg_m2 = s.mass.inertia_kg_m2;
  s.inertia_body_inv = s.mass.inertia_kg_m2.inverse();
  if (disk_radius_m <= 0) {
    for (const auto& v : s.body_mesh.vertices) disk_radius_m = std::max(disk_radius_m, std::hypot(v.x(), v.y()));
  }
  for (const auto& v : s.body_mesh.vertices) s.bounding_radius_m = std::max(s.bounding_radius_m, v.norm());
  s.disk_radius_m = disk_radius_m;
  s.disk_area_m2 = std::numbers::pi * disk_radius_m * disk_radius_m;  // model/README.md §1.5: S_d = π R²
  for (const auto& t : s.body_mesh.triangles) {
    const Vec3 cr = (s.body_mesh.vertices[t[1]] - s.body_mesh.vertices[t[0]])
                        .cross(s.body_mesh.vertices[t[2]] - s.body_mesh.vertices[t[0]]);
    s.face_areas_m2.push_back(0.5 * cr.norm());
    s.face_normals_body.push_back(cr.normalized());
  }
  s.description = std::move(description);
  return s;
}

}  // namespace stoneskip
