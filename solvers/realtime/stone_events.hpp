#pragma once
// The event (root) functions that split a throw into smooth segments: the CVODE reference locates
// them, and the real-time stepper steps to them with KinkSteps::all (stone_stepper.hpp). Still
// water η = 0 for the reference; the real-time stepper holds a live surface fixed during each step
// (stone_stepper.hpp) and clips the faces against it.
//
// The right-hand side of model/README.md §1.3–1.6 is smooth except where
//   (a) a vertex crosses the surface: the clipped polygons change shape (§1.4 step 2). For a
//       slanted face the wetted area is C¹ in the state (piecewise quadratic in the depths, its
//       second derivative jumps), so the force is C¹ there; for a face lying in the surface (a flat
//       face reaching or leaving the water: its three vertices cross together) the area itself
//       jumps, and so does the force. Root function g_j = z_j, vertex j's world height.
//   (b) physical convention only: a wet face's normal velocity u_i = v_i·n_i changes sign, the
//       switch of Eq. 2 (model/stone/water_laws.hpp). Every law is zero at u_i = 0, so the force is
//       continuous; newtonian and nagahiro_hayakawa (∝ max(u_i, 0)²) are C¹ with a jump in the
//       second derivative, planing (∝ max(u_i, 0) |v|) is C⁰ with a jump in the first. Root function
//       g = u_i at the clipped centroid, live only while the face has a vertex under water. The
//       pressure distributions (model/stone/pressure_distribution.hpp) add points of their own,
//       whose switching functions are model/stone/load_switches.hpp's: kinks where the wetted
//       span's ends change vertex, a face switches at its centre of pressure or the planing share
//       reaches 1; jumps of the loads where a face joins or leaves the loaded region (the span is
//       that of the advancing faces); under savitsky_wagner the raised waterline's crossings
//       (depth = −rise) and the kinks where the deepest vertex, which sets the rise, changes. The
//       real-time stepper with KinkSteps::all locates them too and holds the loaded region over
//       each step (LoadMode, fluid_forces.hpp); CVODE steps through them under its error control.
//       The distributions' direction v_h/|v_h| is blended away below planing speed
//       (planing_share), so a stone sinking straight down is no longer a point where the load's
//       derivative is unbounded. In the paper convention every wet face pushes with u_i² whatever
//       its sign — smooth in u_i — so there is nothing to locate.
//   (c) physical convention with air: the disk's normal velocity u = v·n_d changes sign; the
//       air force −C_a ρ_a u|u| S_d n_d (§1.5) is C¹ there. In the paper convention u² is smooth.
// Between events the set of submerged vertices is fixed, so each live root function is smooth.
// (b) and (c) are located only on request (the reference's RestartStrategy::every_event); (a) always (contacts and sinking
// are defined by it, model/README.md §1.8). EventChange::flat_faces says where (a) is a jump of the force.
//
#include <vector>

#include "model/stone/rigid_body.hpp"

namespace stoneskip {

struct EventChange {
  int submerged_before = 0, submerged_after = 0;
  int vertices_under = 0, vertices_out = 0;  // crossings in this event
  int face_switches = 0;                     // (b) events
  int air_switches = 0;                      // (c) events
  int resynced_vertices = 0;  // mode corrected from the state: a crossing root finding missed
  int deepest_new_vertex = -1;               // the deepest vertex that went under, or −1
  // Faces through a vertex crossed in this event whose three vertices all lie within
  // kFlatFace_m of the surface: their wetted area jumps, and with it the force.
  int flat_faces = 0;
  bool force_jumps() const { return flat_faces > 0; }
};

class StoneEvents {
 public:
  // The face and air switches (b), (c) are watched only with locate_switches (the CVODE reference:
  // RestartStrategy::every_event; the real-time stepper: KinkSteps::all).
  // surface (the real-time stepper over live water, held during a step): the faces are clipped, and
  // set_mode's vertices are under, against it; the root functions of the vertices stay z_j.
  StoneEvents(const Stone& stone, const Environment& env, bool locate_switches, const WaterSurface* surface = nullptr);

  int count() const { return static_cast<int>(directions_.size()); }
  int vertex_count() const { return nv_; }

  // Sets the mode from a state: vertex j is under water where z_j < 0 (the start of a throw).
  void reset(const RigidState& s);
  // Only the mode from a state (vertex j under water where z_j < 0), no watched directions: the
  // real-time stepper's view at the start of each step.
  void set_mode(const RigidState& s);
  // Root function k alone at y (the real-time stepper's root search).
  double value(const double* y, int k) const;
  // Root functions at y (kStateSize doubles) into g (count() doubles). False when a value is not
  // finite (the caller fails the solve).
  bool evaluate(const double* y, double* g) const;
  // Updates the mode at a root: found[k] = +1 / −1 where root k was crossed rising / falling.
  // s is the (renormalised) state at the root.
  EventChange apply(const int* found, const RigidState& s);
  // Directions to watch for the next segment (for CVodeSetRootDirection).
  int* directions() { return directions_.data(); }

  int submerged_vertices() const;
  bool vertex_under(int j) const { return under_[j] != 0; }

  // Which root function is which: [0, nv) vertices, then faces (b), then the air switch (c).
  enum class Kind { vertex, face, air };
  Kind kind(int k) const;

 private:
  double depth(const Vec3& world_point) const;  // η − z
  double face_normal_velocity(int i, const RigidState& s, const Mat3& R, const Vec3& omega) const;
  double air_normal_velocity(const RigidState& s, const Mat3& R) const;
  double velocity_scale(const RigidState& s, const Vec3& omega) const;
  bool face_live(int i) const;
  void refresh_directions(const RigidState& s, const std::vector<int>& sign_hint);

  const Stone& stone_;
  const Environment& env_;
  const WaterSurface* surface_ = nullptr;
  int nv_ = 0, nf_ = 0;  // nf_ = 0 when face switches are not located
  bool air_ = false;
  std::vector<char> under_;      // mode: vertex under water
  std::vector<int> sign_;        // faces then air: +1 / −1 the sign in this segment, 0 unknown
  std::vector<int> directions_;  // per root function
  std::vector<std::vector<int>> faces_of_vertex_;
};

}  // namespace stoneskip
