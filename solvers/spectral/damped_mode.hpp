#pragma once
// The exact solution of one Fourier mode of the damped wave equation (model/README.md §2.3):
//   ẑ'' + μ ẑ' + λ ẑ = 0,  ẑ(0) = ẑ0, ẑ'(0) = v̂0,
// written as ẑ(t) = gz ẑ0 + gv v̂0. With D = λ − μ²/4 and b = v̂0 + (μ/2) ẑ0:
//   ẑ(t) = e^{−μt/2} [C(t) ẑ0 + S(t) b],
//   D > 0: C = cos √D t, S = sin(√D t)/√D;  D < 0: C = cosh √−D t, S = sinh(√−D t)/√−D;
//   D ≈ 0: the common power series C = Σ u^n/(2n)!, S = t Σ u^n/(2n+1)!, u = −D t²
//   (no cancellation near critical damping); λ = 0: ẑ0 + v̂0 (1 − e^{−μt})/μ.
// The hyperbolic branch combines the exponentials so that nothing overflows for large t.
namespace stoneskip {

struct DampedModeFactors {
  double gz = 1;  // multiplies ẑ0
  double gv = 0;  // multiplies v̂0
};

DampedModeFactors damped_mode(double lambda, double mu, double t);

}  // namespace stoneskip
