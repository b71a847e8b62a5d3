#pragma once
// Speed against error (issue 4, item 3): work-precision data for the real-time stepper over a
// range of steps and for CVODE (BDF and Adams) over a range of tolerances, on several throws.
// Error: the largest distance between a solver's bounce positions (the centre of mass where each
// contact ends: where the stone takes off again, or where it sank) and those of a tight reference;
// also the first-touch and contact-time errors. The first-touch point is not used as the headline:
// when an edge of the polygon lands parallel to the water (a spin-free prism does), two vertices
// touch at once and "the first" is decided by round-off. Work: CPU time (minimum of repeated runs)
// and right-hand-side evaluations. A run whose contact list differs from the reference's (a
// missed, extra or merged contact) or that fails is listed as a failure with the reason, never
// dropped.
#include <string>

#include "verification/study/progress.hpp"
#include <vector>

#include "verification/stones/throw_problem.hpp"

namespace stoneskip {

struct WorkPrecisionOptions {
  struct RealtimeFamily {
    Scheme scheme;
    double contact_ratio;  // contact step = ratio · dt
  };
  std::vector<RealtimeFamily> realtime{{Scheme::semi_implicit_euler, 0.1},
                                       {Scheme::midpoint, 0.1},
                                       {Scheme::rk4, 0.1},
                                       {Scheme::semi_implicit_euler, 0.01}};
  std::vector<double> dt_s{1.0 / 60, 8e-3, 4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4};
  std::vector<ReferenceMethod> methods{ReferenceMethod::bdf, ReferenceMethod::adams};
  std::vector<double> rtol{1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9};
  double atol_ratio = 1e-2;    // atol = atol_ratio · rtol
  double truth_rtol = 1e-11;
  double truth_check_factor = 0.1;  // a second truth at rtol × this bounds the truth's own error
  int repeats = 3;             // CPU time: minimum over this many runs
  std::vector<double> target_errors_m{1e-2, 1e-3, 1e-4};
  int workers = 2;
  ProgressFactory progress;  // how long runs are shown; empty: silently
};

struct WorkPoint {
  std::string family;        // "realtime rk4 (contact dt/10)", "CVODE bdf"
  bool realtime = true;
  double setting = 0;        // dt_s (realtime) or rtol (CVODE)
  bool ok = false;
  std::string problem;       // why it failed
  int bounces = 0;
  double bounce_position_error_m = 0;   // NaN on failure
  double touch_error_m = 0;
  double contact_time_error_s = 0;
  double cpu_s = 0;
  long rhs_evaluations = 0;
  long steps = 0;
};

// The cheapest setting of a family that reaches a target error.
struct CheapestSetting {
  double target_error_m = 0;
  std::string family;
  bool found = false;
  double setting = 0;
  double cpu_s = 0;
  long rhs_evaluations = 0;
  double error_m = 0;
};

struct WorkPrecisionThrow {
  std::string label;
  ThrowResult truth;
  double truth_uncertainty_m = 0;   // bounce-position difference between truth and truth check (NaN: lists differ)
  std::string truth_check_problem;
  std::vector<WorkPoint> points;
  std::vector<CheapestSetting> cheapest;  // per target and family
};

struct WorkPrecisionResult {
  std::vector<WorkPrecisionThrow> throws;
};

WorkPrecisionResult run_work_precision(const std::vector<ThrowProblem>& throws, const WorkPrecisionOptions& o);

}  // namespace stoneskip
