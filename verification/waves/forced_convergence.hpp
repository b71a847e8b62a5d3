#pragma once
// Convergence of the forced leapfrog (model/README.md §2.4: the height field driven by a draught b) to the
// forced spectral reference (model/README.md §2.5), split three ways as for the free field
// (verification/waves/convergence_study.hpp):
//   space: the stencil's exact semi-discrete forced solution vs the continuum one (no time error);
//   time:  the forced leapfrog vs the stencil's semi-discrete forced solution on one grid, Δt halved;
//   both:  the forced leapfrog vs the continuum forced solution, d and Δt refined at fixed σ.
// The problem: a periodic square at rest, a Gaussian draught moving at constant velocity under a
// smooth envelope (solvers/spectral/forced_wave.hpp: MovingGaussianDraught), the surface at t_end.
// Orders are fitted and judged by verification/convergence (fit_order + judge_order, on the
// confidence interval). The reference's own quadrature error is estimated by halving its
// sub-intervals on the finest grid and reported beside the errors it is used to measure.
#include <string>
#include <vector>

#include "model/water/stencil.hpp"
#include "solvers/spectral/forced_wave.hpp"
#include "verification/waves/convergence_study.hpp"

namespace stoneskip {

// The free problem (domain, c, μ, t_end, initial surface: flat by default) and the draught.
struct ForcedWaveProblem {
  WaveProblem wave = at_rest();
  MovingGaussianDraught draught;  // 5 mm deep, w = 0.1 m, from (0.3, 0.4) m at (0.4, 0.2) m/s, rise 0.1 s
  static WaveProblem at_rest() {
    WaveProblem w;
    w.initial.amplitude_m = 0;
    return w;
  }
};

struct ForcedConvergenceOptions {
  ForcedWaveProblem problem;
  std::vector<int> space_grids{32, 64, 128, 256};
  int time_grid = 64;
  std::vector<long> time_steps{64, 128, 256, 512};  // σ = 0.5 … 0.06 at n = 64
  std::vector<int> both_grids{32, 64, 128, 256};
  double both_sigma = 0.5;
  // "both" again in the square walled in (the walls at 0 and L as in convergence_study.hpp's walled
  // sequences; the draught sampled without periodic images), to walls_t_end_s, against the forced
  // walled reference (solvers/spectral/forced_walled_wave.hpp). Empty: none.
  std::vector<Boundary> walls{Boundary::reflecting, Boundary::fixed};
  double walls_t_end_s = 1.25;
  DuhamelQuadrature quadrature{32, 8};
  int fit_points = 3;
  OrderJudgement judgement;  // expected order 2 ± 0.1
  bool is_valid(std::string* why = nullptr) const;
};

struct ForcedConvergenceStudy {
  std::string stencil;
  ConvergenceSequence space, time, both;
  std::vector<ConvergenceSequence> walls;  // one per options.walls, kind "walls_<boundary>"
  double reference_quadrature_m = 0;  // max |reference − reference with half the sub-intervals' length|, finest grid
  double smallest_error_m = 0;        // the smallest error the study measures, for comparison with it
  long reference_transforms = 0;      // FFTs of b taken by the references
};

// The forced leapfrog on an n × n periodic grid, `steps` equal steps to t_end, b(t_k) given at the
// start of each step; the surface at t_end.
LeapfrogResult solve_forced_leapfrog(const ForcedWaveProblem& p, const Stencil& stencil, int n, long steps);
// The forced reference at t_end: continuum symbol, or the stencil's (exact semi-discrete).
std::vector<double> solve_forced_reference(const ForcedWaveProblem& p, int n, SpectralSymbol symbol, const Stencil& stencil,
                                           const DuhamelQuadrature& quadrature, long* transforms = nullptr);

// Throws std::invalid_argument for invalid options.
ForcedConvergenceStudy run_forced_convergence(const Stencil& stencil, const ForcedConvergenceOptions& options);

}  // namespace stoneskip
