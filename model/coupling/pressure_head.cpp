#include "model/coupling/pressure_head.hpp"

#include <algorithm>
#include <cmath>

namespace stoneskip {

namespace {

constexpr int kMaxVertices = 16;  // a convex polygon of ≤ 4 vertices clipped by 4 half-planes: ≤ 8

// Signed shoelace area of a polygon.
double signed_area(const double* x, const double* y, int n) {
  double a = 0;
  for (int k = 0; k < n; ++k) {
    const int l = k + 1 == n ? 0 : k + 1;
    a += x[k] * y[l] - x[l] * y[k];
  }
  return 0.5 * a;
}

// Keeps the part of the polygon where s·(coordinate) ≤ s·bound (axis 0: x, 1: y), Sutherland–Hodgman.
int clip_half_plane(const double* x, const double* y, int n, int axis, double bound, double sign, double* ox,
                    double* oy) {
  int m = 0;
  for (int k = 0; k < n; ++k) {
    const int l = k + 1 == n ? 0 : k + 1;
    const double ck = axis == 0 ? x[k] : y[k], cl = axis == 0 ? x[l] : y[l];
    const double fk = sign * (bound - ck), fl = sign * (bound - cl);  // ≥ 0 inside
    if (fk >= 0) {
      ox[m] = x[k];
      oy[m] = y[k];
      ++m;
    }
    if ((fk >= 0) != (fl >= 0)) {
      const double t = fk / (fk - fl);
      ox[m] = x[k] + t * (x[l] - x[k]);
      oy[m] = y[k] + t * (y[l] - y[k]);
      ++m;
    }
  }
  return m;
}

}  // namespace

double overlap_with_cell(const double* x, const double* y, int count, int i, int j) {
  double ax[kMaxVertices], ay[kMaxVertices], bx[kMaxVertices], by[kMaxVertices];
  int n = clip_half_plane(x, y, count, 0, i + 0.5, 1, ax, ay);
  n = clip_half_plane(ax, ay, n, 0, i - 0.5, -1, bx, by);
  n = clip_half_plane(bx, by, n, 1, j + 0.5, 1, ax, ay);
  n = clip_half_plane(ax, ay, n, 1, j - 0.5, -1, bx, by);
  return n < 3 ? 0.0 : std::abs(signed_area(bx, by, n));
}

void smooth_conservatively(DraughtPatch& p, int passes, std::vector<double>& scratch) {
  for (int pass = 0; pass < passes && !p.empty(); ++pass) {
    const int ni = p.ni + 2, nj = p.nj + 2;
    // Along x into scratch (ni × p.nj), then along y into the patch (ni × nj).
    scratch.assign(static_cast<std::size_t>(ni) * p.nj, 0.0);
    for (int c = 0; c < p.nj; ++c)
      for (int a = 0; a < p.ni; ++a) {
        const double h = p.at(a, c);
        double* row = &scratch[static_cast<std::size_t>(c) * ni];
        row[a] += 0.25 * h;
        row[a + 1] += 0.5 * h;
        row[a + 2] += 0.25 * h;
      }
    const int old_nj = p.nj;
    p.reset(p.i0 - 1, p.j0 - 1, ni, nj);
    for (int c = 0; c < old_nj; ++c)
      for (int a = 0; a < ni; ++a) {
        const double h = scratch[static_cast<std::size_t>(c) * ni + a];
        p.at(a, c) += 0.25 * h;
        p.at(a, c + 1) += 0.5 * h;
        p.at(a, c + 2) += 0.25 * h;
      }
  }
}

namespace {

// The mirror image of index i in walls at −½ and n − ½ (the reflecting wall's ghost: −1 ↔ 0, n ↔ n − 1).
int mirror_into(int i, int n) {
  while (i < 0 || i >= n) i = i < 0 ? -1 - i : 2 * n - 1 - i;
  return i;
}

// Rebuilds p as a box on the grid holding each point's value at map(i), map(j) (skipped where
// keep is false), summed where two points land on one.
template <class Map>
void remap_onto_grid(DraughtPatch& p, int nx, int ny, std::vector<double>& scratch, Map map) {
  if (p.empty()) return;
  if (p.i0 >= 0 && p.j0 >= 0 && p.i0 + p.ni <= nx && p.j0 + p.nj <= ny) return;  // already on the grid
  int ilo = nx, ihi = -1, jlo = ny, jhi = -1;
  for (int c = 0; c < p.nj; ++c)
    for (int a = 0; a < p.ni; ++a) {
      int i = p.i0 + a, j = p.j0 + c;
      if (!map(i, j)) continue;
      ilo = std::min(ilo, i), ihi = std::max(ihi, i), jlo = std::min(jlo, j), jhi = std::max(jhi, j);
    }
  scratch = p.b_m;
  const int i0 = p.i0, j0 = p.j0, ni = p.ni, nj = p.nj;
  if (ihi < ilo || jhi < jlo) {
    p.clear();
    return;
  }
  p.reset(ilo, jlo, ihi - ilo + 1, jhi - jlo + 1);
  for (int c = 0; c < nj; ++c)
    for (int a = 0; a < ni; ++a) {
      int i = i0 + a, j = j0 + c;
      if (map(i, j)) p.at(i - ilo, j - jlo) += scratch[static_cast<std::size_t>(c) * ni + a];
    }
}

}  // namespace

void drop_beyond_rim(DraughtPatch& p, int nx, int ny, std::vector<double>& scratch) {
  remap_onto_grid(p, nx, ny, scratch, [&](int& i, int& j) { return i >= 0 && i < nx && j >= 0 && j < ny; });
}

void fold_onto_walled_grid(DraughtPatch& p, int nx, int ny, std::vector<double>& scratch) {
  remap_onto_grid(p, nx, ny, scratch, [&](int& i, int& j) {
    i = mirror_into(i, nx);
    j = mirror_into(j, ny);
    return true;
  });
}

PressureHeadSummary rasterise_pressure_head(const std::vector<FacePush>& pushes, double cell_m,
                                            const FieldPlacement& placement, double rho_g, DraughtPatch& out) {
  PressureHeadSummary summary;
  // The box: cells whose squares meet any projection.
  int ilo = 0, ihi = -1, jlo = 0, jhi = -1;
  bool any = false;
  for (const FacePush& p : pushes) {
    for (int k = 0; k < p.wetted.count; ++k) {
      const double u = (p.wetted.vertices[k].x() - placement.origin_x_m) / cell_m;
      const double v = (p.wetted.vertices[k].y() - placement.origin_y_m) / cell_m;
      const int i = static_cast<int>(std::floor(u + 0.5)), j = static_cast<int>(std::floor(v + 0.5));
      if (!any) {
        ilo = ihi = i;
        jlo = jhi = j;
        any = true;
      }
      ilo = std::min(ilo, i);
      ihi = std::max(ihi, i);
      jlo = std::min(jlo, j);
      jhi = std::max(jhi, j);
    }
  }
  if (!any) {
    out.clear();
    return summary;
  }
  out.reset(ilo, jlo, ihi - ilo + 1, jhi - jlo + 1);
  for (const FacePush& p : pushes) {
    const int n = p.wetted.count;
    if (n < 3) continue;
    // Cell units relative to a cell near the polygon, so that the clipped areas are computed from
    // coordinates of a few cells (a pond's far corner is hundreds of cells from its origin).
    const double u0 = (p.wetted.vertices[0].x() - placement.origin_x_m) / cell_m;
    const double v0 = (p.wetted.vertices[0].y() - placement.origin_y_m) / cell_m;
    const int iref = static_cast<int>(std::floor(u0)), jref = static_cast<int>(std::floor(v0));
    double x[4], y[4];
    for (int k = 0; k < n; ++k) {
      x[k] = (p.wetted.vertices[k].x() - placement.origin_x_m) / cell_m - iref;
      y[k] = (p.wetted.vertices[k].y() - placement.origin_y_m) / cell_m - jref;
    }
    const double area = std::abs(signed_area(x, y, n));  // |P_i| in cell units
    if (!(area > 0)) continue;  // a vertical face: no vertical force to spread
    const double fz = p.force_N.z();
    summary.force_N += fz;
    ++summary.faces;
    // h per unit of overlap (a fraction of a cell): F_z / (|P_i| d² ρ g).
    const double head_per_overlap = fz / (area * cell_m * cell_m * rho_g);
    const auto [xmin, xmax] = std::minmax_element(x, x + n);
    const auto [ymin, ymax] = std::minmax_element(y, y + n);
    const int i0 = static_cast<int>(std::floor(*xmin + 0.5)), i1 = static_cast<int>(std::floor(*xmax + 0.5));
    const int j0 = static_cast<int>(std::floor(*ymin + 0.5)), j1 = static_cast<int>(std::floor(*ymax + 0.5));
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) {
        const double a = overlap_with_cell(x, y, n, i, j);
        if (a > 0) out.at(i + iref - ilo, j + jref - jlo) += head_per_overlap * a;
      }
  }
  double sum = 0;
  for (double h : out.b_m) sum += h;
  summary.rastered_N = sum * rho_g * cell_m * cell_m;
  return summary;
}

}  // namespace stoneskip
