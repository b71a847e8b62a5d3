#pragma once
// Whether a closed, consistently oriented mesh (check_mesh() ok) bounds one solid, so that its
// volume and inertia (the divergence theorem, Eberly 2002) count each point once (an OBJ
// of two overlapping shells counted its volume twice).
//
//  * Shells are the sets of triangles connected through shared vertices.
//  * No two triangles may cross (a proper crossing: an edge of one passes through the inside of the
//    other), whether of one shell (a surface through itself) or of two (shells that overlap).
//    Triangles sharing a vertex are not compared; touching without crossing is allowed.
//  * Shells that do not cross are disjoint or nested. The winding number of the whole surface
//    must be 0 or 1 everywhere (Jacobson et al. 2013, generalized winding numbers): at a vertex of
//    each shell A, the winding number w of the other shells (the sum of their solid angles / 4π,
//    Van Oosterom & Strackee 1983) and w + s_A (s_A = ±1 by the orientation of A) must both be
//    0 or 1. So an outward shell inside another outward shell (volume twice) is refused, an inward
//    shell inside an outward one (a cavity) is allowed.
//  * One piece: a solid that passes the above has one outward shell per piece, so a second
//    outward shell (a box beside the stone, or loose in its cavity) is refused: a stone is one
//    rigid body.
// Triangle pairs are found through a uniform grid over the bounding box, so the check is about
// linear in the triangle count for meshes of evenly sized triangles; a mesh that puts more than
// 2e8 triangle pairs into common cells is not tested for crossings (crossings_checked = false).
#include <string>

#include "model/stone/mesh.hpp"

namespace stoneskip {

struct SolidCheck {
  bool ok = true;
  int shells = 0;
  int pieces = 1;                 // outward shells, where the shells were compared (one solid each)
  bool crossings_checked = true;  // false: more than 2e8 candidate pairs (a fan of long thin
                                  // triangles), the crossing test was not completed
  std::string problem;            // empty when ok
  int at_fault = -1;              // for `problem`, the triangle (0-based) at fault: of two crossing
  int other_at_fault = -1;        // triangles the first and the other; of a shell, its first
};

SolidCheck check_solid(const Mesh& mesh);

// The winding number of a closed triangle surface at p: Σ solid angles / 4π (+1 inside an
// outward-oriented closed surface, 0 outside; non-integer on the surface).
double winding_number(const Mesh& mesh, const std::vector<int>& triangles, const Vec3& p);

}  // namespace stoneskip
