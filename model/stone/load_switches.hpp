#pragma once
// Where the distributed pressure's loads are not smooth in the state, as sign changes of functions
// of the state (model/stone/pressure_distribution.hpp, fluid_forces.cpp). stone_events.hpp's
// switching functions (a vertex crossing the surface, a wet face's flow switching at its clipped
// centroid, the air disk's) are the only non-smooth points of the uniform pressure; the savitsky
// and savitsky_wagner distributions add their own, each the change of one of their decisions:
//   * under savitsky_wagner, a vertex crossing the raised waterline (d_j + rise = 0: a polygon
//     below it changes shape), and the deepest vertex, which sets the rise, changing
//     (d_a − d_b = 0, a the deepest);
//   * a face joining or leaving the loaded region (its normal velocity u at the centroid of its
//     polygon below the raised waterline passes 1e-9 of the speed there, the loads' own test): the
//     span, and with it every face's centre of pressure, can jump;
//   * a face's pressure switching at its centre of pressure (the normal velocity there changes
//     sign);
//   * the span's trailing or leading end passing from one polygon corner to another
//     (s_b − s_a = 0, s = ĥ·x along the horizontal velocity; a corner is a mesh vertex or the
//     point where the raised waterline cuts a mesh edge);
//   * the planing share reaching 1 (|v_h| = √(g b), pressure_distribution.hpp);
//   * under savitsky_wagner, the stone turning over (R₂₂ = 0: the side the rise wets, on_underside
//     in pressure_distribution.hpp, flips), held by the mode like the loaded faces.
// The functions that compare two choices (the deepest vertex, a span end) are defined relative to
// the choice made at a reference state, the *mode*: recorded by reset, then held by evaluate, so
// a step from that state sees the choice change as a sign change. Every function is continuous in
// the state (a corner on an edge is extended along the edge's line beyond its ends), so a sign
// change located on a step's interpolant is where the load changes branch; a value that does not
// exist at a state (a face with no wetted polygon) is NaN and never counts as a sign change.
// Used by the real-time stepper's `all` kinks (solvers/realtime/stone_stepper.hpp); the loads
// themselves do not use this file.
#include <vector>

#include "model/stone/environment.hpp"
#include "model/stone/fluid_forces.hpp"
#include "model/stone/rigid_state.hpp"
#include "model/stone/stone.hpp"
#include "model/stone/triangle_clip.hpp"
#include "model/stone/water_surface.hpp"

namespace stoneskip {

// A corner of a wetted polygon: mesh vertex a (b < 0), or where the waterline cuts the mesh edge
// (a, b), a < b: the raised waterline on a face of the underside (raised), else the surface.
struct PolygonCorner {
  int a = -1, b = -1;
  bool raised = false;
  bool operator==(const PolygonCorner&) const = default;
};

class LoadSwitches {
 public:
  // Active only in the physical convention under savitsky or savitsky_wagner (the uniform pressure
  // and the paper convention have no switches beyond stone_events.hpp's). surface == nullptr:
  // still water.
  LoadSwitches(const Stone& stone, const Environment& env, const WaterSurface* surface = nullptr);
  bool active() const { return active_; }

  // Records the mode of s (the deepest vertex in contact, the span's corners and ends, the loaded
  // faces) and writes the values at s in it. The number of values is fixed until the next reset.
  void reset(const RigidState& s, std::vector<double>& g);
  // The values at s in the recorded mode.
  void evaluate(const RigidState& s, std::vector<double>& g) const;
  // Value k of evaluate(s, g), bit for bit, computing only what it needs: the vertices alone for a
  // crossing of the raised waterline, the deepest vertex, the underside's side and the span's ends,
  // and one face for a face's loaded-region switch (a root search on one function evaluates it
  // alone; evaluate's every face costs several times more). NaN where evaluate's is.
  double value(const RigidState& s, int k) const;

  // The loaded region of the recorded mode, for a right-hand side that holds it over a step (the
  // loads' own choice at the state reset was given).
  const LoadMode& load_mode() const { return mode_.loads; }

  // What value k is (for tests and messages).
  enum class Kind {
    raised_crossing,
    deepest_vertex,
    loaded_face,
    centre_of_pressure,
    planing_share,
    underside_flip,
    span_start,
    span_end
  };
  Kind kind(int k) const;

 private:
  struct Mode {
    int deepest = -1;
    std::vector<PolygonCorner> corners;  // the loaded polygons' corners, each once
    int start = -1, end = -1;            // indices into corners: the span's trailing and leading ends
    LoadMode loads;                      // the loaded faces and the side the rise wets
  };
  void compute(const RigidState& s, Mode* record, const Mode& held, std::vector<double>& g) const;

  // The state's vertices exactly as water_loads computes them (fluid_forces.cpp), and what the
  // distribution makes of them: the deepest vertex, the Wagner rise and the raised depths.
  struct Vertices {
    Mat3 R;
    Vec3 omega;
    std::vector<Vec3> world;
    std::vector<double> depth, raised;
    int deepest = -1;  // -1: no vertices
  };
  void vertices(const RigidState& s, Vertices& v) const;
  // Face i's polygon below the raised waterline (a face on the underside `side`) or the surface,
  // its area and centroid, and the normal velocity u at the centroid (vc the velocity there).
  struct FaceCut {
    bool up = false;   // on the underside: cut at the raised waterline
    double d[3] = {};  // its vertices' depths at that waterline
    Vec3 normal;
    ClippedPolygon poly;
    ClippedArea area;
    Vec3 vc;
    double u = 0;
  };
  // False where the face is dry (then only up and d are set) or its polygon has no area.
  bool cut_face(int i, int side, const RigidState& s, const Vertices& v, FaceCut& f) const;
  // Where corner c lies along the horizontal unit direction dir.
  double along(const PolygonCorner& c, const Vec3& dir, const Vertices& v) const;

  const Stone& stone_;
  const Environment& env_;
  const WaterSurface* surface_;
  bool active_ = false;
  int nv_ = 0, nf_ = 0;
  Mode mode_;
  // Scratch for compute and value, kept so that they allocate nothing once grown: one object is
  // used by one thread at a time (a stepper's or a sliding treatment's own).
  mutable Vertices vertices_;
  mutable std::vector<FaceCut> faces_;
  mutable std::vector<char> loaded_;
  mutable std::vector<double> values_;
};

}  // namespace stoneskip
