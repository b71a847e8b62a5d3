#pragma once
// The wave studies: every question the waves report answers, as a function from
// settings (cases/studies/waves*.toml) to findings (verification/study/record.hpp), section by
// section: consistency, convergence (space / time / both), isotropy (symbol, simulation, ring),
// stability (computed, measured, Lengyel's bound), speed against error. Each section's record
// holds the numbers, tables, verdicts and computed reasons the report formats (reports/waves/);
// nothing in a report decides a verdict.
#include <string>
#include <vector>

#include "model/water/stencil.hpp"
#include "verification/study/study_sink.hpp"
#include "verification/waves/convergence_study.hpp"
#include "verification/waves/isotropy.hpp"
#include "verification/waves/stability.hpp"
#include "verification/waves/stencil_consistency.hpp"
#include "verification/waves/work_precision.hpp"

namespace stoneskip {

struct WaveIsotropyOptions {
  std::vector<double> polar_kd{M_PI / 8, M_PI / 4, M_PI / 2};  // polar plots of c_h/c
  int polar_angles = 181;                                     // over [0, 2π]
  double spread_kd_min = 0.02, spread_kd_max = M_PI;          // spread against kd (log-spaced)
  int spread_points = 41;
  double table_kd = M_PI / 8;                                 // where stencils are compared
  std::string baseline_stencil = "five_point";               // spreads are shown as ratios to it
  std::vector<double> measured_kd{M_PI / 8, M_PI / 4};        // single-mode simulations
  int measured_angles = 10;                                   // over [0, π/4]
  int measured_grid = 256;
  double measured_sigma = 0.1;
  long measured_steps = 400;
  RingTestOptions ring;
};

struct WaveStabilityOptions {
  double mu_dt_max = 1.9;     // the computed limit against μΔt on [0, mu_dt_max]
  int mu_dt_points = 39;
  std::vector<double> check_mu_dt{0.0, 0.5, 1.0, 1.5};  // the limit measured by running
  double check_factor = 0.02;         // runs at (1 ∓ factor) × the computed limit
  double measured_tolerance = 1e-4;   // relative width of the bisection on runs
  long measured_steps = 2000;
  double damping_independence_tolerance = 1e-6;  // limit range over μΔt below this: "independent"
  double lengyel_sigma = 0.75, lengyel_mu_dt = 0.5;  // Lengyel's bound's counter-example (five-point)
  long lengyel_steps = 200;
};

struct WaveSpeedOptions {
  WaveWorkPrecisionOptions work;             // problem, grids, σ fractions (the limit is set per stencil)
  std::vector<double> targets_m{1e-4, 1e-5, 1e-6};  // errors whose cost is compared
  std::string baseline_stencil = "five_point";
  double material_gain = 1.5;            // a speed-up below this is "not material" (timing noise on a shared machine)
};

struct WaveStudiesOptions {
  std::string preset = "full";   // what the settings file called it ("full", "quick", …)
  std::vector<std::string> stencils{"five_point", "nine_point_half", "nine_point_isotropic", "paper_eq11"};
  WaveProblem problem;
  ConsistencyOptions consistency;
  ConvergenceStudyOptions convergence;  // its problem is `problem`
  WaveIsotropyOptions isotropy;
  WaveStabilityOptions stability;
  WaveSpeedOptions speed;
  // Checks itself (Ceres' Options::IsValid): false with the first problem in words.
  bool valid(std::string* why) const;
};

// The sections in order, each stored in the sink as it finishes (names: "settings",
// "consistency", "convergence", "isotropy", "stability", "speed"), and the summary record of the
// whole report (the headline findings, one per stencil).
Record run_wave_studies(const WaveStudiesOptions& options, StudySink& sink);

// The sections one by one (each a function of the options alone).
Record wave_settings_findings(const WaveStudiesOptions& o);
Record wave_consistency_findings(const WaveStudiesOptions& o);
Record wave_convergence_findings(const WaveStudiesOptions& o, const ProgressFactory& progress);
Record wave_isotropy_findings(const WaveStudiesOptions& o, const ProgressFactory& progress);
Record wave_stability_findings(const WaveStudiesOptions& o, const ProgressFactory& progress);
Record wave_speed_findings(const WaveStudiesOptions& o, const ProgressFactory& progress);

// The verdict of an order fit, stored with its inputs (rule "order_fit") so it can be decided again.
Record& store_order_verdict(Record& parent, const std::string& key, const OrderFit& fit, const OrderJudgement& j);

}  // namespace stoneskip
