#pragma once
// The stone studies (issue 4): every question the stones report answers, as a function from
// settings (cases/studies/stones*.toml, resolved by the command line into the throws below) to
// findings (verification/study/record.hpp), section by section:
//   settings        the throws and their case files
//   convergence     the real-time stepper against CVODE as its steps shrink; CVODE against its tolerance
//   work_precision  speed against error, real-time stepper and CVODE
//   sweeps          bounce count against one parameter with bisected thresholds
//   hard_cases      throws chosen to break a solver; the largest stable step against speed
//   validation      the model beside experiments and the seed's claims (and the paper's Fig. 9)
// Each section's record holds the numbers, tables, verdicts and computed reasons the report
// formats (reports/stones/); nothing in a report decides a verdict.
#include <string>
#include <utility>
#include <vector>

#include "verification/stones/bounce_sweep.hpp"
#include "verification/stones/hard_cases.hpp"
#include "verification/stones/realtime_convergence.hpp"
#include "verification/stones/reference_tolerance.hpp"
#include "verification/stones/validation.hpp"
#include "verification/stones/work_precision.hpp"
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

struct StoneStudiesOptions {
  std::string preset = "full";
  int workers = 2;
  // The throws.
  StudyThrow convergence_throw, spin_throw, nospin_throw, sweep_base, clanet, bocquet, stable_step_base;
  std::vector<StudyThrow> hard;
  // The studies.
  RealtimeConvergenceOptions convergence;
  OrderJudgement convergence_judgement{1, 0.25, 0.25, "formal"};  // expected order set per scheme; tolerance, minimum slope
  ReferenceToleranceOptions reference_tolerance;
  double required_tolerance_drop = 100;  // CVODE's bounce-position error should fall this much from rtol 1e-6 to 1e-10
  WorkPrecisionOptions work_precision;
  std::vector<std::string> work_precision_throws{"convergence", "nospin", "spin_paper"};  // which throws, by name
  std::vector<SweepAxisOptions> sweep_axes;
  int max_thresholds = 8;
  double sweep_reference_rtol = 1e-8, sweep_reference_atol = 1e-10;
  HardCaseOptions hard_cases;
  StableStepOptions stable_step;
  ValidationOptions validation;
  bool valid(std::string* why) const;
};

// The sections in order, each stored in the sink as it finishes; returns the report-wide record.
Record run_stone_studies(const StoneStudiesOptions& options, StudySink& sink);

// The findings of each study (also used by tests on small settings).
Record convergence_findings(const RealtimeConvergenceResult& conv, const ReferenceToleranceResult& tol,
                            const OrderJudgement& judgement, double required_tolerance_drop);
Record work_precision_findings(const WorkPrecisionResult& wp, const WorkPrecisionOptions& o);
Record sweeps_findings(const std::vector<BounceSweepResult>& sweeps);
Record hard_cases_findings(const std::vector<HardCaseResult>& hard, const std::vector<StableStepRow>& stable,
                           const HardCaseOptions& ho, const StableStepOptions& so);
Record validation_findings(const ValidationResult& v, const ValidationOptions& o);

// A throw's history as a record (table "history", contacts, label, bounces, outcome).
Record history_record(const ThrowHistory& h);
// "8 m/s, 10 rev/s, physical, reference" → "8_m_s_10_rev_s_physical_reference"
std::string record_key(const std::string& label);

}  // namespace stoneskip
