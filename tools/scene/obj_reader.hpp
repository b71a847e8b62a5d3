#pragma once
// Wavefront OBJ reader for stone meshes: `v x y z` and `f i j k ...` lines (polygons are fanned
// into triangles; `i/t/n` forms and negative indices accepted; everything else ignored).
// Units: metres. Errors name the file and line. Limits: a file of at most 256 MiB, at most
// 1 000 000 triangles, vertex coordinates within ±1e6 m.
#include <cstddef>
#include <string>

#include "model/stone/mesh.hpp"

namespace stoneskip {

constexpr std::size_t kMaxObjBytes = 256u << 20;
constexpr std::size_t kMaxObjTriangles = 1000000;
constexpr double kMaxObjCoordinate_m = 1e6;

Mesh read_obj(const std::string& path);
Mesh parse_obj(const std::string& text, const std::string& name);

}  // namespace stoneskip
