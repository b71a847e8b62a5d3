#pragma once
// The draught a water step receives in a coupled scene (model/README.md §2.4), gathered over the step's
// window. The leapfrog level n (time t_n) is seen by the stone during [t_n − Δt/2, t_n + Δt/2);
// the step n → n+1 is forced by
//   b̄ⁿ = (1/K) Σ_{k<K} b(t_n − Δt/2 + (k + ½) Δt/K),
// the midpoint rule on K sub-intervals of that window, each sample computed from the stone's pose
// then and the surface zⁿ it sees. K = 1 is the spec's point sample b(t_n); K > 1 is the window's
// mean to O((Δt/K)²), centred on t_n like the point sample (so the forced leapfrog keeps its
// second order), and it cannot miss a contact shorter than a water step, which a point sample
// does (a 10 ms contact between two samples 11 ms apart leaves no wave at all).
//
// Samples are added into a grid-sized sum (wrapped on periodic fields, clipped elsewhere) with the
// box of the touched points tracked, and taken out as one patch over that box: O(touched box) per
// sample and per step, no allocation once the patch has grown.
#include <vector>

#include "model/water/draught_patch.hpp"

namespace stoneskip {

class DraughtWindow {
 public:
  DraughtWindow(int nx, int ny, bool periodic);

  // Adds weight · b of a sample (weight = samples it stands for / K).
  void add(const DraughtPatch& sample, double weight);
  // Σ b over the points of `sample` that add() keeps (all on a periodic field; those inside the
  // grid elsewhere): what the field receives of it, by the same rule.
  double kept_sum(const DraughtPatch& sample) const;
  bool empty() const { return i_lo_ > i_hi_; }
  // Σ b̄ over the window as it stands (what the next take() would hand over).
  double sum() const;
  // The window's b̄ over the touched box, into `out` (empty when nothing was added); the window
  // is cleared for the next step.
  void take(DraughtPatch& out);

 private:
  int nx_, ny_;
  bool periodic_;
  std::vector<double> sum_;  // nx·ny, x fastest
  int i_lo_, i_hi_, j_lo_, j_hi_;
};

}  // namespace stoneskip
