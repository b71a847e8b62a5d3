#pragma once
// Convergence of the real-time stepper to the CVODE reference as its steps shrink.
//
// Two families of measurements, both against the reference (rtol ≤ 1e-10):
//  * the scheme alone (realtime_step, N equal steps, no contact logic) over a free-flight interval
//    and over an interval that holds the whole first contact: the error of the state at the end;
//    this isolates the integrator's order from the stepper's event handling;
//  * the whole stepper (run_realtime, flight step dt, contact step = ratio · dt): the state at a
//    time in free flight after the first bounce, the state at the end of the first contact, the
//    contact start and end times, the positions of every bounce, and (apart from the bounces)
//    where and when the stone sank.
// Each series gets the observed order (least squares with 95 % interval, pairwise), a verdict
// against the scheme's formal order with its reason (verification/convergence/order_fit.hpp: the
// interval decides, not the point estimate), and, for scalar quantities, Celik's GCI from the
// three finest runs.
//
// Why an order may not show (the events diagnostic): the right-hand side is only piecewise smooth;
// its kinks are the reference's located events (vertex crossings, a wet face's switch). A fixed
// step across one kink costs a local error O(h³) (order 3 at best for RK4); a step across several
// has an error constant that changes with h, so the slope fitted over steps that still hold
// several events per step is pre-asymptotic. The study lists the events inside the first contact,
// their spacing, and for each step of the scheme-alone contact series the fraction of its steps
// inside the contact that hold two or more events.
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
  // Whole stepper, fixed schemes: which kinks end a step (stone_stepper.hpp). `all` by default: a
  // step across a kink makes an O(h²)–O(h³) local error, so without it no scheme shows more than
  // order 2–3 through a contact, and the events' orders would say so, not the scheme's order.
  KinkSteps fixed_kinks = KinkSteps::all;
  // Whole stepper, adaptive schemes (bs32, dp54) in `schemes`: rtol = atol_m over these, descending.
  // Their errors are fitted against the tolerance, expected order 1 (an error-per-step controller
  // on a pair with local extrapolation makes a global error ∝ tol); the scheme alone is the pair's
  // fixed-step member (formal order 3 and 5).
  std::vector<double> adaptive_tolerances{1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10};
  std::vector<int> interval_steps{64, 128, 256, 512, 1024, 2048, 4096, 8192};  // scheme alone: steps per interval
  double reference_rtol = 1e-12;                 // rtol ≤ 1e-10: far below the stepper's errors
  double reference_atol = 1e-14;
  double check_factor = 100;                     // the check run: rtol × check_factor
  double floor_factor = 1;                       // fit only errors > floor_factor × |check − reference|
  double order_tolerance = 0.2;                  // a verdict of "formal order" needs the interval within this
  // Test the first correction term of the error's expansion, h^(p+1), and fit with it where it is
  // significant (verification/convergence/order_fit.hpp, OrderFitOptions): the coarse steps of a
  // 40 rev/s throw turn the stone by up to 1 rad a step, far from h → 0. Fixed steps only: an
  // adaptive scheme's error against its tolerance has no such expansion.
  bool correction_term = true;
  int workers = 2;
  ProgressFactory progress;  // how long runs are shown; empty: silently
};

struct ConvergenceSeries {
  std::string quantity;      // short name: "flight_interval_state", "contact1_end_time", ...
  std::string description;   // words for the report
  std::string unit;          // of the error
  std::string scheme;
  int formal_order = 0;      // the expected order: the scheme's, or 1 against a tolerance
  bool against_tolerance = false;  // h_s holds the adaptive scheme's tolerance, not a step
  std::vector<double> h_s;   // step size (the flight step for the whole stepper), or the tolerance
  std::vector<double> value; // the scalar measured (NaN for vector quantities)
  std::vector<double> error; // against the reference; NaN where the run failed
  std::vector<bool> in_fit;  // false: failed or below the reference's accuracy
  std::vector<bool> below_floor;  // true: left out because below the reference's accuracy or round-off
  // Per point (empty: not estimated): a bound on the round-off the N steps can accumulate, N ε
  // times the quantity's scale (a step's additions round at ε of the values they add to). An
  // error at or below it is not the scheme's truncation error (a scheme exact on the problem, as
  // rk4 on a parabola, shows round-off that grows with N), so it is left out of the fit.
  std::vector<double> roundoff;
  std::vector<std::string> notes;  // per point: empty, or why it is not in the fit
  double reference_error = 0;      // the reference's own error on this quantity
  OrderFit fit;
  OrderDecision decision;          // against formal_order ± order_tolerance, with its reason
  std::string left_out;            // "" or " (of 8 runs, left out: ...)": the points the fit lacks, why;
                                   // and "; its smallest error is …" where the reference may not resolve them
  bool has_gci = false;
  GciResult gci;
};

// Fills in_fit and notes from the errors and the reference's own error, then fits the order, judges
// it and (for scalar quantities) computes the GCI of the three finest runs. A series that does not
// converge with its smallest error within a decade of the reference's estimated error says, beside
// its verdict, that the reference may not resolve it.
void finish_series(ConvergenceSeries& s, const RealtimeConvergenceOptions& o);

// Steps of a uniform grid t0 + k h (k = 0 … steps − 1) that overlap [window_start, window_end],
// and how many of them hold two or more of the events (times; an event on a step boundary
// belongs to the step it ends; a step overlaps the window when they share a positive length).
struct EventCrowding {
  double h_s = 0;
  long steps_in_window = 0;
  long steps_with_two_or_more = 0;
  double fraction() const { return steps_in_window ? double(steps_with_two_or_more) / double(steps_in_window) : 0.0; }
};
EventCrowding crowding(const std::vector<double>& event_times_s, double t0_s, double h_s, long steps,
                       double window_start_s, double window_end_s);

struct ContactEvents {
  double start_s = 0, end_s = 0;           // the reference's first contact
  std::vector<double> times_s;             // located events inside it, start and end included
  double min_spacing_s = 0, median_spacing_s = 0;  // between consecutive events (NaN: fewer than 2)
  std::vector<EventCrowding> scheme_alone; // per step of the contact-interval series (interval_steps)
};

struct RealtimeConvergenceResult {
  std::string case_label;
  ThrowResult reference;           // rtol = reference_rtol, no trajectory
  double reference_rtol = 0, check_rtol = 0;
  double flight_interval_start_s = 0, flight_interval_end_s = 0;
  double contact_interval_start_s = 0, contact_interval_end_s = 0;
  double free_flight_time_s = 0;   // when the whole-stepper state is compared (NaN: no bounce)
  ContactEvents events;            // the events diagnostic (see above)
  std::vector<ConvergenceSeries> series;
  std::vector<std::string> problems;  // what could not be measured, in words
};

RealtimeConvergenceResult run_realtime_convergence(const ThrowProblem& problem, const RealtimeConvergenceOptions& o);

}  // namespace stoneskip
