#pragma once
// A rigid stone ready for dynamics: its mesh in the body frame (origin at the centre of mass, axes
// along the principal axes of inertia with body z the axis of the largest moment: a flat stone's
// normal, model/README.md §1.1), mass properties, and per-triangle data precomputed once.
#include <Eigen/Geometry>
#include <string>

#include "model/stone/mass_properties.hpp"
#include "model/stone/mesh.hpp"

namespace stoneskip {

using Quat = Eigen::Quaterniond;

struct Stone {
  Mesh body_mesh;                 // vertices relative to the centre of mass, on the principal axes
  MassProperties mass;            // in the body frame: centre_of_mass_m zero, inertia diagonal
  Mat3 body_axes_in_mesh = Mat3::Identity();  // columns: body x, y, z in the mesh's frame (principal_frame)
  Vec3 mesh_center_of_mass_m = Vec3::Zero();  // the centre of mass in the mesh's frame
  Mat3 inertia_body_kg_m2;        // = mass.inertia_kg_m2
  Mat3 inertia_body_inv;          // its inverse
  double disk_radius_m = 0;       // air model's disk radius (model/README.md §1.5)
  double disk_area_m2 = 0;        // π R²
  double bounding_radius_m = 0;   // largest vertex distance from the centre of mass
  std::vector<Vec3> face_normals_body;  // outward unit normals
  std::vector<double> face_areas_m2;
  std::string description;        // "prism R=... h=... N=..."
};

// How the body axes are chosen (model/README.md §1.2):
//   principal: the mesh's principal axes (principal_frame in model/stone/mass_properties.hpp: body z
//              the largest moment, pointing to the mesh's up; body x the smallest; right-handed), so
//              that a mesh rotated in its file, up kept up, gives the same stone (a mesh read from
//              a file);
//   mesh:      the mesh's own axes, moved to the centre of mass: a parametric stone built about its
//              symmetry axis z (make_prism, make_lens), whose body z is that axis (spec: the normal
//              of its flat faces) whatever its thickness. Past h ≈ 1.69 R a prism's largest moment
//              lies across it, and the principal rule would turn it on its side.
enum class BodyAxes { principal, mesh };

// Moves the mesh to its centre of mass, onto the body axes chosen, and precomputes the rest.
// disk_radius_m <= 0 takes the largest distance of a vertex from the body z axis.
Stone make_stone(const Mesh& mesh, const MassProperties& mp, double disk_radius_m, std::string description,
                 BodyAxes axes = BodyAxes::principal);

}  // namespace stoneskip
