#pragma once
// The head h = p_s / (ρ_w g) that the stone's faces press on the water with (model/README.md §2.4,
// pressure coupling), rasterised conservatively on the water's grid. Each wetted face i pushes the
// stone with F_i (model/stone/fluid_forces.hpp, FacePush); the water receives −F_i, whose vertical
// part is spread uniformly over the xy-projection P_i of the face's wetted polygon:
//   p_s = F_z,i / |P_i|   on P_i,
// and grid point (i, j) receives the pressure integrated over its cell [i − ½, i + ½] × [j − ½, j + ½]
// (in cell units), divided by the cell's area: h_ij = Σ_i F_z,i |P_i ∩ cell_ij| / (|P_i| ρ_w g d²).
// The cell overlaps of one polygon sum to |P_i| (Sutherland–Hodgman clipping of a convex polygon
// against each cell square, shoelace areas), so Σ_ij h_ij ρ_w g d² = Σ_i F_z,i to round-off: the
// water receives the stone's vertical force, equal and opposite, however the stone lies on the
// grid, and a stone a few cells wide spreads over the cells it covers instead of aliasing onto
// the grid points it happens to cover (the point-sampled draught's checkerboard).
// A face pressing down on the stone (F_z,i < 0, a wetted top face) pulls the water up: h < 0.
#include <vector>

#include "model/coupling/draught.hpp"
#include "model/stone/fluid_forces.hpp"
#include "model/water/draught_patch.hpp"

namespace stoneskip {

struct PressureHeadSummary {
  double force_N = 0;       // Σ_i F_z,i: the vertical force the faces put on the stone
  double rastered_N = 0;    // Σ_ij h_ij ρ_w g d²: what the grid received (= force_N to round-off)
  int faces = 0;            // faces with a projection of positive area
  bool wet() const { return faces > 0; }
};

// Writes h (m) into `out`, a box covering the projections (the box may reach outside the grid: the
// field's own rules apply, model/water/draught_patch.hpp). rho_g = ρ_w g (N/m³).
PressureHeadSummary rasterise_pressure_head(const std::vector<FacePush>& pushes, double cell_m,
                                            const FieldPlacement& placement, double rho_g, DraughtPatch& out);

// Spreads a head patch with the binomial filter ([1 2 1]/4 along x, then along y) `passes` times,
// conservatively: Σ h is kept to round-off, the box grows by one point on each side per pass.
// Its transfer function is cos²(a/2) cos²(b/2) per pass (a = k_x d, b = k_y d): 1 at |k| → 0,
// ≤ ½ per axis at half the grid's Nyquist (a = π/2), 0 at the checkerboard (a = b = π). A stone a
// few cells wide projects onto the grid mostly at those wavenumbers, which the leapfrog carries
// slowly and wrongly (its dispersion); a pass or two moves the forcing's energy to the waves the
// grid resolves. scratch: reused storage.
void smooth_conservatively(DraughtPatch& patch, int passes, std::vector<double>& scratch);

// A walled (non-periodic) pond of nx × ny points: the head's points beyond the rim are dropped (a
// stone beyond the rim presses on no water; the box shrinks to its part on the grid).
void drop_beyond_rim(DraughtPatch& patch, int nx, int ny, std::vector<double>& scratch);

// A walled pond: the head's points beyond the rim moved onto the grid, each onto its mirror image
// in the wall (i → −1 − i below, i → 2 nx − 1 − i above: the reflecting wall's ghost, model/README.md
// §2.1; repeated for a spill wider than the grid), so that smoothing next to a wall keeps Σ h
// (smooth_conservatively spills past the rim). The box becomes one on the grid.
void fold_onto_walled_grid(DraughtPatch& patch, int nx, int ny, std::vector<double>& scratch);

// The area of the part of a convex polygon (xy, cell units, at most 8 vertices, either winding)
// inside the square [i − ½, i + ½] × [j − ½, j + ½].
double overlap_with_cell(const double* x, const double* y, int count, int i, int j);

}  // namespace stoneskip
