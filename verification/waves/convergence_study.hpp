#pragma once
// Convergence of a stencil on the fixed wave problem (verification/waves/wave_problem.hpp),
// with the error split three ways (model/README.md §2.3):
//   space: the exact semi-discrete solution of the stencil vs the exact continuum solution,
//          on grids n = 32, 64, ... (no time error at all);
//   time:  the leapfrog vs the exact semi-discrete solution on one grid, Δt halved (no space error);
//   both:  the leapfrog vs the exact continuum solution, grid and Δt refined together at fixed σ;
//   walls: "both" again in the problem's square walled in, reflecting or fixed (solvers/spectral/
//          walled_wave.hpp), followed until the waves have come back from the walls.
// Each sequence gets a least-squares order with its 95 % interval (verification/convergence/
// order_fit.hpp), fitted on its finest points (the asymptotic range), and the "both" sequence a
// Grid Convergence Index on a point value (verification/convergence/gci.hpp).
#include <string>
#include <vector>

#include "model/water/stencil.hpp"
#include "verification/study/progress.hpp"
#include "verification/convergence/gci.hpp"
#include "verification/convergence/order_fit.hpp"
#include "verification/waves/wave_problem.hpp"

namespace stoneskip {



struct ConvergencePoint {
  int n = 0;
  long steps = 0;
  double h = 0;        // the refined size: d (space, both) or Δt (time)
  double sigma = 0;    // cΔt/d (NaN for space: no time stepping)
  double l2_m = 0, max_m = 0;
  double cpu_s = 0;    // leapfrog stepping (0 for space)
  double point_m = 0;  // the height at (3/4, 1/2) L at t_end (GCI functional)
};

struct ConvergenceSequence {
  std::string kind;  // "space", "time", "both"
  std::vector<ConvergencePoint> points;
  OrderFit fit;             // on the finest `fit_points` points, l2 norm
  OrderFit fit_max;         // same, max norm
  OrderVerdict verdict = OrderVerdict::insufficient_data;
  GciResult gci;            // "both" only: three finest point values
  double point_exact_m = 0; // "both" only: the continuum value at the finest grid
};

// The walled square of side L on the grid of n cells of d = L/n: between reflecting walls, n points
// at the cell centres (i + ½)d (the ghost cells mirror the edge points, a wall half a cell out); inside
// fixed rims, the n − 1 points (i + 1)d (the ghost cells hold 0 one cell out: the rims at 0 and L).
// So d is the periodic square's d, and a fixed grid of n = 2^k cells has a sine transform of 2^(k+1).
struct WalledSquareGrid {
  int points = 0;      // along each axis
  double cell_m = 0;   // d
  double first_m = 0;  // the first point's coordinate: d/2 or d
};
WalledSquareGrid walled_square_grid(double length_m, Boundary b, int n);

struct ConvergenceStudyOptions {
  WaveProblem problem;
  std::vector<int> space_grids{32, 64, 128, 256, 512};
  int time_grid = 64;
  std::vector<long> time_steps{64, 128, 256, 512, 1024};  // σ = 0.5 … 0.03 at n = 64
  std::vector<int> both_grids{32, 64, 128, 256};
  double both_sigma = 0.5;
  // The walled sequences: the square's edges are walls (reflecting: zero slope; fixed: z = 0) at
  // x, y = 0 and L, on the grid walled_square_grid gives (where the ghost cells put those walls);
  // grids both_grids, σ both_sigma, to walls_t_end_s (long enough for the waves to reach the walls
  // and come back). Empty: none.
  std::vector<Boundary> walls{Boundary::reflecting, Boundary::fixed};
  double walls_t_end_s = 1.25;
  int fit_points = 0;  // fit the finest this many points; 0: every point (no range to choose)
  OrderJudgement judgement;  // expected order 2 ± 0.1
};

struct ConvergenceStudy {
  std::string stencil;
  ConvergenceSequence space, time, both;
  std::vector<ConvergenceSequence> walls;  // one per options.walls, kind "walls_<boundary>"
};

ConvergenceStudy run_convergence_study(const Stencil& stencil, const ConvergenceStudyOptions& options,
                                       ProgressTicker* progress = nullptr);
// Work units (≈ cell updates) the study will do, for progress reporting.
std::size_t convergence_study_work(const ConvergenceStudyOptions& options);

// The order fit of the finest `fit_points` of a sequence (0: all; both norms) and its verdict.
void fit_sequence(ConvergenceSequence& s, int fit_points, const OrderJudgement& judgement);
// The Grid Convergence Index of a sequence's three finest point values (no change with fewer); an
// apparent order outside the judgement's expected ± tolerance reverts to it with Fs = 3 (gci.hpp).
void attach_gci(ConvergenceSequence& s, const OrderJudgement& judgement);

}  // namespace stoneskip
