#pragma once
// Tolerance proportionality of the CVODE reference: the error of the reference
// at tolerance rtol, measured against a much tighter run, should fall in proportion to rtol
// (slope ≈ 1 on a log–log plot) if its error control works through the located contact events.
#include <string>

#include "verification/study/progress.hpp"
#include <vector>

#include "verification/convergence/order_fit.hpp"
#include "verification/stones/throw_problem.hpp"

namespace stoneskip {

struct ReferenceToleranceOptions {
  std::vector<double> rtol{1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10};
  double truth_rtol = 1e-12;        // the "exact" solution
  double atol_ratio = 1e-2;         // atol = atol_ratio · rtol (SI units, positions ~ 1 m)
  double drop_from_rtol = 1e-6;     // the error drop is measured between these two tolerances
  double drop_to_rtol = 1e-10;      //   (both must be in rtol for it to be measured)
  ReferenceMethod method = ReferenceMethod::bdf;
  int workers = 2;
  ProgressFactory progress;  // how long runs are shown; empty: silently
};

struct ReferenceTolerancePoint {
  double rtol = 0;
  bool ok = false;
  std::string problem;
  int bounces = 0;
  double bounce_position_error_m = 0;   // largest error of the centre of mass where a contact ends
  double contact_time_error_s = 0;      // largest start/end time error over the contacts
  double final_position_error_m = 0;    // where the throw ended (same end reason only)
  long rhs_evaluations = 0;
  long steps = 0;
  double cpu_s = 0;
};

struct ReferenceToleranceResult {
  std::string case_label;
  std::string method;
  ThrowResult truth;
  std::vector<ReferenceTolerancePoint> points;
  OrderFit bounce_position_fit;   // slope of log error against log rtol
  OrderFit contact_time_fit;
  double drop_from_rtol = 0, drop_to_rtol = 0;  // the tolerances of error_drop
  double error_drop = 0;  // bounce-position error at drop_from_rtol over that at drop_to_rtol (NaN: not run)
};

ReferenceToleranceResult run_reference_tolerance(const ThrowProblem& p, const ReferenceToleranceOptions& o);

}  // namespace stoneskip
