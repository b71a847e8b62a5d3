#pragma once
// Forces of the water and the air on the stone, as functions of a state (model/README.md §1.4–1.6). Both the
// real-time stepper and the CVODE reference call these.
#include <vector>

#include "model/stone/environment.hpp"
#include "model/stone/rigid_state.hpp"
#include "model/stone/triangle_clip.hpp"
#include "model/stone/water_surface.hpp"

namespace stoneskip {

struct WaterLoads {
  Vec3 force_N = Vec3::Zero();
  Vec3 torque_N_m = Vec3::Zero();   // about the centre of mass
  double wetted_area_m2 = 0;        // Σ S_i
  int wet_triangles = 0;            // triangles with S_i > 0
  int submerged_vertices = 0;       // vertices with d_j > 0
  int vertex_count = 0;
  double deepest_depth_m = 0;       // max_j d_j (> 0: in contact); −(clearance) when above
  bool in_contact() const { return deepest_depth_m > 0; }
  bool fully_submerged() const { return submerged_vertices == vertex_count && vertex_count > 0; }
};

// What one wetted face presses on the water with (the scene's pressure coupling, model/README.md
// §2.4): the force F_i the water puts on the stone through that face, and the wetted polygon it
// acts on (clipped below the raised waterline where the Wagner rise is modelled). The water
// receives −F_i; its vertical part spread over the polygon's xy-projection is the face's surface
// pressure.
struct FacePush {
  ClippedPolygon wetted;
  Vec3 force_N = Vec3::Zero();
};

// The distributed pressure's discrete choices that make its loads jump: which faces form the
// loaded region (advancing into the water at their wetted centroid, fluid_forces.cpp), whose extent
// sets every face's centre of pressure. A stepper that locates where that choice changes
// (model/stone/load_switches.hpp) holds it over a step, so that each of the step's stages sees one
// smooth branch of the loads; without a mode the loads decide it from the state.
struct LoadMode {
  // Per face: 1 part of the loaded region, 0 not, kDecide (a face that had no wetted polygon when
  // the mode was taken) decided from the state as without a mode.
  static constexpr char kDecide = 2;
  std::vector<char> loaded_faces;
  // The side the Wagner rise wets (underside_side in pressure_distribution.hpp): ±1 held, 0 decided
  // from the state. It flips only with the stone on edge (R₂₂ = 0), where the raised faces jump.
  int underside = 0;
};

struct AirLoads {
  Vec3 force_N = Vec3::Zero();  // torque is zero in both conventions (model/README.md §1.6, Eq. 7)
};

// Σ over triangles of the water force (model/README.md §1.4; Lee & Baek 2013 Eq. 1–5) on the exactly clipped
// wetted part of each triangle.
// physical: v_i = v + ω × r_i, only faces with u_i = v_i·n_i > 0 push, with env.water_law's
//           pressure (model/stone/water_laws.hpp: F_i = −p_i S_i n_i) acting where
//           env.pressure_distribution puts it (model/stone/pressure_distribution.hpp), τ_i = r_i × F_i.
// paper:    v_i = v + r_i × ω (Eq. 1 as printed), every submerged face pushes with −C_w ρ_w u_i² S_i n_i
//           (Eq. 2 as printed, whatever env.water_law says: environment_problem() refuses another
//           law with this convention), τ_i = F_i × r_i (Eq. 3 as printed).
// surface == nullptr: still water η = 0. Below the stone's bounding sphere nothing is evaluated.
// pushes (optional): cleared, then one FacePush per face that pushes (Σ force_N = force_N).
// mode (optional): the loaded region held (LoadMode); only the savitsky distributions read it.
WaterLoads water_loads(const Stone& stone, const Environment& env, const RigidState& s,
                       const WaterSurface* surface = nullptr, std::vector<FacePush>* pushes = nullptr,
                       const LoadMode* mode = nullptr);

// The same from the vertices' world positions and signed depths (d_j = η − z_j), the rotation R
// of s and the world angular velocity ω: for callers that already have them.
WaterLoads water_loads_from_depths(const Stone& stone, const Environment& env, const RigidState& s, const Mat3& R,
                                   const Vec3& omega, const std::vector<Vec3>& world_m,
                                   const std::vector<double>& depth_m, std::vector<FacePush>* pushes = nullptr,
                                   const LoadMode* mode = nullptr);

// Disk air model (model/README.md §1.5; Eq. 6): u = v·n_d;
// physical: F = −C_a ρ_a u|u| S_d n_d;  paper: F = −C_a ρ_a u² S_d n_d (always along −n_d).
AirLoads air_loads(const Stone& stone, const Environment& env, const RigidState& s);

}  // namespace stoneskip
