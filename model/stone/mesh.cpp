#include "model/stone/mesh.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

namespace stoneskip {

const char* to_string(RimSplit s) { return s == RimSplit::centre ? "centre" : "diagonal"; }

bool parse_rim_split(const std::string& s, RimSplit& out) {
  if (s == "diagonal") out = RimSplit::diagonal;
  else if (s == "centre") out = RimSplit::centre;
  else return false;
  return true;
}

Mesh make_prism(double radius_m, double thickness_m, int segments, RimSplit split) {
  // Spec §1.1: face centres (0, 0, ±h/2), rim vertices (R cos θk, R sin θk, ±h/2), θk = 2πk/N;
  // a fan on each face (N + N triangles) and two triangles per rim segment (2N): 4N in all.
  Mesh m;
  const int n = segments;
  const double hz = 0.5 * thickness_m;
  m.vertices.push_back(Vec3(0, 0, hz));   // 0: top centre
  m.vertices.push_back(Vec3(0, 0, -hz));  // 1: bottom centre
  for (int k = 0; k < n; ++k) {
    const double th = 2.0 * std::numbers::pi * k / n;
    m.vertices.push_back(Vec3(radius_m * std::cos(th), radius_m * std::sin(th), hz));   // 2 + 2k
    m.vertices.push_back(Vec3(radius_m * std::cos(th), radius_m * std::sin(th), -hz));  // 3 + 2k
  }
  auto top = [&](int k) { return 2 + 2 * (k % n); };
  auto bot = [&](int k) { return 3 + 2 * (k % n); };
  for (int k = 0; k < n; ++k) {
    m.triangles.push_back({0, top(k), top(k + 1)});             // top face, normal +z
    m.triangles.push_back({1, bot(k + 1), bot(k)});             // bottom face, normal −z
    if (split == RimSplit::diagonal) {
      m.triangles.push_back({bot(k), bot(k + 1), top(k + 1)});  // rim, normal outward
      m.triangles.push_back({bot(k), top(k + 1), top(k)});
    } else {
      // The face's centre: the mean of its four corners (on the chord, at z = 0).
      const Vec3 c = 0.25 * (m.vertices[bot(k)] + m.vertices[bot(k + 1)] + m.vertices[top(k)] + m.vertices[top(k + 1)]);
      const int ci = static_cast<int>(m.vertices.size());
      m.vertices.push_back(c);
      m.triangles.push_back({ci, bot(k), bot(k + 1)});          // rim, normal outward, each
      m.triangles.push_back({ci, bot(k + 1), top(k + 1)});
      m.triangles.push_back({ci, top(k + 1), top(k)});
      m.triangles.push_back({ci, top(k), bot(k)});
    }
  }
  return m;
}

Mesh make_lens(double radius_m, double thickness_m, int segments) {
  // Spec §1.1: rim ring of N vertices at z = 0, apexes (0, 0, ±h/2): 2N triangles.
  Mesh m;
  const int n = segments;
  m.vertices.push_back(Vec3(0, 0, 0.5 * thickness_m));   // 0: upper apex
  m.vertices.push_back(Vec3(0, 0, -0.5 * thickness_m));  // 1: lower apex
  for (int k = 0; k < n; ++k) {
    const double th = 2.0 * std::numbers::pi * k / n;
    m.vertices.push_back(Vec3(radius_m * std::cos(th), radius_m * std::sin(th), 0));
  }
  auto rim = [&](int k) { return 2 + (k % n); };
  for (int k = 0; k < n; ++k) {
    m.triangles.push_back({0, rim(k), rim(k + 1)});
    m.triangles.push_back({1, rim(k + 1), rim(k)});
  }
  return m;
}

Mesh make_icosphere(double radius_m, int subdivisions) {
  // The icosahedron's 12 vertices are the cyclic permutations of (0, ±1, ±φ), φ the golden ratio.
  const double phi = std::numbers::phi;
  std::vector<Vec3> v{{-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0}, {0, -1, phi}, {0, 1, phi},
                      {0, -1, -phi}, {0, 1, -phi}, {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
  std::vector<std::array<int, 3>> t{{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                    {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                                    {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (auto& x : v) x = radius_m * x.normalized();
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<int, int>, int> midpoint;  // each shared edge split once
    auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      v.push_back(radius_m * (v[a] + v[b]).normalized());
      return midpoint[key] = static_cast<int>(v.size()) - 1;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& [a, b, c] : t) {
      const int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      finer.push_back({a, ab, ca});
      finer.push_back({b, bc, ab});
      finer.push_back({c, ca, bc});
      finer.push_back({ab, bc, ca});
    }
    t = std::move(finer);
  }
  return Mesh{std::move(v), std::move(t)};
}

MeshCheck check_mesh(const Mesh& mesh) {
  MeshCheck c;
  const int nv = static_cast<int>(mesh.vertices.size());
  // Directed edge uses: a closed, consistently oriented 2-manifold uses every edge exactly once
  // in each direction. Each keeps its first and second triangle, to name one at fault.
  struct Uses {
    int count = 0, first = -1, second = -1;
  };
  std::map<std::pair<int, int>, Uses> directed;
  // Sizes relative to the mesh itself, not to the origin: a stone's file may place it far away
  // (a 6 cm box at 1.2e5 m was called inward and at 1.8e5 m degenerate, its coordinates' magnitude
  // swamping its size). The scale is the bounding box's diagonal; the volume's tetrahedra meet at
  // the box's centre, where the cancellation is that of the stone's own size.
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const auto& v : mesh.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const double scale = nv > 0 ? (hi - lo).norm() : 0;
  const Vec3 o = nv > 0 ? Vec3(0.5 * (lo + hi)) : Vec3::Zero();
  constexpr int none = std::numeric_limits<int>::max();
  int first_bad_index = none, first_repeated = none, first_degenerate = none;
  std::vector<char> named(static_cast<std::size_t>(std::max(nv, 0)), 0);  // vertices a valid triangle names
  for (int i = 0; i < static_cast<int>(mesh.triangles.size()); ++i) {
    const auto& t = mesh.triangles[i];
    if (t[0] < 0 || t[1] < 0 || t[2] < 0 || t[0] >= nv || t[1] >= nv || t[2] >= nv) {
      ++c.bad_indices;
      first_bad_index = std::min(first_bad_index, i);
      continue;
    }
    for (int k : t) named[static_cast<std::size_t>(k)] = 1;
    const Vec3 a = mesh.vertices[t[0]] - o;
    const Vec3 b = mesh.vertices[t[1]] - o;
    const Vec3 d = mesh.vertices[t[2]] - o;
    const Vec3 cr = (b - a).cross(d - a);
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      ++c.repeated_vertex_triangles;  // "f 1 1 2": not a triangle; its edges would read as misoriented
      first_repeated = std::min(first_repeated, i);
      continue;
    }
    if (cr.norm() <= 1e-14 * scale * scale) {
      ++c.degenerate_triangles;
      first_degenerate = std::min(first_degenerate, i);
    }
    c.signed_volume_m3 += a.dot(b.cross(d)) / 6.0;  // divergence theorem, tetrahedra from the box's centre
    for (int e = 0; e < 3; ++e) {
      Uses& u = directed[{t[e], t[(e + 1) % 3]}];
      if (u.count == 0) u.first = i;
      else if (u.count == 1) u.second = i;
      ++u.count;
    }
  }
  int first_boundary = none, first_nonmanifold = none;
  std::map<int, int> misoriented_uses;  // triangle → its edges traversed twice one way
  for (const auto& [edge, uses] : directed) {
    const auto rev = directed.find({edge.second, edge.first});
    const Uses back = rev == directed.end() ? Uses{} : rev->second;
    if (uses.count > 1) {
      ++c.misoriented_edges;
      ++misoriented_uses[uses.first];
      ++misoriented_uses[uses.second];
    }
    if (edge.first < edge.second || back.count == 0) {
      const int total = uses.count + back.count;
      const int earliest = back.count == 0 ? uses.first : std::min(uses.first, back.first);
      if (total == 1) {
        ++c.boundary_edges;
        first_boundary = std::min(first_boundary, earliest);
      }
      if (total > 2) {
        ++c.nonmanifold_edges;
        first_nonmanifold = std::min(first_nonmanifold, earliest);
      }
    }
  }
  int first_loose = -1;
  for (int k = nv - 1; k >= 0; --k)
    if (!named[static_cast<std::size_t>(k)]) {
      ++c.loose_vertices;
      first_loose = k;
    }
  auto count = [](int n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); };
  auto blame = [&](int first) { c.at_fault = first == none ? -1 : first; };
  if (mesh.triangles.empty() || nv < 4)
    c.problem = "the mesh has fewer than 4 vertices or no triangles";
  else if (c.bad_indices) {
    c.problem = count(c.bad_indices, "triangle indexes a vertex", "triangles index vertices") + " that do not exist";
    blame(first_bad_index);
  } else if (c.repeated_vertex_triangles) {
    c.problem = count(c.repeated_vertex_triangles, "triangle names", "triangles name") + " one vertex twice (no area)";
    blame(first_repeated);
  } else if (c.boundary_edges) {
    c.problem = "the mesh is open: " + count(c.boundary_edges, "edge belongs", "edges belong") + " to one triangle only";
    blame(first_boundary);
    // A closed surface written as a triangle soup (each face with its own copies of its corners)
    // reads as open: say so, and what mends it.
    std::vector<Vec3> sorted = mesh.vertices;
    std::sort(sorted.begin(), sorted.end(), [](const Vec3& a, const Vec3& b) {
      return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
    });
    int repeats = 0;
    for (std::size_t i = 1; i < sorted.size(); ++i) repeats += sorted[i] == sorted[i - 1] ? 1 : 0;
    if (repeats > 0)
      c.problem += " (" + count(repeats, "vertex repeats", "vertices repeat") +
                   " another's position: merge duplicate vertices, e.g. as the file is exported, so that faces share them)";
  } else if (c.nonmanifold_edges) {
    c.problem = count(c.nonmanifold_edges, "edge is", "edges are") + " shared by more than two triangles";
    blame(first_nonmanifold);
  } else if (c.misoriented_edges) {
    c.problem = "inconsistent orientation: " + count(c.misoriented_edges, "edge is", "edges are") +
                " traversed twice in the same direction";
    // The triangle with most such edges (a face flipped alone has all three), the first on ties.
    int most = 0;
    for (const auto& [t, n] : misoriented_uses)
      if (n > most) {
        most = n;
        c.at_fault = t;
      }
  } else if (c.loose_vertices) {
    // A vertex no face names is still a point of the stone to everything that walks the vertex
    // list: its crossing of the surface would start a contact no face makes, and it would set
    // the bounding and the air disk's default radius.
    c.problem = count(c.loose_vertices, "vertex belongs", "vertices belong") +
                " to no triangle (a loose point would be taken for part of the stone: remove it, e.g. as the file is exported)";
    c.vertex_at_fault = first_loose;
  } else if (c.degenerate_triangles) {
    c.problem = count(c.degenerate_triangles, "triangle has", "triangles have") + " zero area";
    blame(first_degenerate);
  } else if (!(c.signed_volume_m3 > 0))
    c.problem = "the mesh is oriented inward (negative signed volume)";
  c.ok = c.problem.empty();
  return c;
}

int merge_repeated_vertices(Mesh& mesh, std::vector<long>* vertex_lines) {
  const int n = static_cast<int>(mesh.vertices.size());
  // The vertices in coordinate order: equal positions are adjacent; each maps to its first (lowest
  // index) copy, so that a mesh without repeats keeps its numbering.
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  auto less = [&](int a, int b) {
    const Vec3 &u = mesh.vertices[a], &v = mesh.vertices[b];
    if (u.x() != v.x()) return u.x() < v.x();
    if (u.y() != v.y()) return u.y() < v.y();
    if (u.z() != v.z()) return u.z() < v.z();
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<int> first(n);
  for (int k = 0; k < n; ++k) {
    const int i = order[k];
    first[i] = k > 0 && mesh.vertices[order[k - 1]] == mesh.vertices[i] ? first[order[k - 1]] : i;
  }
  std::vector<int> renumber(n, -1);
  std::vector<Vec3> kept;
  std::vector<long> kept_lines;
  for (int i = 0; i < n; ++i) {
    if (first[i] != i) continue;
    renumber[i] = static_cast<int>(kept.size());
    kept.push_back(mesh.vertices[i]);
    if (vertex_lines && i < static_cast<int>(vertex_lines->size())) kept_lines.push_back((*vertex_lines)[i]);
  }
  const int merged = n - static_cast<int>(kept.size());
  if (merged == 0) return 0;
  for (auto& t : mesh.triangles)
    for (int& v : t)
      if (v >= 0 && v < n) v = renumber[first[v]];
  mesh.vertices = std::move(kept);
  if (vertex_lines) *vertex_lines = std::move(kept_lines);
  return merged;
}

}  // namespace stoneskip
