#include "tools/scene/mesh_solid.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace stoneskip {

namespace {

struct Box {
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  void add(const Vec3& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void add(const Box& b) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
  bool overlaps(const Box& b) const { return (lo.array() <= b.hi.array()).all() && (b.lo.array() <= hi.array()).all(); }
  bool contains(const Vec3& p) const { return (lo.array() <= p.array()).all() && (p.array() <= hi.array()).all(); }
};

int find(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

// Signed volume of the tetrahedron (a, b, c, d) × 6.
double orient(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return (b - a).dot((c - a).cross(d - a)); }

// Candidate pairs (triangles in one grid cell) examined before the crossing check gives up: a fan
// of long thin triangles (all through one apex) puts every pair in one cell.
constexpr long long kMaxCandidatePairs = 200'000'000;

int sign(double v, double eps) { return v > eps ? 1 : (v < -eps ? -1 : 0); }

// Segment pq passes through the inside of triangle abc (strictly: touching is not crossing).
bool segment_crosses(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c, double eps) {
  const int sp = sign(orient(a, b, c, p), eps), sq = sign(orient(a, b, c, q), eps);
  if (sp == 0 || sq == 0 || sp == sq) return false;
  const int s1 = sign(orient(p, q, a, b), eps), s2 = sign(orient(p, q, b, c), eps), s3 = sign(orient(p, q, c, a), eps);
  return s1 != 0 && s1 == s2 && s2 == s3;
}

bool triangles_cross(const Mesh& m, int i, int j, double eps) {
  const auto& t = m.triangles[i];
  const auto& u = m.triangles[j];
  const Vec3 &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
  const Vec3 &d = m.vertices[u[0]], &e = m.vertices[u[1]], &f = m.vertices[u[2]];
  return segment_crosses(a, b, d, e, f, eps) || segment_crosses(b, c, d, e, f, eps) || segment_crosses(c, a, d, e, f, eps) ||
         segment_crosses(d, e, a, b, c, eps) || segment_crosses(e, f, a, b, c, eps) || segment_crosses(f, d, a, b, c, eps);
}

bool share_vertex(const std::array<int, 3>& t, const std::array<int, 3>& u) {
  for (int a : t)
    for (int b : u)
      if (a == b) return true;
  return false;
}

}  // namespace

double winding_number(const Mesh& mesh, const std::vector<int>& triangles, const Vec3& p) {
  // Van Oosterom & Strackee 1983: tan(Ω/2) = a·(b×c) / (|a||b||c| + (a·b)|c| + (a·c)|b| + (b·c)|a|).
  double sum = 0;
  for (int k : triangles) {
    const auto& t = mesh.triangles[k];
    const Vec3 a = mesh.vertices[t[0]] - p, b = mesh.vertices[t[1]] - p, c = mesh.vertices[t[2]] - p;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double num = a.dot(b.cross(c));
    const double den = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
    sum += 2 * std::atan2(num, den);
  }
  return sum / (4 * M_PI);
}

SolidCheck check_solid(const Mesh& m) {
  SolidCheck out;
  const int nt = static_cast<int>(m.triangles.size());
  if (nt == 0) return out;

  // 1. Shells: triangles joined through shared vertices.
  std::vector<int> parent(m.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& t : m.triangles) {
    const int r0 = find(parent, t[0]);
    for (int k = 1; k < 3; ++k) parent[find(parent, t[k])] = r0;
  }
  std::vector<int> shell_of(nt), root_to_shell(m.vertices.size(), -1);
  std::vector<std::vector<int>> shells;
  for (int i = 0; i < nt; ++i) {
    const int r = find(parent, m.triangles[i][0]);
    if (root_to_shell[r] < 0) {
      root_to_shell[r] = static_cast<int>(shells.size());
      shells.emplace_back();
    }
    shell_of[i] = root_to_shell[r];
    shells[shell_of[i]].push_back(i);
  }
  out.shells = static_cast<int>(shells.size());

  std::vector<Box> tri_box(nt);
  Box all;
  double mean_extent = 0;
  for (int i = 0; i < nt; ++i) {
    for (int v : m.triangles[i]) tri_box[i].add(m.vertices[v]);
    all.add(tri_box[i]);
    mean_extent += (tri_box[i].hi - tri_box[i].lo).maxCoeff();
  }
  mean_extent /= nt;
  const double size = (all.hi - all.lo).norm();
  if (!(size > 0) || !std::isfinite(size)) return out;
  const double eps = 1e-12 * size * size * size;  // orient() is a volume × 6: round-off of the mesh's scale

  // 2. Crossing triangles, found through a uniform grid of cells about the mean triangle size.
  // At most about two cells per triangle, so the grid's memory stays linear too.
  const Vec3 extent = all.hi - all.lo;
  double cell = std::max(mean_extent, size * 1e-6);
  auto cells_along = [&](double e) { return std::max(1.0, std::floor(e / cell) + 1); };
  while (cells_along(extent.x()) * cells_along(extent.y()) * cells_along(extent.z()) > 2.0 * nt + 64) cell *= 1.5;
  const int n[3] = {static_cast<int>(cells_along(extent.x())), static_cast<int>(cells_along(extent.y())),
                    static_cast<int>(cells_along(extent.z()))};
  auto cell_of = [&](const Vec3& p, int axis) {
    return std::clamp(static_cast<int>((p[axis] - all.lo[axis]) / cell), 0, n[axis] - 1);
  };
  long long candidates = 0;
  std::vector<std::vector<int>> grid(static_cast<std::size_t>(n[0]) * n[1] * n[2]);
  auto index = [&](int x, int y, int z) { return (static_cast<std::size_t>(z) * n[1] + y) * n[0] + x; };
  for (int i = 0; i < nt; ++i)
    for (int z = cell_of(tri_box[i].lo, 2); z <= cell_of(tri_box[i].hi, 2); ++z)
      for (int y = cell_of(tri_box[i].lo, 1); y <= cell_of(tri_box[i].hi, 1); ++y)
        for (int x = cell_of(tri_box[i].lo, 0); x <= cell_of(tri_box[i].hi, 0); ++x) grid[index(x, y, z)].push_back(i);
  for (int z = 0; z < n[2]; ++z)
    for (int y = 0; y < n[1]; ++y)
      for (int x = 0; x < n[0]; ++x) {
        const auto& in = grid[index(x, y, z)];
        for (std::size_t a = 0; a < in.size(); ++a)
          for (std::size_t b = a + 1; b < in.size(); ++b) {
            const int i = in[a], j = in[b];
            if (++candidates > kMaxCandidatePairs) {
              out.crossings_checked = false;
              goto nesting;
            }
            if (share_vertex(m.triangles[i], m.triangles[j]) || !tri_box[i].overlaps(tri_box[j])) continue;
            // Each pair once: in the cell holding the low corner of the boxes' overlap.
            const Vec3 low = tri_box[i].lo.cwiseMax(tri_box[j].lo);
            if (cell_of(low, 0) != x || cell_of(low, 1) != y || cell_of(low, 2) != z) continue;
            if (!triangles_cross(m, i, j, eps)) continue;
            out.ok = false;
            out.at_fault = i;
            out.other_at_fault = j;
            if (shell_of[i] == shell_of[j])
              out.problem = "triangles " + std::to_string(i + 1) + " and " + std::to_string(j + 1) +
                            " cross each other (the surface passes through itself)";
            else
              out.problem = "shells " + std::to_string(shell_of[i] + 1) + " and " + std::to_string(shell_of[j] + 1) +
                            " cross each other (triangles " + std::to_string(i + 1) + " and " + std::to_string(j + 1) +
                            "): the volume inside both would be counted twice";
            return out;
          }
      }

nesting:
  // 3. Nesting: the winding number of the whole surface must be 0 or 1 on both sides of each shell.
  if (shells.size() < 2) return out;
  std::vector<Box> shell_box(shells.size());
  std::vector<double> shell_volume(shells.size(), 0.0);
  for (std::size_t s = 0; s < shells.size(); ++s)
    for (int k : shells[s]) {
      shell_box[s].add(tri_box[k]);
      const auto& t = m.triangles[k];
      shell_volume[s] += m.vertices[t[0]].dot(m.vertices[t[1]].cross(m.vertices[t[2]])) / 6;
    }
  for (std::size_t a = 0; a < shells.size(); ++a) {
    const Vec3& p = m.vertices[m.triangles[shells[a][0]][0]];
    double w = 0;
    for (std::size_t b = 0; b < shells.size(); ++b) {
      if (b == a || !shell_box[b].contains(p)) continue;
      const double wb = winding_number(m, shells[b], p);
      if (std::abs(wb - std::round(wb)) > 1e-6) {
        out.ok = false;
        out.at_fault = shells[a][0];
        out.problem = "shells " + std::to_string(a + 1) + " and " + std::to_string(b + 1) +
                      " touch or overlap (a vertex of one lies on the surface of the other)";
        return out;
      }
      w += std::round(wb);
    }
    const double s_a = shell_volume[a] >= 0 ? 1 : -1;
    const bool inside_ok = (w == 0 || w == 1) && (w + s_a == 0 || w + s_a == 1);
    if (!inside_ok) {
      out.ok = false;
      out.at_fault = shells[a][0];
      out.problem = "shell " + std::to_string(a + 1) + " (of " + std::to_string(shells.size()) + ") lies " +
                    (w >= 1 ? "inside another shell with the same orientation: the volume inside both would be counted twice"
                            : "outside every other shell but is inward-oriented (a cavity with no solid around it)");
      return out;
    }
  }
  // 4. One piece: in a solid that passed 3 each piece has one outward shell (its outside; the
  // inward ones are its cavities), so a second outward shell is a second piece, apart from the
  // first or loose inside its cavity. A stone is one rigid body: two pieces would be carried as one,
  // their gap rigid (an exported scene's other object, taken for part of the stone).
  std::vector<int> outward;
  for (std::size_t s = 0; s < shells.size(); ++s)
    if (shell_volume[s] > 0) outward.push_back(static_cast<int>(s));
  out.pieces = static_cast<int>(outward.size());
  if (outward.size() > 1) {
    out.ok = false;
    out.at_fault = shells[outward[1]][0];
    out.problem = "the mesh is " + std::to_string(outward.size()) + " separate pieces (shells " + std::to_string(outward[0] + 1) +
                  " and " + std::to_string(outward[1] + 1) +
                  " each bound a solid of their own): a stone is one rigid piece (another object exported with it?)";
  }
  return out;
}

}  // namespace stoneskip
