#pragma once
// Wavefront OBJ reader for stone meshes: `v x y z` and `f i j k ...` lines (polygons are fanned
// into triangles; `i/t/n` forms and negative indices accepted; everything else ignored).
// Units: metres. Errors name the file and line.
#include <string>

#include "model/stone/mesh.hpp"

namespace stoneskip {

Mesh read_obj(const std::string& path);
Mesh parse_obj(const std::string& text, const std::string& name);

}  // namespace stoneskip
