#pragma once
// One step of an embedded Runge–Kutta pair with its error estimate, for the adaptive real-time
// stepper (stone_stepper.hpp): Bogacki–Shampine 3(2) (scheme bs32) or Dormand–Prince 5(4) (dp54).
//
// Bogacki–Shampine 3(2) (Bogacki & Shampine 1989, Appl. Math. Lett. 2(4), 321–325; Hairer,
// Nørsett & Wanner, Solving ODEs I, §II.4 and §II.5): 3 right-hand sides per accepted step (FSAL:
// the last stage is the next step's first); its third-order solution and the stage at the end give
// the cubic Hermite dense output (dense_output.hpp) for free, and it has the smallest error
// constant of the common third-order pairs. The step is advanced with the third-order solution
// (local extrapolation); the quaternion is renormalised before the last stage is evaluated.
//
// Dormand–Prince 5(4) (Dormand & Prince 1980, J. Comput. Appl. Math. 6(1), 19–26; Hairer,
// Nørsett & Wanner §II.5, Table 5.2): six right-hand sides per trial (seven stages, FSAL),
// advanced with the fifth-order solution, the quaternion renormalised as for bs32; its dense
// output is the pair's own continuous extension (quartic, O(h⁵): dense_output.hpp), so its events
// are located to order 5.
//
// Why bs32 stays the default (solvers/README.md, "The fifth-order pair"): the stone's right-hand
// side is only piecewise smooth (a kink wherever a vertex crosses the surface, a jump where a face
// joins the distributed pressure's loaded region, model/README.md §1.4), and a high order pays
// only between them. At the tolerance that decides bounce counts (1e-9) dp54 takes a quarter of
// bs32's steps, but a spinning stone planing on its faceted rim meets a crossing every half
// millisecond or so, and each costs a trial cut back and taken again: half of dp54's trials are
// cut or rejected, against a tenth of bs32's. And dp54's estimate is all but blind to a jump
// inside its step (Σ e_i = 0, and its e over stages 3–7 sums to −e₁ = 0.0012 while its solution
// errs by up to 0.16 of the jump × h), so it must cut its steps at the jumps too (kinks "all"),
// which costs more again.
#include <functional>

#include "model/stone/rigid_body.hpp"

namespace stoneskip {

struct AdaptiveTrial {
  StateVector y1{};        // the higher-order solution (quaternion normalised)
  StateVector k4{};        // f(y1): the first stage of the next step (FSAL; dp54's k7)
  double wetted_area_m2 = 0;  // Σ S_i at y1, from the evaluation of k4 (the stepper logs it)
  double error_norm = 0;   // RMS of (y1 − ŷ1)_i / (atol_i + rtol max(|y0_i|, |y1_i|)); ≤ 1 passes
  double position_error_m = 0;  // ‖(y1 − ŷ1)_x‖: the local error estimate of the position
  // dp54: the continuous extension's quartic term (HermiteStep::quartic); bs32: none.
  StateVector quartic{};
  bool has_quartic = false;
};

// A right-hand side other than the loads' own (a sliding field, filippov_sliding.hpp): dydt at y.
using FieldFunction = std::function<void(const double* y, double* dydt)>;

// One trial step of size h from y0, with k1 = f(y0) given. Three right-hand sides. With `field`,
// the stages are its values (and wetted_area_m2 is NaN: the caller measures it); with `mode`, every
// stage's loads hold that loaded region (LoadMode, fluid_forces.hpp; k1 must have been computed so).
AdaptiveTrial bs32_step(const Stone& stone, const Environment& env, const StateVector& y0, const StateVector& k1,
                        double h_s, const WaterSurface* surface, const StateVector& atol, double rtol,
                        const FieldFunction* field = nullptr, const LoadMode* mode = nullptr);

// The same for Dormand–Prince 5(4): six right-hand sides (k1 given, k7 = f(y1) returned as k4).
AdaptiveTrial dp54_step(const Stone& stone, const Environment& env, const StateVector& y0, const StateVector& k1,
                        double h_s, const WaterSurface* surface, const StateVector& atol, double rtol,
                        const FieldFunction* field = nullptr, const LoadMode* mode = nullptr);

// The next step size from the error norm of an accepted or a rejected one (Hairer, Nørsett &
// Wanner §II.4, Eq. 4.13): h · min(5, max(0.2, 0.9 err^(−1/3))).
double bs32_next_step(double h_s, double error_norm);
// The same for Dormand–Prince 5(4): h · min(5, max(0.2, 0.9 err^(−1/5))).
double dp54_next_step(double h_s, double error_norm);

}  // namespace stoneskip
