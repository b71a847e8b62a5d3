#pragma once
// One step of the Bogacki–Shampine 3(2) pair (Bogacki & Shampine 1989, Appl. Math. Lett. 2(4),
// 321–325; Hairer, Nørsett & Wanner, Solving ODEs I, §II.4 and §II.5) with its error estimate,
// for the adaptive real-time stepper (stone_stepper.hpp, scheme bs32).
//
// Why this pair and not Dormand–Prince 5(4): the stone's right-hand side is only piecewise smooth
// (a kink wherever a vertex crosses the surface or a wet face's flow switches, model/README.md
// §1.4), so a high order pays only between kinks, and the accuracies that decide a bounce count
// are loose (rtol ~ 1e-4..1e-6). BS 3(2) costs 3 right-hand sides per accepted step (FSAL: the
// last stage is the next step's first), its third-order solution and the stage at the end give
// the cubic Hermite dense output (dense_output.hpp) for free, and it has the smallest error
// constant of the common third-order pairs. The step is advanced with the third-order solution
// (local extrapolation); the quaternion is renormalised before the last stage is evaluated.
#include <functional>

#include "model/stone/rigid_body.hpp"

namespace stoneskip {

struct Bs32Trial {
  StateVector y1{};        // the third-order solution (quaternion normalised)
  StateVector k4{};        // f(y1): the first stage of the next step (FSAL)
  double wetted_area_m2 = 0;  // Σ S_i at y1, from the evaluation of k4 (the stepper logs it)
  double error_norm = 0;   // RMS of (y1 − ŷ1)_i / (atol_i + rtol max(|y0_i|, |y1_i|)); ≤ 1 passes
  double position_error_m = 0;  // ‖(y1 − ŷ1)_x‖: the local error estimate of the position
};

// A right-hand side other than the loads' own (a sliding field, filippov_sliding.hpp): dydt at y.
using FieldFunction = std::function<void(const double* y, double* dydt)>;

// One trial step of size h from y0, with k1 = f(y0) given. Three right-hand sides. With `field`,
// the stages are its values (and wetted_area_m2 is NaN: the caller measures it).
Bs32Trial bs32_step(const Stone& stone, const Environment& env, const StateVector& y0, const StateVector& k1,
                    double h_s, const WaterSurface* surface, const StateVector& atol, double rtol,
                    const FieldFunction* field = nullptr);

// The next step size from the error norm of an accepted or a rejected one (Hairer, Nørsett &
// Wanner §II.4, Eq. 4.13): h · min(5, max(0.2, 0.9 err^(−1/3))).
double bs32_next_step(double h_s, double error_norm);

}  // namespace stoneskip
