#include "model/coupling/draught.hpp"

#include <algorithm>
#include <cmath>

namespace stoneskip {
namespace {

inline int wrap(int i, int n) {
  i %= n;
  return i < 0 ? i + n : i;
}

// One edge of a projected triangle, oriented so that the triangle's interior is where E > 0.
// e(P) is evaluated from the lexicographically smaller endpoint, so two triangles sharing the
// edge get the same |E| to the bit (model/README.md §2.4 draught; the tie rule in draught.hpp).
struct Edge {
  double lo_x, lo_y, ex, ey;  // e(P) = ex (P.y − lo_y) − ey (P.x − lo_x)
  double sign;                // E = sign · e
  bool owned;                 // top-left rule: points with E = 0 belong to this triangle
  double at(double px, double py) const { return sign * (ex * (py - lo_y) - ey * (px - lo_x)); }
  bool contains(double e) const { return e > 0 || (e == 0 && owned); }
};

Edge make_edge(const Vec3& a, const Vec3& b, double orientation) {
  const bool a_lo = a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  const Vec3& lo = a_lo ? a : b;
  const Vec3& hi = a_lo ? b : a;
  Edge e{lo.x(), lo.y(), hi.x() - lo.x(), hi.y() - lo.y(), (a_lo ? 1.0 : -1.0) * orientation, false};
  // The direction in which the interior lies on the left (counter-clockwise traversal).
  const double dx = e.sign * e.ex, dy = e.sign * e.ey;
  e.owned = dy < 0 || (dy == 0 && dx < 0);  // left edges go down, top edges go left (y up)
  return e;
}

}  // namespace

StoneDraught::StoneDraught(Mesh body_mesh) : mesh_(std::move(body_mesh)) { grid_vertices_.resize(mesh_.vertices.size()); }

DraughtSummary StoneDraught::compute(const Vec3& position_m, const Mat3& rotation, const HeightField& field,
                                     const FieldPlacement& placement, DraughtPatch& out) {
  const HeightFieldOptions& fo = field.options();
  const int nx = fo.nx, ny = fo.ny;
  const double inv_d = 1.0 / fo.cell_m;
  const bool periodic = fo.boundary == Boundary::periodic;
  DraughtSummary summary;
  out.clear();
  if (mesh_.vertices.empty()) return summary;
  // 1. The vertices in grid units (x, y) and metres (z).
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY, zmin = INFINITY;
  for (std::size_t k = 0; k < mesh_.vertices.size(); ++k) {
    const Vec3 w = position_m + rotation * mesh_.vertices[k];  // rigid_state.hpp: world_vertex
    Vec3& g = grid_vertices_[k];
    g = Vec3((w.x() - placement.origin_x_m) * inv_d, (w.y() - placement.origin_y_m) * inv_d, w.z());
    xmin = std::min(xmin, g.x());
    xmax = std::max(xmax, g.x());
    ymin = std::min(ymin, g.y());
    ymax = std::max(ymax, g.y());
    zmin = std::min(zmin, g.z());
  }
  // 2. The box of grid points under the stone's projection.
  if (!std::isfinite(xmin + xmax + ymin + ymax + zmin)) return summary;
  int ilo = static_cast<int>(std::ceil(xmin)), ihi = static_cast<int>(std::floor(xmax));
  int jlo = static_cast<int>(std::ceil(ymin)), jhi = static_cast<int>(std::floor(ymax));
  if (!periodic) {
    ilo = std::max(ilo, 0);
    jlo = std::max(jlo, 0);
    ihi = std::min(ihi, nx - 1);
    jhi = std::min(jhi, ny - 1);
  }
  if (ilo > ihi || jlo > jhi) return summary;
  const int ni = std::min(ihi - ilo + 1, nx), nj = std::min(jhi - jlo + 1, ny);  // folded on a periodic field
  auto height = [&](int i, int j) { return periodic ? field.height(wrap(i, nx), wrap(j, ny)) : field.height(i, j); };
  // 3. Nothing below the water anywhere in the box: no draught (a stone in flight).
  double eta_max = -INFINITY;
  for (int j = jlo; j < jlo + nj; ++j)
    for (int i = ilo; i < ilo + ni; ++i) eta_max = std::max(eta_max, height(i, j));
  if (!(zmin < eta_max)) return summary;
  out.reset(ilo, jlo, ni, nj);
  // 4. Every face that reaches below the water: b += sign · (η − z_face)⁺ over its grid points.
  for (const auto& t : mesh_.triangles) {
    const Vec3& p0 = grid_vertices_[t[0]];
    const Vec3& p1 = grid_vertices_[t[1]];
    const Vec3& p2 = grid_vertices_[t[2]];
    if (std::min({p0.z(), p1.z(), p2.z()}) >= eta_max) continue;  // above the water everywhere here
    const double area2 = (p1.x() - p0.x()) * (p2.y() - p0.y()) - (p1.y() - p0.y()) * (p2.x() - p0.x());
    if (area2 == 0) continue;  // vertical in the world: projects to a segment, no interval
    const double orientation = area2 > 0 ? 1.0 : -1.0;
    const double sign = -orientation;  // n_z < 0 (clockwise from above): an entry, +1; n_z > 0: an exit, −1
    // Edge k is opposite vertex k; E_k is vertex k's barycentric weight times the area.
    const Edge e0 = make_edge(p1, p2, orientation), e1 = make_edge(p2, p0, orientation), e2 = make_edge(p0, p1, orientation);
    int ti0 = static_cast<int>(std::ceil(std::min({p0.x(), p1.x(), p2.x()})));
    int ti1 = static_cast<int>(std::floor(std::max({p0.x(), p1.x(), p2.x()})));
    int tj0 = static_cast<int>(std::ceil(std::min({p0.y(), p1.y(), p2.y()})));
    int tj1 = static_cast<int>(std::floor(std::max({p0.y(), p1.y(), p2.y()})));
    if (!periodic) {
      ti0 = std::max(ti0, 0);
      tj0 = std::max(tj0, 0);
      ti1 = std::min(ti1, nx - 1);
      tj1 = std::min(tj1, ny - 1);
    }
    for (int j = tj0; j <= tj1; ++j)
      for (int i = ti0; i <= ti1; ++i) {
        const double px = i, py = j;
        const double w0 = e0.at(px, py), w1 = e1.at(px, py), w2 = e2.at(px, py);
        if (!(e0.contains(w0) && e1.contains(w1) && e2.contains(w2))) continue;
        const double z_face = (w0 * p0.z() + w1 * p1.z() + w2 * p2.z()) / (w0 + w1 + w2);
        const double depth = height(i, j) - z_face;
        if (depth <= 0) continue;
        const int a = periodic ? wrap(i - ilo, nx) : i - ilo, c = periodic ? wrap(j - jlo, ny) : j - jlo;
        out.at(a, c) += sign * depth;
      }
  }
  // 5. Round-off can leave −1e-17 where an entry and an exit cancel; b ≥ 0 by definition.
  for (double& b : out.b_m) {
    if (b < 0) b = 0;
    if (b > 0) {
      ++summary.points;
      summary.volume_m3 += b;
      summary.max_m = std::max(summary.max_m, b);
    }
  }
  summary.volume_m3 *= fo.cell_m * fo.cell_m;
  summary.wet = summary.points > 0;
  if (!summary.wet) out.clear();
  return summary;
}

double coupled_courant_limit(const Stencil& stencil) { return leapfrog_courant_limit(stencil) / std::sqrt(2.0); }

}  // namespace stoneskip
