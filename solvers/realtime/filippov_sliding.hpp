#pragma once
// A sliding mode on one face's loaded-region switch, or on two at once, solved as Filippov's
// differential inclusion (A. F. Filippov, Differential Equations with Discontinuous Righthand
// Sides, Kluwer 1988; the event-driven treatment of P. T. Piiroinen & Yu. A. Kuznetsov, "An
// event-driven method to simulate Filippov systems with accurate computing of sliding motions",
// ACM TOMS 34(3), 2008).
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
// Two switches at zero at once (the twin faces of a mirror-symmetric throw, or a second face's
// switch reached while sliding on one) are slid along together on their intersection with the
// bilinear combination of the four fields f_ab (face i out/in a = 0/1, face j b = 0/1) that L. Dieci
// & L. Lopez proposed (SIAM J. Numer. Anal. 47(3), 2009, where they also show that Filippov's
// convex hull of four fields leaves the sliding field undetermined; extended to more switches in
// Numer. Math. 117, 2011):
//   ẏ = (1−α)(1−β) f₀₀ + α(1−β) f₁₀ + (1−α)β f₀₁ + αβ f₁₁,  ∇gᵢ · ẏ = 0 and ∇gⱼ · ẏ = 0,
// two bilinear equations in (α, β), solved in closed form (a quadratic in β). It is taken where the
// solution lies in the open unit square and the fields attract: ∇gᵢ · ẏ > 0 at α = 0 and < 0 at α = 1
// (at the solution's β), and likewise for j (Dieci & Lopez's attractivity). The sliding ends where α
// or β reaches 0 or 1 (that face leaves, out or in, and is held; the other slides on alone with it
// held, where its switch attracts, else is held too) or where the solution ceases to exist.
// More than two switches at zero at once are not treated; attracting() says so.
// Used by the CVODE reference (cvode_stone.cpp) and the adaptive real-time stepper (sliding_steps.hpp).
// a_i is the central difference of g along f_i over ±kDirectionalStep_s. g is smooth in the state
// away from a vertex crossing the raised waterline; round-off in g (world positions of metres) over
// 2ε dominates the truncation error: ~1e-7 of a typical a_i of 1–10 m/s², ample for α and for the
// exit function's sign.
#include <span>
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

// Sliding on two switches, a weight this close to 0 or 1 where the other's reached it counts as
// there too. The twins of a mirror-symmetric lens throw reach their bounds together, but their
// weights differ there by 3e-8 (attack 20°) and 1.3e-6 (attack 5°; measured 5 December: the
// round-off of the rates' central differences, and of the two switches' starting values), so the
// root finder finds one exit first and the other, left to slide alone, exits at once. A weight
// moves at 300–2000 /s on those throws, so treating 1e-5 as the bound moves an exit by < 4e-8 s.
constexpr double kWeightAtBoundary = 1e-5;

// At most this many faces slide at once (on one switch, or on two switches' intersection), and at
// most kMaxTreatedFaces are treated apart at once, sliding or held on one side after sliding (a
// large lens can leave two faces held while a third switch attracts: a 28 cm lens at 37 m/s did).
constexpr std::size_t kMaxSlidingFaces = 2;
constexpr std::size_t kMaxTreatedFaces = 16;

// The bilinear sliding field's weights on two switches (Dieci & Lopez 2009), from the four fields'
// rates toward each: A[a][b] = ∇gᵢ · f_ab, B[a][b] = ∇gⱼ · f_ab (a: face i out 0 / in 1, b: face j).
// `solved`: a real solution exists (of the two roots of the quadratic, the one nearest the unit
// square); `attracts`: it lies inside the square and the fields attract (filippov_sliding.hpp).
struct BilinearWeights {
  bool solved = false, attracts = false;
  double alpha = 0, beta = 0;
};
BilinearWeights bilinear_sliding_weights(const double (&A)[2][2], const double (&B)[2][2]);

// Two switches at zero whose intersection does not attract (no bilinear weights in the unit
// square): the single-switch sliding modes on one of them with the other face held on a side,
// from the same corner rates. Sliding on j with i held on side a: j's switch attracts there
// (B[a][0] > 0 > B[a][1]) and its sliding field, β = B[a][0] / (B[a][0] − B[a][1]), keeps i on
// side a (its rate (1 − β) A[a][0] + β A[a][1] < 0 for side 0, > 0 for side 1); likewise sliding
// on i with j held. Consistent modes are tried with the face `prefer` sliding first (the face not
// sliding yet: the sliding is handed over to it, the other exits). `slides`: 0 for face i, 1 for
// face j, −1 if none is consistent; `held_side` the other's side.
struct PairHandover {
  int slides = -1, held_side = 0;
};
PairHandover handover_pair(const double (&A)[2][2], const double (&B)[2][2], int prefer);

// One face's loaded-region switch treated apart: slid along (with the other sliding face, if any, on
// the intersection), or held on one side (0: out of the loaded region, 1: in) after a sliding left it.
struct FaceRule {
  int face = -1;
  bool sliding = false;
  int side = 0;  // when held
};
using FaceRules = std::vector<FaceRule>;

// The choice made where a solve's step collapsed: the face(s) to slide on, or why there is none.
struct SlidingChoice {
  int face = -1;          // −1: no switch (or pair of switches) at zero attracts here
  int face2 = -1;         // the second face, sliding on the two switches' intersection; −1: one switch
  double g = 0;           // the (first) face's switch value there
  double a0 = 0, a1 = 0;  // one switch: ∇g · f₀ and ∇g · f₁ there
  double alpha = 0, beta = 0;  // two switches: the bilinear weights there
  // Two switches at zero whose intersection does not attract, where one slides alone with the
  // other face held on one side (handover_pair): that face and side; −1 otherwise.
  int hold_face = -1, hold_side = 0;
  std::string why;        // when face < 0: what was found instead
  // A choice that changes what slides where one face slides already: a second switch added, or
  // the sliding handed over to another face.
  bool changes_sliding() const { return face2 >= 0 || hold_face >= 0; }
};

class FilippovSliding {
 public:
  // Still water (the reference's). Available only where LoadSwitches is active (physical
  // convention, a savitsky distribution).
  FilippovSliding(const Stone& stone, const Environment& env);
  bool available() const { return switches_.active(); }

  // The loaded-region switches at zero at s (|g| ≤ kAtSwitch_m_s), other than those `rules` hold,
  // tested for attraction: one switch from both sides (a₀ > 0 > a₁), two on their intersection (the
  // bilinear field's weights inside the unit square, attracting); the held faces stay held.
  SlidingChoice attracting(const RigidState& s, const FaceRules& rules);
  SlidingChoice attracting_face(const RigidState& s) { return attracting(s, {}); }

  // The right-hand side at y (kStateSize doubles) under `rules` (the sliding field where a face
  // slides, the loads with the held faces held); the load evaluations it took.
  int rhs(const FaceRules& rules, const double* y, double* dydt);
  // The rules' root functions at y, one per rule: a sliding face's exit value (one switch:
  // min(a₀, −a₁); two: min(α, 1 − α) for the first, min(β, 1 − β) for the second; −1 where the
  // field is undefined or, for two, the weights do not exist), a held face's hold value (−g on side
  // 0, g on side 1; −1 where the face has no wetted polygon). The load evaluations it took.
  int roots(const FaceRules& rules, const double* y, double* g);
  // The rules after the roots flagged in `found` (one per rule, nonzero: its root was found) at y:
  // a sliding face that exits is held on the side it leaves to (the other sliding face slides on
  // alone where its switch attracts, else is held too); a hold that ends is dropped.
  FaceRules after_roots(const FaceRules& rules, const int* found, const double* y);

 private:
  // One switch: the sliding field's weight of f₁, clamped to [0, 1], and its exit value.
  struct SlidingField {
    double alpha = 0;
    double exit = -1;
  };
  // The loads with the faces of forced_ set (LoadMode's loaded_faces values), the others decided.
  void rhs_forced(const double* y, double* dydt);
  // forced_ = the held faces of `rules`, each on its side (the sliding ones left to the caller).
  void hold(const FaceRules& rules);
  // Switch values of `faces` at y (NaN where undefined), from one evaluation.
  void switch_values(std::span<const int> faces, const double* y, double* out);
  // ∇g · f for each of `faces` (at most 2: central differences along f at y).
  void rates_along(std::span<const int> faces, const double* y, const double* f, double* out);

  // One switch with the held faces held: the two fields and their rates.
  struct Sides {
    StateVector f0{}, f1{};
    double a0 = 0, a1 = 0;
  };
  Sides sides(int face, const FaceRules& held, const double* y);
  SlidingField one_switch(int face, const FaceRules& held, const double* y, double* dydt);
  // Two switches: the four fields f_ab (a: face i, b: face j), the rates A_ab = ∇gᵢ · f_ab and
  // B_ab = ∇gⱼ · f_ab, and the bilinear solution.
  struct Corners {
    StateVector f[2][2]{};
    double A[2][2]{}, B[2][2]{};
    bool defined = false;   // every rate finite
    bool solved = false, attracts = false;  // bilinear_sliding_weights'
    double alpha = 0, beta = 0;
  };
  Corners corners(int fi, int fj, const FaceRules& held, const double* y);

  std::size_t index_of(int face) const;  // the face's loaded_face value among LoadSwitches' values

  const Stone& stone_;
  const Environment& env_;
  LoadSwitches switches_;
  LoadMode mode_;
  std::vector<double> g_;
  // The faces rhs_forced holds (face, 0 out of the loaded region or 1 in), rebuilt by each caller;
  // kept, like mode_ and g_, so that a right-hand side allocates nothing once they have grown.
  std::vector<std::pair<int, char>> forced_;
};

}  // namespace stoneskip
