#pragma once
// A 3×3 Laplacian stencil as data: L[z] = (1/d²)[centre·z + orth·Σ_orth + diag·Σ_diag]
// (model/README.md §2.2), Σ_orth the four edge neighbours, Σ_diag the four corner neighbours. The four
// named stencils of the spec are built from their weights; a case file may define its own.
#include <string>
#include <vector>

namespace stoneskip {

struct Stencil {
  std::string name;
  double centre = -4;  // weights × 1/d²
  double orth = 1;
  double diag = 0;

  double weight_sum() const { return centre + 4 * orth + 4 * diag; }
  // d² × the stencil's eigenvalue on the Fourier mode e^{i(a x + b y)/d}, a = kx d, b = ky d:
  // centre + 2 orth (cos a + cos b) + 4 diag cos a cos b. (The continuum's is −(a² + b²).)
  double symbol(double a, double b) const;
  // The smallest symbol over all wavenumbers. symbol() is bilinear in (cos a, cos b) ∈ [−1, 1]²,
  // so its extremes lie at the four corners (a, b ∈ {0, π}).
  double min_symbol() const;
  double max_symbol() const;  // likewise at the corners
  // A symbol within this of 0 is 0: a few ulps of the weights' magnitude, the round-off of a sum
  // of weights × cosines (the constant mode's exact 0 comes out as ±4e-16 for γ = 1/3).
  double symbol_roundoff() const;
};

// The largest σ = cΔt/d for which the damped leapfrog of model/README.md §2.1 is stable with this stencil:
// a mode is multiplied per step by a root g of (2 + μΔt) g² − (4 + 2σ² s) g + (2 − μΔt) = 0, and
// both roots lie in the closed unit disc iff −4 ≤ σ² s ≤ 0, for every μΔt ≥ 0 (the Schur–Cohn/Jury
// test for a real quadratic a g² + b g + c with a > 0: both roots in the closed disc iff |c| ≤ a and
// |b| ≤ a + c; here |2 − μΔt| ≤ 2 + μΔt always, and |4 + 2σ² s| ≤ 4): so σ_max = 2/√(−min s),
// independent of damping (the limits are listed in model/README.md §2.2). At σ_max with μ = 0 the
// root −1 is double, so the highest mode grows linearly there: the limit is the supremum of the
// stable steps. Exact, from the symbol's extremes at the corners of the Brillouin zone.
// 0 ("no stable step") if some mode has s > 0 (it grows for every σ > 0); +∞ ("unbounded") if the
// symbol is 0 for every mode (no spatial coupling: g = 1 and (2 − μΔt)/(2 + μΔt) for every σ).
// Five-point 1/√2, γ = 1/3 √3/2, γ = 1/2 1; verification/waves/stability.hpp finds the same
// limits by bisection on the amplification factors.
double leapfrog_courant_limit(const Stencil& stencil);

// The same over a finite set of modes: the wavenumbers a grid holds, given as the range of their
// cosines along each axis, [cx_min, cx_max] × [cy_min, cy_max] (the symbol is bilinear in the
// cosines, so its extremes over the set lie at those ends). A periodic grid of N points holds
// k = 2πm/N (no k = π when N is odd), a reflecting one k = πm/N, m < N, a fixed one k = πm/(N + 1),
// 1 ≤ m ≤ N: on a grid without the zone's corner the limit is above the plane's (a 5 × 5 periodic
// five-point grid: 0.7435, not 1/√2).
double leapfrog_courant_limit(const Stencil& stencil, double cx_min, double cx_max, double cy_min, double cy_max);

// The family of model/README.md §2.2: (1 − γ)(Σ_orth − 4z) + (γ/2)(Σ_diag − 4z).
Stencil stencil_family(double gamma, std::string name);

// "five_point" (γ = 0, Figure 4a), "nine_point_half" (γ = 1/2, half of Eq. 10),
// "nine_point_isotropic" (γ = 1/3, Patra & Karttunen 2006), "paper_eq11" (Eq. 11 as printed).
const std::vector<std::string>& stencil_names();
bool is_stencil_name(const std::string& name);
Stencil named_stencil(const std::string& name);  // throws std::invalid_argument for other names

}  // namespace stoneskip
