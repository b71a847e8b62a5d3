#pragma once
// Mass, centre of mass and inertia tensor of a uniform-density closed triangle mesh, by the
// divergence theorem (Eberly, "Polyhedral Mass Properties (Revisited)", 2002, after Mirtich 1996).
#include "model/stone/mesh.hpp"

namespace stoneskip {

struct MassProperties {
  double volume_m3 = 0;
  double density_kg_m3 = 0;
  double mass_kg = 0;
  Vec3 center_of_mass_m = Vec3::Zero();   // in the mesh's frame
  Mat3 inertia_kg_m2 = Mat3::Zero();      // about the centre of mass, axes of the mesh's frame
};

MassProperties mass_properties_from_density(const Mesh& mesh, double density_kg_m3);
MassProperties mass_properties_from_mass(const Mesh& mesh, double mass_kg);

// The stone's principal frame as a proper rotation P (columns: body x, y, z in the mesh's frame):
// body z is the principal axis of the LARGEST moment (a flat stone's normal, model/README.md §1.1), body x the
// principal axis of the smallest, body y = z × x (right-handed), so Pᵀ I P is diagonal. Eigenvectors
// have no sign and equal moments no direction; the choice:
//  * body z points to the side the mesh calls up: positive along the mesh axis it is most nearly
//    parallel to (+z for a file written z-up; +y for one written y-up, as Blender exports OBJ);
//  * body x points to where the surface's third moment Σ_faces A_f (c_f·x)³ about the centre of mass
//    is positive (an intrinsic choice: the same mesh rotated gets the same x); where that moment
//    vanishes (a shape symmetric along x) it points along its largest mesh component;
//  * with equal in-plane moments (a regular prism's I_xx = I_yy) body x is the mesh's x projected
//    onto the plane normal to body z (then y); with the two largest moments equal, body z is the
//    mesh's up projected onto their plane; three equal moments keep the mesh's axes;
//  * moments within 1e-9 of the largest count as equal; a P within 1e-12 of the identity is the
//    identity, so meshes already on their principal axes (make_prism, make_lens) are left exactly.
// A stone rotated in its file (its up kept up) therefore gives the same body mesh.
Mat3 principal_frame(const Mesh& mesh, const MassProperties& mp);

}  // namespace stoneskip
