#pragma once
// Shared by the coupling tests (not part of the library): closed meshes made of voxels (boxes and
// non-convex shapes with exact column structure) and an independent submerged volume.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>
#include <vector>

#include "model/stone/mesh.hpp"
#include "model/water/height_field.hpp"

namespace stoneskip::test {

// The boundary of a union of lattice voxels (ix, iy, iz) of size (sx, sy, sz), shifted by
// -offset: every voxel face without a neighbour becomes two outward triangles. Closed and
// manifold when no two voxels touch only along an edge.
inline Mesh voxel_mesh(const std::vector<std::array<int, 3>>& voxels, const Vec3& size, const Vec3& offset) {
  Mesh m;
  std::map<std::tuple<int, int, int>, int> index;
  auto vertex = [&](int x, int y, int z) {
    auto key = std::make_tuple(x, y, z);
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    m.vertices.push_back(Vec3(x * size.x(), y * size.y(), z * size.z()) - offset);
    return index[key] = static_cast<int>(m.vertices.size()) - 1;
  };
  auto filled = [&](int x, int y, int z) {
    return std::find(voxels.begin(), voxels.end(), std::array<int, 3>{x, y, z}) != voxels.end();
  };
  for (const auto& v : voxels)
    for (int axis = 0; axis < 3; ++axis)
      for (int side : {0, 1}) {
        std::array<int, 3> n = v;
        n[axis] += side ? 1 : -1;
        if (filled(n[0], n[1], n[2])) continue;
        const int u = (axis + 1) % 3, w = (axis + 2) % 3;
        std::array<std::array<int, 3>, 4> c;
        for (int k = 0; k < 4; ++k) {
          c[k] = v;
          c[k][axis] += side;
        }
        c[1][u] += 1;
        c[2][u] += 1;
        c[2][w] += 1;
        c[3][w] += 1;  // a cycle: (0,0), (1,0), (1,1), (0,1) in (u, w); normal +axis
        int q[4];
        for (int k = 0; k < 4; ++k) q[k] = vertex(c[k][0], c[k][1], c[k][2]);
        if (side) {
          m.triangles.push_back({q[0], q[1], q[2]});
          m.triangles.push_back({q[0], q[2], q[3]});
        } else {
          m.triangles.push_back({q[0], q[2], q[1]});
          m.triangles.push_back({q[0], q[3], q[2]});
        }
      }
  return m;
}

// Volume of a closed mesh (vertices already in the world) below the plane z = eta, by an
// independent route: tetrahedra from the vertices' centroid to each triangle, each clipped by the
// half-space z ≤ eta (the part below a plane of a tetrahedron is a tetrahedron, a tetrahedron's
// complement, or a wedge cut into three tetrahedra), signed volumes summed.
inline double tet_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

inline double tet_volume_below(std::array<Vec3, 4> p, double eta) {
  const double full = tet_volume(p[0], p[1], p[2], p[3]);
  std::array<int, 4> below{}, above{};
  int nb = 0, na = 0;
  for (int k = 0; k < 4; ++k) (p[k].z() < eta ? below[nb++] : above[na++]) = k;
  auto cut = [&](int i, int j) {  // where edge i–j crosses z = eta
    const double t = (eta - p[i].z()) / (p[j].z() - p[i].z());
    return Vec3(p[i] + t * (p[j] - p[i]));
  };
  const double sign = full < 0 ? -1 : 1;
  if (nb == 0) return 0;
  if (nb == 4) return full;
  if (nb == 1) {
    const int a = below[0];
    return sign * std::abs(tet_volume(p[a], cut(a, above[0]), cut(a, above[1]), cut(a, above[2])));
  }
  if (nb == 3) {
    const int a = above[0];
    return full - sign * std::abs(tet_volume(p[a], cut(a, below[0]), cut(a, below[1]), cut(a, below[2])));
  }
  const int a = below[0], b = below[1], c = above[0], d = above[1];
  const Vec3 ac = cut(a, c), ad = cut(a, d), bc = cut(b, c), bd = cut(b, d);
  return sign * (std::abs(tet_volume(p[a], ac, ad, p[b])) + std::abs(tet_volume(ac, ad, p[b], bd)) +
                 std::abs(tet_volume(ac, p[b], bc, bd)));
}

inline double submerged_volume(const std::vector<Vec3>& world, const std::vector<std::array<int, 3>>& triangles, double eta) {
  Vec3 centre = Vec3::Zero();
  for (const auto& v : world) centre += v;
  centre /= static_cast<double>(world.size());
  double v = 0;
  for (const auto& t : triangles) v += tet_volume_below({centre, world[t[0]], world[t[1]], world[t[2]]}, eta);
  return v;
}

// A still field at height eta (both levels), cells of size d, n × n.
inline HeightFieldOptions still_field_options(int n, double cell_m, Boundary b) {
  HeightFieldOptions o;
  o.nx = o.ny = n;
  o.cell_m = cell_m;
  o.dt_s = 0.1 * cell_m;
  o.stencil = named_stencil("five_point");
  o.boundary = b;
  return o;
}

}  // namespace stoneskip::test
