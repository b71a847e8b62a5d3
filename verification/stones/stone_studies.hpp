#pragma once
// The stone studies: every question the stones report answers, as a function from
// settings (cases/studies/stones*.toml, resolved by the command line into the throws below) to
// findings (verification/study/record.hpp), section by section:
//   settings        the throws and their case files
//   convergence     the real-time stepper against CVODE as its steps shrink, for each water law;
//                   CVODE against its tolerance
//   work_precision  speed against error, real-time stepper and CVODE, for each water law; the
//                   CVODE restart strategies on spinning and non-spinning throws
//   work_precision_grid  the same over a grid of throws, on bounce counts and contact times; the
//                   adaptive stepper's default tolerance it supports
//   sweeps          bounce count against one parameter with bisected thresholds
//   count_ensembles the two solvers' paper-convention counts at a sample of the sweeps' values, on ensembles
//   hard_cases      throws chosen to break a solver; the largest stable step against speed
//   validation      each water law beside experiments and the seed's claims (and the paper's Fig.
//                   9); the laws ranked, and the cheapest that skips like a real stone
// Each section's record holds the numbers, tables, verdicts and computed reasons the report
// formats (reports/stones/); nothing in a report decides a verdict.
#include <string>
#include <utility>
#include <vector>

#include "verification/stones/bounce_sweep.hpp"
#include "verification/stones/count_ensembles.hpp"
#include "verification/stones/mesh_study.hpp"
#include "verification/stones/hard_cases.hpp"
#include "verification/stones/realtime_convergence.hpp"
#include "verification/stones/reference_tolerance.hpp"
#include "verification/stones/validation.hpp"
#include "verification/stones/work_precision.hpp"
#include "verification/stones/work_precision_grid.hpp"
#include "verification/study/study_sink.hpp"

namespace stoneskip {

// A throw of the study with the case file it came from (stored with the findings).
struct StudyThrow {
  std::string file;      // as given in the study file
  std::string case_text; // the case file as written
  ThrowProblem problem;
};

struct SweepAxisOptions {
  SweepParameter parameter = SweepParameter::spin_rev_s;
  std::vector<double> values;    // ascending
  double threshold_tolerance = 0.25;
};

// The CVODE restart strategies measured against each other: the
// work-precision study's CVODE runs only, on these throws under these laws.
struct RestartStudyOptions {
  std::vector<std::string> throws{"spin", "nospin"};   // as work_precision_throws (spinning and not)
  std::vector<RestartStrategy> strategies{RestartStrategy::every_event, RestartStrategy::every_crossing,
                                          RestartStrategy::at_jumps, RestartStrategy::never};
  std::vector<ReferenceMethod> methods{ReferenceMethod::bdf};
  std::vector<double> rtol{1e-6, 1e-8, 1e-10};
  int repeats = 1;
  double time_tolerance_s = 1e-7;  // WorkPrecisionOptions::restart_time_tolerance_s
  double error_factor = 2;         // WorkPrecisionOptions::restart_error_factor
};

struct StoneStudiesOptions {
  std::string preset = "full";
  int workers = 2;
  // The throws.
  StudyThrow convergence_throw, spin_throw, nospin_throw, sweep_base, clanet, bocquet, stable_step_base;
  StudyThrow flat_drop;  // optional (file empty when not given): a throw whose force jumps at landing
  std::vector<StudyThrow> hard;
  // The studies.
  RealtimeConvergenceOptions convergence;
  std::vector<WaterLaw> convergence_laws;  // each with its published C_w; the first in full; empty: the throw's own
  // Each law under each of these pressure distributions (the first pair in full); empty: the throw's own.
  std::vector<PressureDistribution> convergence_distributions;
  OrderJudgement convergence_judgement{1, 0.25, 0.25, "formal"};  // expected order set per scheme; tolerance, minimum slope
  ReferenceToleranceOptions reference_tolerance;
  double required_tolerance_drop = 100;  // CVODE's bounce-position error should fall this much from rtol 1e-6 to 1e-10
  WorkPrecisionOptions work_precision;
  // Which throws, by name: a study throw or spin_paper (the spinning throw, paper convention), with
  // "@law" for that throw under that water law with its published C_w ("nospin@planing").
  std::vector<std::string> work_precision_throws{"convergence", "nospin", "spin_paper"};
  RestartStudyOptions restarts;
  // The work-precision study over a grid of throws (optional: base file empty when not given); its
  // bs32 tolerances, truth tolerances and atol ratio are work_precision's.
  StudyThrow work_precision_grid_base;
  WorkPrecisionGridOptions work_precision_grid;
  std::vector<SweepAxisOptions> sweep_axes;
  int max_thresholds = 8;
  double sweep_reference_rtol = 1e-8, sweep_reference_atol = 1e-10;
  CountEnsembleOptions count_ensembles;  // the sweeps' paper-convention counts, solver against solver, on ensembles
  // Bounce counts against the stone's mesh (optional: base file empty when not given).
  StudyThrow mesh_base;
  MeshStudyOptions mesh;
  HardCaseOptions hard_cases;
  StableStepOptions stable_step;
  ValidationOptions validation;
  bool valid(std::string* why) const;
};

// A throw of the work-precision and restart studies: a study throw's name ([throws]: convergence,
// spin, nospin, ...) or "spin_paper" (the spinning throw in the paper convention), optionally with
// "@law": that throw under that water law with its published C_w. Empty when the entry names one;
// else what is wrong, in words.
std::string study_throw_problem(const std::string& entry);

// The sections in order, each stored in the sink as it finishes; returns the report-wide record.
Record run_stone_studies(const StoneStudiesOptions& options, StudySink& sink);

// The findings of each study (also used by tests on small settings).
Record convergence_findings(const RealtimeConvergenceResult& conv, const ReferenceToleranceResult& tol,
                            const OrderJudgement& judgement, double required_tolerance_drop);
// The series part alone (every law but the first: no reference-tolerance study).
Record convergence_series_findings(const RealtimeConvergenceResult& conv, const OrderJudgement& judgement);
Record work_precision_findings(const WorkPrecisionResult& wp, const WorkPrecisionOptions& o);
// The restart strategies: the summaries per method, rtol and strategy, and the verdict (rule
// restart_strategy) with its inputs; `default_restart` is the reference's default strategy.
Record restart_findings(const WorkPrecisionResult& wp, const WorkPrecisionOptions& o, RestartStrategy default_restart);
Record sweeps_findings(const std::vector<BounceSweepResult>& sweeps);
Record hard_cases_findings(const std::vector<HardCaseResult>& hard, const std::vector<StableStepRow>& stable,
                           const HardCaseOptions& ho, const StableStepOptions& so);
Record validation_findings(const ValidationResult& v, const ValidationOptions& o);

// A throw's history as a record (table "history", contacts, label, bounces, outcome).
Record history_record(const ThrowHistory& h);
// "8 m/s, 10 rev/s, physical, reference" → "8_m_s_10_rev_s_physical_reference"
std::string record_key(const std::string& label);

}  // namespace stoneskip
