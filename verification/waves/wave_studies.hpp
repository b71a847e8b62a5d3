#pragma once
// All the wave studies of the waves report (issue 3), run in one call and returned as plain
// result structs; reports/waves/ turns them into HDF5, figures and Markdown (reports never
// integrate). Sections: consistency, convergence (space / time / both), isotropy (symbol,
// simulation, ring), stability (computed, measured, Lengyel's bound), speed against error.
#include <string>
#include <vector>

#include "model/water/stencil.hpp"
#include "verification/waves/convergence_study.hpp"
#include "verification/waves/isotropy.hpp"
#include "verification/waves/stability.hpp"
#include "verification/waves/stencil_consistency.hpp"
#include "verification/waves/work_precision.hpp"

namespace stoneskip {

struct WaveStudiesOptions {
  bool quick = false;  // smaller grids and fewer points: a smoke run in a few seconds
  std::vector<std::string> stencils{"five_point", "nine_point_half", "nine_point_isotropic", "paper_eq11"};
};

struct IsotropyCurve {  // phase-speed error from the symbol against angle, one stencil, one kd
  std::string stencil;
  double kd = 0;
  std::vector<double> theta_rad, error;
};
struct SpreadCurve {  // max − min over angle of the phase-speed error, against kd
  std::string stencil;
  std::vector<double> kd, spread;
};
struct MeasuredIsotropy {
  std::string stencil;
  double kd_target = 0;
  std::vector<MeasuredPhaseSpeed> points;
};

struct StabilityCurve {  // computed σ limit against μΔt
  std::string stencil;
  std::vector<double> mu_dt, limit;
};
struct StabilityCheck {  // the limit checked by running
  std::string stencil;
  double mu_dt = 0;
  double computed_limit = 0;
  double measured_limit = 0;    // bisection on runs
  double lengyel_bound = 0;
  GrowthRun below, above;       // at 0.98 and 1.02 × computed limit
};

struct WaveStudies {
  WaveStudiesOptions options;
  std::vector<Stencil> stencils;
  WaveProblem problem;
  // Consistency
  std::vector<ConsistencyResult> consistency;
  // Convergence
  ConvergenceStudyOptions convergence_options;
  std::vector<ConvergenceStudy> convergence;
  // Isotropy
  std::vector<IsotropyCurve> isotropy_curves;
  std::vector<SpreadCurve> spread_curves;
  std::vector<MeasuredIsotropy> measured_isotropy;
  int measured_grid = 256;
  double measured_sigma = 0.1;
  long measured_steps = 400;
  RingTestOptions ring_options;
  std::vector<std::pair<std::string, RingTest>> rings;
  // Stability
  std::vector<StabilityCurve> stability_curves;
  std::vector<StabilityCheck> stability_checks;
  GrowthRun lengyel_counterexample;  // five-point, μΔt = 0.5, σ = 0.75
  double lengyel_counterexample_predicted = 0;
  // Speed against error
  WorkPrecisionOptions work_options;
  std::vector<std::pair<std::string, std::vector<WorkPoint>>> work;
  std::vector<std::pair<std::string, double>> work_sigma_limit;
  // Cost of each section (CPU seconds)
  double cpu_consistency_s = 0, cpu_convergence_s = 0, cpu_isotropy_s = 0, cpu_stability_s = 0, cpu_work_s = 0;
};

// Runs every study; progress (if given) is ticked per unit of work, shown on stderr by the caller.
WaveStudies run_wave_studies(const WaveStudiesOptions& options);

}  // namespace stoneskip
