#pragma once
// The stone's draught on the water's grid (model/README.md §2.4): at each grid point (x_i, y_j),
//   b_ij = length of the vertical line through (x_i, y_j) that lies inside the stone and below the
//          water surface z_ij,
// from a closed, outward-oriented triangle mesh in a given pose. Any closed mesh: prism, lens or a
// non-convex OBJ. Along a vertical line the stone is a union of intervals [entry_k, exit_k]; the
// clipped length is Σ_k [(z − entry_k)⁺ − (z − exit_k)⁺]. Entries lie on faces whose outward
// normal points down, exits on faces whose normal points up, so
//   b = Σ over faces above/below the point of  sign · (z − z_face)⁺,  sign = +1 (n_z < 0), −1 (n_z > 0),
// and each triangle is rasterised over the grid points inside its xy-projection (vertical faces
// project to nothing and add nothing). Tie rule, so that a point on an edge shared by two faces
// of one sheet is counted once and a point on a silhouette edge is counted by both sheets or by
// neither: the top-left rule of rasterisers, with each edge's function evaluated from its
// endpoints in a fixed (lexicographic) order, so that two triangles sharing an edge compute it to
// the same bits. Cost: O(Σ triangle footprints) — the grid points under the stone, not the grid.
#include <vector>

#include "model/stone/mesh.hpp"
#include "model/stone/rigid_state.hpp"
#include "model/water/draught_patch.hpp"
#include "model/water/height_field.hpp"

namespace stoneskip {

// Where the field lies in the scene: grid point (i, j) is at (origin_x_m + i d, origin_y_m + j d),
// as in model/water/height_field_surface.hpp.
struct FieldPlacement {
  double origin_x_m = 0, origin_y_m = 0;
};

struct DraughtSummary {
  int points = 0;          // grid points with b > 0
  double volume_m3 = 0;    // Σ b d²
  double max_m = 0;        // largest b
  bool wet = false;        // points > 0
};

// Computes b for a mesh in a pose against a field, into a reusable patch and scratch (no
// allocation once they have grown). The patch covers the bounding box of the stone's projection
// (clipped to the grid on non-periodic fields, folded onto ni ≤ nx, nj ≤ ny on periodic ones); it
// is empty when no part of the stone is below the water there, so a stone in flight costs the
// bounding box only.
class StoneDraught {
 public:
  explicit StoneDraught(Mesh body_mesh);

  DraughtSummary compute(const Vec3& position_m, const Mat3& rotation, const HeightField& field,
                         const FieldPlacement& placement, DraughtPatch& out);
  DraughtSummary compute(const RigidState& pose, const HeightField& field, const FieldPlacement& placement,
                         DraughtPatch& out) {
    // Normalised, as the loads normalise it (rigid_state.hpp): an integrator's quaternion drifts off unit length.
    return compute(pose.position_m, pose.orientation.normalized().toRotationMatrix(), field, placement, out);
  }

  const Mesh& body_mesh() const { return mesh_; }

 private:
  Mesh mesh_;
  std::vector<Vec3> grid_vertices_;  // x, y in grid units (relative to the placement), z in m
};

// The largest σ = cΔt/d for which the leapfrog stays stable where a stone floats on the water
// (model/README.md §2.4): under the footprint b follows z with unit gain, L[z + b] = L[2z], so the Courant
// number there is effectively √2 σ and the limit is the stencil's free limit / √2
// (model/water/stencil.hpp: leapfrog_courant_limit). The coupled operator is L·(1 + χ) with χ the
// footprint's indicator, whose spectral radius is at most twice L's: the limit is sufficient for
// any footprint and necessary as footprints grow.
double coupled_courant_limit(const Stencil& stencil);

}  // namespace stoneskip
