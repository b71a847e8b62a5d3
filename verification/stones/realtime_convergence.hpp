#pragma once
// Convergence of the real-time stepper to the CVODE reference as its steps shrink (issue 4, item 2).
//
// Two families of measurements, both against the reference (rtol ≤ 1e-10):
//  * the scheme alone (realtime_step, N equal steps, no contact logic) over a free-flight interval
//    and over an interval that holds the whole first contact: the error of the state at the end;
//    this isolates the integrator's order from the stepper's event handling;
//  * the whole stepper (run_realtime, flight step dt, contact step = ratio · dt): the state at a
//    time in free flight after the first bounce, the state at the end of the first contact, the
//    contact start and end times, the positions of every bounce.
// Each series gets the observed order (least squares with 95 % interval, pairwise) set against
// the scheme's formal order, and, for scalar quantities, Celik's GCI from the three finest runs.
// The reference is CVODE at rtol 1e-12; a second run at 100× looser tolerance (1e-10) bounds its
// error from above (|check − reference| ≈ the check's error ≫ the reference's). Points whose
// error is below that bound are kept in the tables but left out of the fit.
#include <string>

#include "verification/study/progress.hpp"
#include <vector>

#include "verification/convergence/gci.hpp"
#include "verification/convergence/order_fit.hpp"
#include "verification/stones/throw_problem.hpp"

namespace stoneskip {

struct RealtimeConvergenceOptions {
  std::vector<Scheme> schemes{Scheme::semi_implicit_euler, Scheme::midpoint, Scheme::rk4};
  std::vector<double> dt_s{4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4};  // whole stepper: flight steps
  double contact_ratio = 0.1;                    // contact step = ratio · dt
  std::vector<int> interval_steps{64, 128, 256, 512, 1024, 2048, 4096, 8192};  // scheme alone: steps per interval
  double reference_rtol = 1e-12;                 // issue 4: rtol ≤ 1e-10
  double reference_atol = 1e-14;
  double check_factor = 100;                     // the check run: rtol × check_factor
  double floor_factor = 1;                       // fit only errors > floor_factor × |check − reference|
  int workers = 2;
  ProgressFactory progress;  // how long runs are shown; empty: silently
};

struct ConvergenceSeries {
  std::string quantity;      // short name: "flight_interval_state", "contact1_end_time", ...
  std::string description;   // words for the report
  std::string unit;          // of the error
  std::string scheme;
  int formal_order = 0;
  std::vector<double> h_s;   // step size (the flight step for the whole stepper)
  std::vector<double> value; // the scalar measured (NaN for vector quantities)
  std::vector<double> error; // against the reference; NaN where the run failed
  std::vector<bool> in_fit;  // false: failed or below the reference's accuracy
  std::vector<std::string> notes;  // per point: empty, or why it is not in the fit
  double reference_error = 0;      // the reference's own error on this quantity
  OrderFit fit;
  bool has_gci = false;
  GciResult gci;
};

struct RealtimeConvergenceResult {
  std::string case_label;
  ThrowResult reference;           // rtol = reference_rtol, no trajectory
  double reference_rtol = 0, check_rtol = 0;
  double flight_interval_start_s = 0, flight_interval_end_s = 0;
  double contact_interval_start_s = 0, contact_interval_end_s = 0;
  double free_flight_time_s = 0;   // when the whole-stepper state is compared (NaN: no bounce)
  std::vector<ConvergenceSeries> series;
  std::vector<std::string> problems;  // what could not be measured, in words
};

RealtimeConvergenceResult run_realtime_convergence(const ThrowProblem& problem, const RealtimeConvergenceOptions& o);

}  // namespace stoneskip
