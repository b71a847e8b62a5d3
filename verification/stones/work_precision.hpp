#pragma once
// Speed against error: work-precision data for the real-time stepper over a
// range of steps and for CVODE (BDF and Adams, each with one or more restart strategies) over a
// range of tolerances, on several throws, each under one or more water laws.
// Error (the headline): the largest distance between a solver's bounce positions (the centre of
// mass where a contact ends with the stone taking off again) and those of a tight reference; for a
// throw whose reference never bounces, the distance between the points where the two sank
// (`headline` says which). The sinking point's error is always kept apart from the bounce
// positions (it is located differently and was, before it was located at all, the whole of the
// "bounce" error); also the first-touch and contact-time errors. The first-touch point is not
// used as the headline:
// when an edge of the polygon lands parallel to the water (a spin-free prism does), two vertices
// touch at once and "the first" is decided by round-off. Work: CPU time (minimum of repeated runs)
// and right-hand-side evaluations. A run whose contact list differs from the reference's (a
// missed, extra or merged contact) or that fails is listed as a failure with the reason, never
// dropped.
// Restart strategies (ReferenceOptions::restart): the truth is always CVODE with
// restarts at every event, at truth_rtol. For each method, rtol and strategy the study sums the
// cost over the throws and takes the worst contact-time error (RestartSummary); a strategy keeps
// the contact times where that error is at most restart_error_factor times every_event's own at
// the same method and rtol, or below restart_time_tolerance_s. RestartVerdict names the cheapest
// strategy (fewest right-hand sides) that keeps them at every method and rtol of the study.
#include <string>

#include "verification/study/progress.hpp"
#include <vector>

#include "verification/stones/throw_problem.hpp"

namespace stoneskip {

struct WorkPrecisionOptions {
  struct RealtimeFamily {
    Scheme scheme;
    double contact_ratio;  // fixed schemes: contact step = ratio · dt (adaptive: unused)
  };
  std::vector<RealtimeFamily> realtime{{Scheme::semi_implicit_euler, 0.1},
                                       {Scheme::midpoint, 0.1},
                                       {Scheme::rk4, 0.1},
                                       {Scheme::semi_implicit_euler, 0.01},
                                       {Scheme::bs32, 0.0}};
  std::vector<double> dt_s{1.0 / 60, 8e-3, 4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4};
  std::vector<double> adaptive_rtol{1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10};  // adaptive families: rtol = atol_m
  std::vector<ReferenceMethod> methods{ReferenceMethod::bdf, ReferenceMethod::adams};
  std::vector<RestartStrategy> restarts{ReferenceOptions{}.restart};  // the default only, unless asked
  // Each throw under each of these laws (with its published C_w); empty: each throw's own environment.
  std::vector<WaterLaw> laws;
  std::vector<double> rtol{1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9};
  double atol_ratio = 1e-2;    // atol = atol_ratio · rtol
  double truth_rtol = 1e-11;
  double truth_check_factor = 0.1;  // a second truth at rtol × this bounds the truth's own error
  int repeats = 3;             // CPU time: minimum over this many runs
  std::vector<double> target_errors_m{1e-2, 1e-3, 1e-4};
  double restart_time_tolerance_s = 1e-7;  // contact times this close to the truth are kept whatever every_event does
  double restart_error_factor = 2;         // ... or within this factor of every_event's error at the same rtol
  int workers = 2;
  ProgressFactory progress;  // how long runs are shown; empty: silently
};

struct WorkPoint {
  std::string family;        // "realtime rk4 (contact dt/10)", "CVODE bdf, restart at_jumps"
  bool realtime = true;
  bool adaptive = false;     // a real-time family whose setting is its tolerance (rtol = atol_m)
  ReferenceMethod method = ReferenceMethod::bdf;         // CVODE points
  RestartStrategy restart = RestartStrategy::every_event;  // CVODE points
  double setting = 0;        // dt_s (fixed real-time), rtol = atol_m (adaptive) or rtol (CVODE)
  bool ok = false;
  std::string problem;       // why it failed
  int bounces = 0;
  double headline_error_m = 0;          // the throw's headline error (WorkPrecisionThrow::headline); NaN on failure
  double bounce_position_error_m = 0;   // bounces only; NaN on failure or without a bounce
  double sink_position_error_m = 0;     // where it sank; NaN on failure or when the reference does not sink
  double touch_error_m = 0;
  double contact_time_error_s = 0;
  double cpu_s = 0;
  long rhs_evaluations = 0;
  long steps = 0;
  long segments = 0;         // CVODE: restarts + 1
};

// The cheapest setting of a family that reaches a target (headline) error.
struct CheapestSetting {
  double target_error_m = 0;
  std::string family;
  bool found = false;
  double setting = 0;
  double cpu_s = 0;
  long rhs_evaluations = 0;
  double error_m = 0;
};

// What a throw's headline error measures: the bounce positions when its reference bounces at all,
// otherwise the point where it sank.
enum class HeadlineError { bounce_position, sink_position };
const char* to_string(HeadlineError h);  // "bounce position", "sinking position"

struct WorkPrecisionThrow {
  std::string label;         // the throw's label, with the law when the study sets laws
  WaterLaw law = WaterLaw::newtonian;
  Convention convention = Convention::physical;
  ThrowResult truth;
  HeadlineError headline = HeadlineError::bounce_position;
  double truth_uncertainty_m = 0;   // headline difference between truth and truth check (NaN: lists differ)
  std::string truth_check_problem;
  std::string fixed_kinks;   // where the fixed schemes' steps end (KinkSteps: the throw's own, else none)
  std::vector<WorkPoint> points;
  std::vector<CheapestSetting> cheapest;  // per target and family
};

// One restart strategy at one method and rtol, over every throw (and law) of the study.
struct RestartSummary {
  ReferenceMethod method = ReferenceMethod::bdf;
  double rtol = 0;
  RestartStrategy restart = RestartStrategy::every_event;
  int throws = 0, failed = 0;          // failed: solve failed or contact list differs from the truth
  long rhs_evaluations = 0, steps = 0, segments = 0;
  double cpu_s = 0;                    // summed (minimum of repeats per throw)
  double worst_contact_time_error_s = 0;  // over the throws that did not fail; NaN if none
  double tolerance_s = 0;              // max(restart_time_tolerance_s, factor × every_event's worst)
  bool keeps_contact_times = false;    // no failure and worst ≤ tolerance_s
};

struct RestartVerdict {
  bool found = false;
  RestartStrategy restart = RestartStrategy::every_event;  // the cheapest that keeps contact times everywhere
  long rhs_evaluations = 0;            // its total over the study's CVODE points
  long every_event_rhs_evaluations = 0;  // every_event's total, for the ratio
  double cpu_s = 0, every_event_cpu_s = 0;
  std::string reason;                  // in words, computed
};

// The adaptive scheme's tolerance as the study chooses it: the loosest tolerance at which, and at
// every tighter one, every throw of the study keeps the truth's contact list (so its bounce count).
struct AdaptiveToleranceChoice {
  bool studied = false;        // the study ran an adaptive family
  std::string family;
  bool found = false;          // some tolerance keeps every throw's contacts
  double tolerance = 0;        // the choice
  double worst_contact_time_error_s = 0;  // over the throws at the choice
  double worst_headline_error_m = 0;
  long rhs_evaluations = 0;    // summed over the throws at the choice
  double default_tolerance = 0;  // the cases' default (kDefaultAdaptiveTolerance)
  std::vector<double> tolerances;        // every tolerance run, as given
  std::vector<int> throws_keeping_contacts;  // per tolerance: throws with the truth's contact list
  int throws = 0;              // the throws the choice is made on (physical convention)
  // Paper-convention throws, set aside: the printed equations create energy in a contact, so their
  // contact lists are chaotic (the stones report compares them on ensembles, section 3b), and the
  // cases' default serves the physical convention. Their labels.
  std::vector<std::string> set_aside;
};

// The loosest tolerance of the (first) adaptive family of `realtime` that, with every tighter one
// of adaptive_rtol, keeps the truth's contact list on every physical-convention throw.
AdaptiveToleranceChoice choose_adaptive_tolerance(const std::vector<WorkPrecisionThrow>& throws,
                                                  const std::vector<WorkPrecisionOptions::RealtimeFamily>& realtime,
                                                  const std::vector<double>& adaptive_rtol);

struct WorkPrecisionResult {
  std::vector<WorkPrecisionThrow> throws;
  AdaptiveToleranceChoice adaptive_choice;
  std::vector<RestartSummary> restarts;  // per method × rtol × strategy (when the study has restarts)
  RestartVerdict restart_verdict;
};

WorkPrecisionResult run_work_precision(const std::vector<ThrowProblem>& throws, const WorkPrecisionOptions& o);

}  // namespace stoneskip
