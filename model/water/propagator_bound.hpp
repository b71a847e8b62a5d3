#pragma once
// How much the free damped leapfrog (model/README.md §2.1) can amplify a perturbation: on a mode of symbol s
// the step is (z_{n+1}, z_n) = M (z_n, z_{n−1}),
//   M = [[(4 + 2σ² s)/(2 + μΔt), −(2 − μΔt)/(2 + μΔt)], [1, 0]],
// and K_N = max over the grid's modes and 0 ≤ p ≤ N of ‖Mᵖ‖₂ bounds the growth of the 2-norm of
// any state pair over N steps (the modes are orthogonal). The modes of an nx × ny periodic grid
// (a = 2πm/nx) and of a reflecting one (cosines, a = πm/nx) are all among a = πm/nx, m ≤ nx, whose
// cosines cover both, so one bound serves both boundaries. K_N ≥ 1; with μ = 0 it grows with N
// (the mean mode keeps a momentum), with μ > 0 it saturates near 2/(μΔt) at most.
// Used to bound the error of active tiles (model/water/height_field.hpp: ActiveTileSummary).
#include "model/water/stencil.hpp"

namespace stoneskip {

// Cost O((nx + 1)(ny + 1) N) 2×2 products (halved when nx = ny, the stencil being symmetric).
double leapfrog_propagator_bound(const Stencil& stencil, double sigma, double mu_dt, int nx, int ny, long steps);

// Two runs whose inputs differ by less than an ulp can still round differently. For one update
// z⁺ = Σ w_i x_i (12 roundings, 9 values of z and one of z⁻), each computed value lies within
// γ₁₂ Σ|w_i||x_i| of the exact one (Higham, Accuracy and Stability of Numerical Algorithms,
// §3.1), so two evaluations differ by at most twice that; over the cells, in the 2-norm, at most
// 2γ₁₂ · 2 (W ‖z‖₂ + |w_p| ‖z⁻‖₂), W = Σ|weights on z|, the last 2 for mirrored edge values.
// unit_roundoff: 2⁻⁵³ (float64) or 2⁻²⁴ (float32).
double leapfrog_rounding_bound(const Stencil& stencil, double sigma, double mu_dt, double z_norm, double z_previous_norm,
                               double unit_roundoff);

}  // namespace stoneskip
