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

}  // namespace stoneskip
