#pragma once
// The stone's draught b ≥ 0 on the grid (model/README.md §2.4), as the height field receives it: a box of
// grid points, so that a forced step costs O(box), not O(grid). Value (a, c) of the box belongs
// to grid point (i0 + a, j0 + c); on a periodic field the index wraps, on other fields points
// outside the grid are ignored (a stone beyond the rim does not touch the pond). Whoever fills a
// patch for a periodic field keeps ni ≤ nx and nj ≤ ny, so that no grid point appears twice
// (model/coupling/draught.hpp does). How b is obtained (from a stone mesh, or prescribed for a
// reference) is not the field's business.
#include <cstddef>
#include <vector>

namespace stoneskip {

struct DraughtPatch {
  int i0 = 0, j0 = 0;  // grid index of the box's first point (may lie outside the grid)
  int ni = 0, nj = 0;  // box size in points
  std::vector<double> b_m;  // ni·nj values, a fastest

  bool empty() const { return ni <= 0 || nj <= 0; }
  double& at(int a, int c) { return b_m[static_cast<std::size_t>(c) * ni + a]; }
  double at(int a, int c) const { return b_m[static_cast<std::size_t>(c) * ni + a]; }
  // A zero box of the given size (keeps the storage: no allocation once it has grown).
  void reset(int first_i, int first_j, int size_i, int size_j) {
    i0 = first_i;
    j0 = first_j;
    ni = size_i > 0 ? size_i : 0;
    nj = size_j > 0 ? size_j : 0;
    b_m.assign(static_cast<std::size_t>(ni) * nj, 0.0);
  }
  void clear() { reset(0, 0, 0, 0); }
  // Σ b d² over the box: the displaced volume the field sees (m³).
  double volume_m3(double cell_m) const {
    double s = 0;
    for (double v : b_m) s += v;
    return s * cell_m * cell_m;
  }
};

}  // namespace stoneskip
