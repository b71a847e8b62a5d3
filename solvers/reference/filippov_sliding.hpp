#pragma once
// A sliding mode on one face's loaded-region switch, solved as Filippov's differential inclusion
// (A. F. Filippov, Differential Equations with Discontinuous Righthand Sides, Kluwer 1988; the
// event-driven treatment of P. T. Piiroinen & Yu. A. Kuznetsov, "An event-driven method to simulate
// Filippov systems with accurate computing of sliding motions", ACM TOMS 34(3), 2008).
//
// Under the savitsky distributions a face belongs to the loaded region while its normal velocity
// at the centroid of its polygon below the raised waterline is advancing, g = u − 1e-9 |v_c| > 0
// (model/stone/load_switches.hpp, fluid_forces.cpp), and the region's extent sets every face's
// centre of pressure: the loads jump where g changes sign. Where the loads with the face out
// (f₀, on g < 0) raise g and the loads with it in (f₁, on g > 0) lower it, both fields point at
// g = 0 and the state cannot leave it: an implicit or explicit step straddles the switch whatever
// its size, and the step collapses (a lens stone's planing exit, solvers/README.md). Filippov's
// solution moves along the switch with the convex combination that keeps g constant:
//   ẏ = (1 − α) f₀(y) + α f₁(y),   α = a₀ / (a₀ − a₁),   a_i = ∇g · f_i   (Filippov's convex method),
// which exists while a₀ > 0 > a₁; the sliding ends where one field turns tangent: the root of
// exit(y) = min(a₀, −a₁) (Piiroinen & Kuznetsov's exit condition). The other faces keep the loads'
// own choice at each state; α ∈ [0, 1] makes the combination as passive as its two ends.
// After the exit the state leaves along the field that turned tangent, so g departs from zero only
// quadratically and its sign there is round-off: the face is *held* on the side it leaves to (out
// where a₀ reached zero, in where a₁ did) until g crosses zero against the hold, a located root.
// Only one switch at zero is treated: where two faces' switches are at zero at once (the twin faces
// of a mirror-symmetric throw), the sliding field is not unique (Filippov 1988; L. Dieci &
// L. Lopez, SIAM J. Numer. Anal. 47(3), 2009) and attracting_face says so.
// a_i is the central difference of g along f_i over ±kDirectionalStep_s. g is smooth in the state
// away from a vertex crossing the raised waterline; round-off in g (world positions of metres) over
// 2ε dominates the truncation error: ~1e-7 of a typical a_i of 1–10 m/s², ample for α and for the
// exit function's sign.
#include <string>
#include <vector>

#include "model/stone/environment.hpp"
#include "model/stone/fluid_forces.hpp"
#include "model/stone/load_switches.hpp"
#include "model/stone/rigid_state.hpp"
#include "model/stone/stone.hpp"

namespace stoneskip {

constexpr double kDirectionalStep_s = 1e-7;  // the central difference's step along a field (time)
// A switch is at zero where |g| is below this (m/s). Where the step collapses at a sliding mode the
// state chatters within ~|a| h of the switch, h the collapsed step (measured |g| ~ 1e-11 m/s); a
// switch farther from zero than this is not what stopped the step.
constexpr double kAtSwitch_m_s = 1e-6;

// The choice made where a solve's step collapsed: the face to slide on, or why there is none.
struct SlidingChoice {
  int face = -1;          // −1: no single switch at zero attracts from both sides here
  double g = 0;           // the face's switch value there
  double a0 = 0, a1 = 0;  // ∇g · f₀ and ∇g · f₁ there
  std::string why;        // when face < 0: what was found instead
};

// The sliding field and its exit function at one state.
struct SlidingField {
  double alpha = 0;  // the weight of f₁ (clamped to [0, 1])
  double exit = -1;  // min(a₀, −a₁); −1 where the face has no wetted polygon (g undefined)
};

class FilippovSliding {
 public:
  // Still water (the reference's). Available only where LoadSwitches is active (physical
  // convention, a savitsky distribution).
  FilippovSliding(const Stone& stone, const Environment& env);
  bool available() const { return switches_.active(); }

  // The one loaded-face switch at zero at s (|g| ≤ kAtSwitch_m_s), tested for attraction from both
  // sides (a₀ > 0 > a₁); none where no switch, or more than one, is at zero.
  SlidingChoice attracting_face(const RigidState& s);

  // The sliding field of `face` at y (kStateSize doubles) into dydt; its α and exit value.
  SlidingField field(int face, const double* y, double* dydt);
  // The exit value alone (the root function), at y.
  double exit_value(int face, const double* y);

  // At a sliding's exit: the side the state leaves to (0: out, where a₀ reached zero; 1: in, where
  // a₁ did).
  int leaving_side(int face, const double* y);
  // Held on `side` after an exit: the loads with the face so held, and the hold's root function,
  // positive while g lies on that side (−g for side 0, g for side 1), and −1 where the face has no
  // wetted polygon (the hold ends there).
  void held_rhs(int face, int side, const double* y, double* dydt);
  double held_value(int face, int side, const double* y);

 private:
  // The two fields at y, the face out (f₀) and in (f₁), and their rates a₀, a₁ toward its switch.
  struct Sides {
    StateVector f0{}, f1{};
    double a0 = 0, a1 = 0;
  };
  Sides sides(int face, const double* y);
  // ∇g · f for the face's switch, f at y (central difference); NaN where g is undefined.
  double rate_along(int face, const double* y, const double* f);
  void rhs_with_face(int face, char loaded, const double* y, double* dydt);
  double switch_value(int face, const double* y);
  std::size_t index_of(int face) const;  // the face's loaded_face value among LoadSwitches' values

  const Stone& stone_;
  const Environment& env_;
  LoadSwitches switches_;
  LoadMode mode_;
  std::vector<double> g_;
};

}  // namespace stoneskip
