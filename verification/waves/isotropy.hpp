#pragma once
// Isotropy of a stencil: how the speed of a plane wave depends on its direction.
// From the symbol: the semi-discrete phase speed of a wave of number k at angle θ is
//   c_h/c = √(−symbol(kd cos θ, kd sin θ)) / kd,
// and the relative phase-speed error is c_h/c − 1. Measured from simulations: a single Fourier
// mode is run with the leapfrog and its frequency is estimated from the time series of its
// amplitude (Prony's linear prediction a_{n+1} + a_{n−1} = 2 cos(ωΔt) a_n, least squares).
// A ring test runs a radially symmetric bump and measures the radius of the outgoing wavefront
// (the z²-weighted mean radius in an annulus around ct) along rays at different angles.
#include <vector>

#include "model/water/stencil.hpp"

namespace stoneskip {

// Relative phase-speed error c_h/c − 1 from the symbol (NaN if the symbol is positive: no wave).
double phase_speed_error(const Stencil& stencil, double kd, double theta_rad);

// max − min over θ ∈ [0, π/2] (the symbols of 3×3 stencils have the square's symmetry).
double phase_error_spread(const Stencil& stencil, double kd, int angles = 181);

struct MeasuredPhaseSpeed {
  int m = 0, n = 0;       // the grid mode (wave numbers 2π m/(N d), 2π n/(N d))
  double kd = 0, theta_rad = 0;
  double measured_error = 0;       // c_measured/c − 1 from the simulation
  double semi_discrete_error = 0;  // from the symbol (space error only)
  double fully_discrete_error = 0; // symbol plus leapfrog: arccos(1 + σ² s/2)/(σ kd) − 1
};

// Runs the mode closest to (kd, θ) on an N × N periodic grid at Courant number σ (μ = 0) for
// `steps` steps and measures its phase speed.
MeasuredPhaseSpeed measure_phase_speed(const Stencil& stencil, double kd, double theta_rad, int N = 128,
                                       double sigma = 0.1, long steps = 400);

struct RingTest {
  std::vector<double> theta_rad;
  std::vector<double> front_radius_m;            // wavefront radius, the stencil's leapfrog run
  std::vector<double> reference_front_radius_m;  // the continuum spectral reference, same measurement
  double spread_m = 0;  // max − min of front_radius_m over θ
  double cell_m = 0;
  double cpu_s = 0;
};
struct RingTestOptions {
  int n = 128;            // cells per side of the unit periodic square
  double width_m = 0.03;  // Gaussian bump width (a few cells: dispersion shows)
  double t_s = 0.3;       // c = 1 m/s
  double sigma = 0.5;
  int angles = 46;        // θ in [0, π/2]
};
RingTest ring_test(const Stencil& stencil, const RingTestOptions& options = {});

}  // namespace stoneskip
