#pragma once
// Wavefront OBJ reader for stone meshes: `v x y z` and `f i j k ...` lines (polygons are fanned
// into triangles; `i/t/n` forms and negative indices accepted; everything else ignored).
// Units: metres. Errors name the file and line. Limits: a file of at most 256 MiB, at most
// 1 000 000 triangles, vertex coordinates within ±1e6 m.
#include <cstddef>
#include <string>
#include <vector>

#include "model/stone/mesh.hpp"

namespace stoneskip {

constexpr std::size_t kMaxObjBytes = 256u << 20;
constexpr std::size_t kMaxObjTriangles = 1000000;
constexpr double kMaxObjCoordinate_m = 1e6;

// triangle_lines, where given, receives each triangle's line in the file (1-based; a polygon's
// triangles share its line), and vertex_lines each vertex's, so that a problem found in the mesh
// can name the line.
Mesh read_obj(const std::string& path, std::vector<long>* triangle_lines = nullptr, std::vector<long>* vertex_lines = nullptr);
Mesh parse_obj(const std::string& text, const std::string& name, std::vector<long>* triangle_lines = nullptr,
               std::vector<long>* vertex_lines = nullptr);

}  // namespace stoneskip
