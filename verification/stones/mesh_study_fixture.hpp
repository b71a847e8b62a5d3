#pragma once
// A fixture shared by the tests of the mesh study and of the report sections that read it: the
// spin-sweep stone's prism (circumradius 3 cm, 8 mm thick, 2500 kg/m³) with N rim segments and
// a rim cut, as a mesh study's variant (mesh_study.hpp). For tests only.
#include "model/stone/mass_properties.hpp"
#include "model/stone/mesh.hpp"
#include "model/stone/stone.hpp"
#include "verification/stones/mesh_study.hpp"

namespace stoneskip {

inline MeshVariant test_prism_variant(int segments, RimSplit split) {
  const Mesh mesh = make_prism(0.03, 0.008, segments, split);
  return MeshVariant{segments, split, make_stone(mesh, mass_properties_from_density(mesh, 2500.0), 0.03, "test prism")};
}

}  // namespace stoneskip
