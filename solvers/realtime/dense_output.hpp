#pragma once
// Dense output of one step: the cubic Hermite interpolant through the states and their time
// derivatives at both ends (Hairer, Nørsett & Wanner, Solving ODEs I, §II.6, Eq. 6.7), and the
// time inside the step at which a vertex crosses the water surface along it.
//
// The interpolant's error is O(h⁴) locally, so an event located on it keeps the order of a scheme
// up to 4 (rk4, Bogacki–Shampine 3(2)); linear interpolation of the depths would cap it at 2. The
// quaternion is interpolated as four numbers and normalised (its derivative ½(0, ω)⊗q is in the
// right-hand side, model/README.md §1.3).
#include <functional>

#include "model/stone/rigid_body.hpp"

namespace stoneskip {

struct HermiteStep {
  StateVector y0{}, y1{};  // the states at the start and the end of the step
  StateVector f0{}, f1{};  // dy/dt there (the right-hand side)
  double h_s = 0;
  // Dormand–Prince 5(4)'s continuous extension (Shampine 1986; Hairer, Nørsett & Wanner §II.6,
  // the dense output of DOPRI5): the cubic Hermite plus θ²(1 − θ)² q, q = h Σ d_i k_i from the
  // step's stages; O(h⁵) locally, so its events keep order 5. Absent (has_quartic false): the cubic.
  StateVector quartic{};
  bool has_quartic = false;

  // The interpolated flat state at t0 + θ h (θ ∈ [0, 1]); exact at θ = 0 and 1.
  StateVector at(double theta) const;
  // The same as a RigidState with its quaternion normalised.
  RigidState state_at(double theta) const;
};

// Depth of body vertex k below the surface (d = η − z; > 0 under water).
double vertex_depth(const Stone& stone, const RigidState& s, const WaterSurface* surface, int k);

// The fraction θ ∈ [0, 1] of the step at which vertex k's depth, along the interpolant, crosses
// zero, given depths d0 and d1 of opposite sign (one of them ≤ 0 < the other) at the step's ends.
// Illinois regula falsi to |Δθ| ≤ fraction_tolerance (Dahlquist & Björck, Numerical Methods
// §6.2.3); the returned θ is the bracket's end on the side of the step's end.
constexpr double kFullFractionTolerance = 1e-13;  // a few hundred ulps of the unit interval
// The same for any function of the fraction whose ends g0, g1 differ in (g > 0): the first θ at
// which g(θ) is on g1's side, to |Δθ| ≤ fraction_tolerance. A caller that wants only a root
// before `wanted_below` (the earliest of several) may pass it: the search then stops as soon as
// the bracket lies at or above it, and returns a θ ≥ wanted_below; a root below it is located as
// without it, bit for bit (the iterates are the same until the search stops).
double sign_change_fraction(const std::function<double(double)>& g, double g0, double g1,
                            double fraction_tolerance = kFullFractionTolerance, double wanted_below = 2);
double crossing_fraction(const HermiteStep& step, const Stone& stone, const WaterSurface* surface, int k,
                         double d0, double d1, double fraction_tolerance = kFullFractionTolerance);

}  // namespace stoneskip
