#include "solvers/reference/cvode_stone.hpp"

// The problem (model/README.md §1.3): y = [x, v, q, L] ∈ R¹³,
//   dx/dt = v,  m dv/dt = F_gravity + F_air + Σ F_i,  dq/dt = ½ (0, ω) ⊗ q,  dL/dt = Σ τ_i,
// with the right-hand side of model/stone/rigid_body.hpp (still water). Root finding
// (solvers/realtime/stone_events.hpp) locates every vertex crossing (and, with
// RestartStrategy::every_event, every face and air switch); at the events the strategy names, the
// integration restarts with CVodeReInit, the quaternion renormalised. Elsewhere it continues: the
// event is logged (contacts, sinking), the discrete mode and the watched root directions are
// updated, and CVODE keeps its history across the kink — its Nordsieck history then interpolates
// a right-hand side that is only C¹ (C⁰ in its derivative for planing) across the event, the local
// error estimate of the step that straddles it grows, and the error test shrinks that step (and may
// lower the order) until the local error is within tolerance again: accuracy is kept by error
// control instead of by a restart. Absolute tolerances per component: absolute_tolerance.hpp.
//
// Linear algebra: BDF uses Newton iteration with SUNDIALS' dense direct solver and CVODE's internal
// difference-quotient Jacobian (13 × 13: cheap, and no hand-written Jacobian of the clipped force
// to get wrong). Adams uses the fixed-point (functional) iteration: the contact stiffness
// (2 C_w ρ_w |u| S / m, ~10³ s⁻¹) is far below what the accuracy-limited steps resolve anyway.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include "solvers/realtime/clocks.hpp"
#include "solvers/reference/absolute_tolerance.hpp"
#include "solvers/realtime/filippov_sliding.hpp"
#include "solvers/realtime/sliding_record.hpp"
#include "solvers/realtime/stone_events.hpp"

namespace stoneskip {

namespace {

constexpr int kMaxEventsPerMs = 1000000;  // bounds the ring of event times below
// Sliding (filippov_sliding.hpp): every kSlideProbeSteps steps the probe looks for a sliding mode
// (a loaded-region switch at zero that attracts). It used to look only where 500 steps advanced
// less than 1 µs, but BDF at the default rtol 1e-10 can also step along a sliding mode without
// stalling: on a lens throw (−0.05 rev/s, 8°, 6 m/s) for 2.3 ms, the state held within 1e-6 m/s of
// face 9's switch, and it then sank 1.65e-4 s off its own solution at 1e-12 and bs32's (measured
// 5 December); probed every 20 steps it slides from where rtol 1e-12 does and sinks with them.
// Stepping along one unnoticed also ended 3 of 324 lens throws in CV_ERR_FAILURE, at a state off
// every switch; probed so, all 324 sink. The probe costs one evaluation of the switches every 20
// steps: nothing measurable on prism throws (same steps, same wall clock), and it saves 15 % of the
// right-hand sides on lens throws (solvers/README.md). The collapse guard waits for max_steps_per_ms (20 000 by default). A solve slides at most
// kMaxSlides times.
constexpr long kSlideProbeSteps = 20;
constexpr std::size_t kMaxSlides = 100;
// |q| drifts between restarts by the accumulated integration error; above this (an attitude error
// of ~1e-6 rad) the drift is named in outcome_detail.
constexpr double kReportedQuaternionDrift = 1e-6;

// A SUNDIALS call that returned an error: thrown by check(), caught in run_reference().
struct CvodeFailure {
  std::string message;
};

// Every SUNDIALS return code goes through here (the SUNDIALS examples' check_flag habit).
void check(int flag, const char* call) {
  if (flag >= 0) return;
  char* name = CVodeGetReturnFlagName(flag);
  std::string message = std::string(call) + " failed: " + (name ? name : "?");
  std::free(name);
  throw CvodeFailure{message};
}

template <class T>
T* check_ptr(T* p, const char* call) {
  if (!p) throw CvodeFailure{std::string(call) + " returned NULL (out of memory?)"};
  return p;
}

std::string describe(const ReferenceOptions& o) {
  std::ostringstream s;
  s << "reference (CVODE " << (o.method == ReferenceMethod::bdf ? "BDF" : "Adams") << " rtol=" << o.rtol
    << " atol=" << o.atol << (o.atol_scaling == ToleranceScaling::per_component ? " m per component" : " uniform")
    << ", restart " << to_string(o.restart) << ")";
  return s.str();
}

// What the callbacks see.
struct Problem {
  const Stone& stone;
  const Environment& env;
  StoneEvents& events;
  FilippovSliding& sliding;
  // Up to two faces' loaded-region switches treated apart (filippov_sliding.hpp), each with one
  // more root function: sliding along one switch or two (the root: the exit), or held on the side a
  // sliding left to (the root: g crossing back).
  SlidingRecord record;
  // Load evaluations CVODE does not count: a sliding right-hand side evaluates the loads twice (f₀
  // and f₁) on one switch and four times on two, its exit function as often again
  // (filippov_sliding.hpp).
  long uncounted_loads = 0;
  std::string nan_detail;  // the first non-finite value met in a callback
};

void note_nan(Problem& p, const char* where, double t) {
  if (!p.nan_detail.empty()) return;
  std::ostringstream m;
  m << "NaN or infinity in the " << where << " at t = " << t << " s";
  p.nan_detail = m.str();
}

int rhs_callback(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
  auto& p = *static_cast<Problem*>(user);
  const double* yy = N_VGetArrayPointer(y);
  double* dy = N_VGetArrayPointer(ydot);
  for (int k = 0; k < kStateSize; ++k) {
    if (!std::isfinite(yy[k])) {
      note_nan(p, "state", t);
      return 1;  // recoverable: CVODE retries with a smaller step, and gives up after a few
    }
  }
  if (p.record.rules().empty())
    rigid_body_rhs(p.stone, p.env, yy, dy);
  else
    p.uncounted_loads += p.sliding.rhs(p.record.rules(), yy, dy) - 1;
  for (int k = 0; k < kStateSize; ++k) {
    if (!std::isfinite(dy[k])) {
      note_nan(p, "right-hand side", t);
      return 1;
    }
  }
  return 0;
}

int root_callback(sunrealtype t, N_Vector y, sunrealtype* g, void* user) {
  auto& p = *static_cast<Problem*>(user);
  if (p.events.evaluate(N_VGetArrayPointer(y), g)) {
    if (!p.record.rules().empty())
      p.uncounted_loads += p.sliding.roots(p.record.rules(), N_VGetArrayPointer(y), g + p.events.count());
    return 0;
  }
  note_nan(p, "state or a root function", t);
  return -1;  // unrecoverable: CVode returns CV_RTFUNC_FAIL
}

// CVODE's messages are kept (the last one explains a failure) instead of printed.
void error_callback(int code, const char* module, const char* function, char* msg, void* user) {
  if (code == CV_WARNING) return;
  auto* last = static_cast<std::string*>(user);
  *last = std::string(module) + "::" + function + ": " + msg;
}

// The SUNDIALS objects of one solve, freed in reverse order.
struct CvodeObjects {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr;
  N_Vector dky = nullptr;  // an output time's state, interpolated (sampled runs)
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  SUNNonlinearSolver NLS = nullptr;
  void* mem = nullptr;
  CvodeObjects() = default;
  CvodeObjects(const CvodeObjects&) = delete;
  CvodeObjects& operator=(const CvodeObjects&) = delete;
  ~CvodeObjects() {
    if (mem) CVodeFree(&mem);
    if (NLS) SUNNonlinSolFree(NLS);
    if (LS) SUNLinSolFree(LS);
    if (A) SUNMatDestroy(A);
    if (dky) N_VDestroy(dky);
    if (y) N_VDestroy(y);
    if (ctx) SUNContext_Free(&ctx);
  }
};

class ReferenceSolve {
 public:
  ReferenceSolve(const Stone& stone, const Environment& env, const ReferenceOptions& o, ThrowResult& r)
      : stone_(stone), env_(env), o_(o), r_(r), events_(stone, env, o.restart == RestartStrategy::every_event),
        sliding_(stone, env), problem_{stone, env, events_, sliding_, {}, 0, {}}, found_(events_.count() + static_cast<int>(kMaxTreatedFaces)),
        event_times_(std::clamp(o.max_events_per_ms, 1, kMaxEventsPerMs), -1e300) {}

  void run(const RigidState& initial);

 private:
  bool check_inputs(const RigidState& initial);
  void setup(const RigidState& s0);
  void integrate();
  void finish(const RigidState& s0);
  void restart(double t);
  void continue_after_event();
  void set_roots();          // the root functions of the mode (the events', and a sliding's exit)
  bool try_sliding();        // where the steps collapse: slide along an attracting switch, if one is there
  void face_root_found(double t, const RigidState& s);  // a sliding's exit, or a hold's end
  void count_steps_to_event();
  void add_segment_stats();
  RigidState state() const;  // the current CVODE vector as a state, quaternion normalised
  void renormalise();
  void sample(double t, const RigidState& s);
  bool handle_root(double t);  // false: the throw ended (sank) or failed
  void fail(const std::string& why);
  double energy(const RigidState& s) const { return mechanical_energy(stone_, env_, s).total_J(); }

  const Stone& stone_;
  const Environment& env_;
  const ReferenceOptions& o_;
  ThrowResult& r_;
  StoneEvents events_;
  FilippovSliding sliding_;
  Problem problem_;
  CvodeObjects cv_;
  std::string last_error_;
  ContactLog log_;
  std::vector<int> found_;
  std::vector<int> root_directions_;
  int roots_now_ = 0;                // the number of root functions CVODE has
  // Filippov sliding (filippov_sliding.hpp; the rules and slides in problem_.record): why a
  // collapse found none.
  std::string no_slide_;
  long probe_steps_ = 0;             // the sliding probe's window: total steps where it began
  std::vector<double> event_times_;  // ring of the last max_events_per_ms event times
  long event_count_ = 0;
  long window_steps_ = 0;            // step-collapse guard: total steps and t where the window began
  double window_t_ = 0;
  long resynced_ = 0;
  double max_q_drift_ = 0;
  bool in_contact_mode_ = false;     // some vertex under water, per the event mode
  long segment_steps_counted_ = 0;   // steps of this segment already attributed (contact or not)
  long restarts_ = 0, continued_events_ = 0;
  double t_ = 0;
  bool done_ = false;
  // The last state CVODE returned (at a root, a t_max stop, a step, or its last accepted step when it
  // gave up), and its time: a failed solve ends there, for CVODE 6.4 leaves its output vector
  // zeroed when it fails on the first step after a restart (the throw's end read as the origin at
  // rest), and a SUNDIALS call that throws leaves no state to trust.
  RigidState last_good_;
  double last_good_t_ = 0;
  double release_energy_J_ = 0;  // the runaway test of fail()
  double rcheck_restart_t_ = -1;  // the event a refused continuation was restarted at (once each)
  long rcheck_restarts_ = 0;
  void remember_good(double t) {
    last_good_ = state();
    last_good_t_ = t;
  }
};

bool ReferenceSolve::check_inputs(const RigidState& initial) {
  std::ostringstream bad;
  if (!(o_.rtol > 0) || !(o_.atol > 0)) bad << "tolerances must be positive (rtol " << o_.rtol << ", atol " << o_.atol << ")";
  else if (!(o_.t_max_s > 0) || !std::isfinite(o_.t_max_s)) bad << "t_max_s must be positive and finite";
  else if (!(o_.output_dt_s >= 0)) bad << "output_dt_s must be >= 0";
  else if (o_.max_steps <= 0) bad << "max_steps must be positive";
  else if (o_.max_steps_per_ms <= 0) bad << "max_steps_per_ms must be positive";
  else if (o_.max_events_per_ms <= 0 || o_.max_events_per_ms > kMaxEventsPerMs)
    bad << "max_events_per_ms must be in [1, " << kMaxEventsPerMs << "]";
  else if (!(o_.max_step_s >= 0)) bad << "max_step_s must be >= 0";
  else if (!(stone_.bounding_radius_m > 0)) bad << "the stone has no size (bounding radius 0)";
  else if (const std::string e = environment_problem(env_); !e.empty()) bad << "environment: " << e;
  if (!bad.str().empty()) {
    fail("invalid reference problem: " + bad.str());
    return false;
  }
  const StateVector y = to_vector(initial);
  for (int k = 0; k < kStateSize; ++k) {
    if (!std::isfinite(y[k])) {
      std::ostringstream m;
      m << "the initial state is not finite (component " << k << " of [x, v, q, L] is " << y[k] << ")";
      fail(m.str());
      return false;
    }
  }
  if (!(initial.orientation.norm() > 0)) {
    fail("the initial quaternion is zero");
    return false;
  }
  return true;
}

void ReferenceSolve::setup(const RigidState& s0) {
  check(SUNContext_Create(nullptr, &cv_.ctx), "SUNContext_Create");
  cv_.y = check_ptr(N_VNew_Serial(kStateSize, cv_.ctx), "N_VNew_Serial");
  cv_.dky = check_ptr(N_VNew_Serial(kStateSize, cv_.ctx), "N_VNew_Serial");
  const StateVector y0 = to_vector(s0);
  std::copy(y0.begin(), y0.end(), N_VGetArrayPointer(cv_.y));
  const bool bdf = o_.method == ReferenceMethod::bdf;
  cv_.mem = check_ptr(CVodeCreate(bdf ? CV_BDF : CV_ADAMS, cv_.ctx), "CVodeCreate");
  check(CVodeSetErrHandlerFn(cv_.mem, error_callback, &last_error_), "CVodeSetErrHandlerFn");
  check(CVodeInit(cv_.mem, rhs_callback, 0.0, cv_.y), "CVodeInit");
  check(CVodeSetUserData(cv_.mem, &problem_), "CVodeSetUserData");
  {
    const StateVector atol = absolute_tolerances(o_, state_scales(stone_, s0, env_.gravity_m_s2));
    N_Vector abstol = check_ptr(N_VNew_Serial(kStateSize, cv_.ctx), "N_VNew_Serial");
    std::copy(atol.begin(), atol.end(), N_VGetArrayPointer(abstol));
    const int flag = CVodeSVtolerances(cv_.mem, o_.rtol, abstol);  // CVODE keeps its own copy
    N_VDestroy(abstol);
    check(flag, "CVodeSVtolerances");
  }
  if (bdf) {
    cv_.A = check_ptr(SUNDenseMatrix(kStateSize, kStateSize, cv_.ctx), "SUNDenseMatrix");
    cv_.LS = check_ptr(SUNLinSol_Dense(cv_.y, cv_.A, cv_.ctx), "SUNLinSol_Dense");
    check(CVodeSetLinearSolver(cv_.mem, cv_.LS, cv_.A), "CVodeSetLinearSolver");  // no Jacobian: difference quotients
  } else {
    cv_.NLS = check_ptr(SUNNonlinSol_FixedPoint(cv_.y, 0, cv_.ctx), "SUNNonlinSol_FixedPoint");
    check(CVodeSetNonlinearSolver(cv_.mem, cv_.NLS), "CVodeSetNonlinearSolver");
  }
  if (o_.max_step_s > 0) check(CVodeSetMaxStep(cv_.mem, o_.max_step_s), "CVodeSetMaxStep");
  check(CVodeSetMaxHnilWarns(cv_.mem, -1), "CVodeSetMaxHnilWarns");
  set_roots();
  check(CVodeSetStopTime(cv_.mem, o_.t_max_s), "CVodeSetStopTime");
}

// Steps since the last event go to the mode they were taken in (contact: some vertex under water).
void ReferenceSolve::count_steps_to_event() {
  long nst = 0;
  check(CVodeGetNumSteps(cv_.mem, &nst), "CVodeGetNumSteps");
  if (in_contact_mode_) r_.stats.contact_steps += nst - segment_steps_counted_;
  segment_steps_counted_ = nst;
  in_contact_mode_ = events_.submerged_vertices() > 0;
}

// CVODE 6.4's CVodeReInit zeroes its counters: they are summed here, segment by segment.
void ReferenceSolve::add_segment_stats() {
  long nst = 0, nfe = 0, nfels = 0, nge = 0, netf = 0, nni = 0;
  check(CVodeGetNumSteps(cv_.mem, &nst), "CVodeGetNumSteps");
  check(CVodeGetNumRhsEvals(cv_.mem, &nfe), "CVodeGetNumRhsEvals");
  if (o_.method == ReferenceMethod::bdf) check(CVodeGetNumLinRhsEvals(cv_.mem, &nfels), "CVodeGetNumLinRhsEvals");
  check(CVodeGetNumGEvals(cv_.mem, &nge), "CVodeGetNumGEvals");
  check(CVodeGetNumErrTestFails(cv_.mem, &netf), "CVodeGetNumErrTestFails");
  check(CVodeGetNumNonlinSolvIters(cv_.mem, &nni), "CVodeGetNumNonlinSolvIters");
  SolverStats& s = r_.stats;
  s.steps += nst;
  s.rhs_evaluations += nfe + nfels;  // right-hand sides for the difference-quotient Jacobian too
  s.root_evaluations += nge;
  s.error_test_failures += netf;
  s.nonlinear_iterations += nni;
  s.segments += 1;
  segment_steps_counted_ = 0;
}

void ReferenceSolve::restart(double t) {
  count_steps_to_event();
  add_segment_stats();
  ++restarts_;
  check(CVodeReInit(cv_.mem, t, cv_.y), "CVodeReInit");
  set_roots();
  check(CVodeSetStopTime(cv_.mem, o_.t_max_s), "CVodeSetStopTime");
}

// The events' root functions, and with a face treated apart one more (a sliding's exit value, a
// hold's value), watched falling through zero. CVodeRootInit (which resets the directions) only
// where the count changes.
void ReferenceSolve::set_roots() {
  const int extra = static_cast<int>(problem_.record.rules().size());
  const int n = events_.count() + extra;
  if (n != roots_now_) {
    check(CVodeRootInit(cv_.mem, n, root_callback), "CVodeRootInit");
    check(CVodeSetNoInactiveRootWarn(cv_.mem), "CVodeSetNoInactiveRootWarn");
    roots_now_ = n;
  }
  root_directions_.assign(events_.directions(), events_.directions() + events_.count());
  root_directions_.insert(root_directions_.end(), static_cast<std::size_t>(extra), -1);
  check(CVodeSetRootDirection(cv_.mem, root_directions_.data()), "CVodeSetRootDirection");
}

// Where the steps collapse (the sliding probe, the collapse guard, or CVODE failing its error test
// or convergence), a sliding mode on loaded-region switches is the one cause this solver can treat
// (filippov_sliding.hpp): when one switch at zero attracts from both sides, or two at zero attract
// on their intersection (a second face's switch reached while sliding on one, say), the solve
// restarts from the last good state on the sliding field. A collapse while sliding on two, or on
// one with no second switch to add, fails the solve; so does sliding more than kMaxSlides times.
bool ReferenceSolve::try_sliding() {
  const int sliding = problem_.record.sliding_count();
  if (!sliding_.available() || sliding == 2) return false;  // says nothing where none can be
  if (problem_.record.slides() >= kMaxSlides) {
    no_slide_ = "it slid " + std::to_string(problem_.record.slides()) + " times already (kMaxSlides)";
    return false;
  }
  const SlidingChoice c = sliding_.attracting(last_good_, problem_.record.rules());
  if (c.face < 0) {
    no_slide_ = c.why;
    return false;
  }
  if (sliding == 1 && !c.changes_sliding()) {  // the switch it slides on: nothing to add or hand over
    no_slide_ = "no other loaded-region switch is at zero there";
    return false;
  }
  const StateVector y = to_vector(last_good_);
  std::copy(y.begin(), y.end(), N_VGetArrayPointer(cv_.y));
  t_ = last_good_t_;
  problem_.record.start(c, t_);
  restart(t_);
  window_steps_ = probe_steps_ = r_.stats.steps;
  window_t_ = t_;
  return true;
}

// The faces' own roots: a sliding's exit (a face is held on the side the state leaves to, and where
// two slid, the other slides on alone where its switch attracts), or a hold's end (g crossed zero
// against it, or the face's polygon went: the loads decide from the state again, unless a switch now
// attracts, where the state slides at once instead of waiting for its steps to collapse). The
// caller restarts.
void ReferenceSolve::face_root_found(double t, const RigidState& s) {
  const StateVector y = to_vector(s);
  const int* found = found_.data() + events_.count();
  SlidingRecord& record = problem_.record;
  bool hold_ended = false;
  for (std::size_t k = 0; k < record.rules().size(); ++k) hold_ended = hold_ended || (!record.rules()[k].sliding && found[k]);
  record.set(sliding_.after_roots(record.rules(), found, y.data()), t);
  if (!hold_ended || record.sliding_count() > 0 || record.slides() >= kMaxSlides) return;
  const SlidingChoice c = sliding_.attracting(s, record.rules());
  if (c.face >= 0) record.start(c, t);
}

// No restart: CVODE keeps its history; only the directions to watch change with the mode. CVODE
// re-evaluates the root functions at the root before searching on (cvRcheck2), so the new mode is
// seen from the event on.
void ReferenceSolve::continue_after_event() {
  count_steps_to_event();
  ++continued_events_;
  set_roots();
}

RigidState ReferenceSolve::state() const {
  RigidState s = from_vector(N_VGetArrayPointer(cv_.y));
  s.orientation.normalize();
  return s;
}

void ReferenceSolve::renormalise() {
  double* y = N_VGetArrayPointer(cv_.y);
  double* q = y + kQuaternion;
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  max_q_drift_ = std::max(max_q_drift_, std::abs(n - 1.0));
  for (int k = 0; k < 4; ++k) q[k] /= n;
}

void ReferenceSolve::sample(double t, const RigidState& s) {
  const bool wet = events_.submerged_vertices() > 0;
  const double wetted = wet ? water_loads(stone_, env_, s).wetted_area_m2 : 0.0;
  log_.observe_wetted_area(wetted);
  if (!o_.record_trajectory) return;
  TrajectorySample p;
  p.t_s = t;
  p.state = s;
  p.angular_velocity_rad_s = angular_velocity(stone_, s);
  p.energy_J = energy(s);
  p.wetted_area_m2 = wetted;
  r_.trajectory.push_back(p);
}

void ReferenceSolve::fail(const std::string& why) {
  r_.outcome = Outcome::failed;
  // The paper convention's printed forces create energy (spec §1.6): a thousandfold gain by the last
  // good state is the model running away, not CVODE failing, and is named so, as bs32 names it.
  const double e = last_good_t_ > 0 ? energy(last_good_) : 0;
  const bool ran_away = env_.convention == Convention::paper && std::isfinite(e) &&
                        e > 1e3 * std::max(std::abs(release_energy_J_), 1e-3);
  std::ostringstream m;
  if (ran_away)
    m << "the paper convention's printed forces ran the stone away (model/README.md §1.6; a thousandfold energy gain: " << e
      << " J at t = " << last_good_t_ << " s against " << release_energy_J_ << " J at release); ";
  r_.outcome_detail = m.str() + why;
  done_ = true;
}

bool ReferenceSolve::handle_root(double t) {
  // Chattering guard: more than max_events_per_ms events within 1 ms fails the solve.
  const std::size_t slot = static_cast<std::size_t>(event_count_ % static_cast<long>(event_times_.size()));
  if (t - event_times_[slot] < 1e-3) {
    std::ostringstream m;
    m << "more than " << o_.max_events_per_ms << " events within 1 ms before t = " << t
      << " s (chattering at the surface; ReferenceOptions::max_events_per_ms)";
    fail(m.str());
    return false;
  }
  event_times_[slot] = t;
  ++event_count_;
  r_.event_times_s.push_back(t);

  check(CVodeGetRootInfo(cv_.mem, found_.data()), "CVodeGetRootInfo");
  // The face's own root (a sliding's exit, a hold's end): the rule changes, after a restart.
  bool face_root = false;
  for (std::size_t k = 0; k < problem_.record.rules().size(); ++k)
    face_root = face_root || found_[static_cast<std::size_t>(events_.count()) + k] != 0;
  // The returned vector is CVODE's output copy: renormalising it changes the integration only
  // where a restart takes it as the new initial value.
  renormalise();
  const RigidState s = state();
  const EventChange c = events_.apply(found_.data(), s);
  resynced_ += c.resynced_vertices;
  const int nv = events_.vertex_count();
  // Spec §1.8: a contact starts when the first vertex goes under and ends when the last comes out.
  if (c.submerged_before == 0 && c.submerged_after > 0) {
    const Mat3 R = s.orientation.toRotationMatrix();
    const int j = c.deepest_new_vertex >= 0 ? c.deepest_new_vertex : 0;
    log_.start(t, s, world_vertex(stone_, s, R, j), energy(s));
  }
  sample(t, s);
  if (c.submerged_before > 0 && c.submerged_after == 0) log_.end(t, s, energy(s), true);
  if (c.submerged_after == nv) {
    // Completely under water: nothing here lifts a submerged stone (model/README.md §1.8).
    log_.end(t, s, energy(s), false);
    r_.outcome = Outcome::sank;
    std::ostringstream m;
    m << "completely under water at t = " << t << " s";
    r_.outcome_detail = m.str();
    return false;
  }
  // at_jumps also restarts where a contact starts: the step that found it may come from flight,
  // long enough to hold a whole submersion whose end CVODE's error test cannot tell from flight
  // (in the paper convention a fully submerged stone's opposite faces cancel).
  const bool contact_starts = c.submerged_before == 0 && c.submerged_after > 0;
  if (face_root) face_root_found(t, s);
  const bool restart_here = face_root || o_.restart == RestartStrategy::every_event || o_.restart == RestartStrategy::every_crossing ||
                            (o_.restart == RestartStrategy::at_jumps && (c.force_jumps() || contact_starts));
  if (restart_here)
    restart(t);
  else
    continue_after_event();
  return true;
}

void ReferenceSolve::run(const RigidState& initial) {
  r_.release_position_m = initial.position_m;
  r_.final_state = initial;
  if (!check_inputs(initial)) return;

  // 1. The discrete mode at t = 0 (a throw may start in the water).
  RigidState s0 = initial;
  s0.orientation.normalize();
  last_good_ = s0;
  last_good_t_ = 0;
  release_energy_J_ = energy(s0);
  events_.reset(s0);
  const int nv = events_.vertex_count();
  if (events_.submerged_vertices() > 0) {
    const DeepestPoint deep = deepest_point(stone_, s0);
    log_.start(0, s0, deep.position_m, energy(s0));
  }
  sample(0, s0);
  r_.outcome = Outcome::time_limit;
  r_.outcome_detail = "reached t_max";
  t_ = 0;
  if (events_.submerged_vertices() == nv) {
    log_.end(0, s0, energy(s0), false);
    r_.outcome = Outcome::sank;
    r_.outcome_detail = "completely under water at t = 0 s";
    finish_result(r_, log_, s0, 0);
    return;
  }

  // 2. CVODE, 3. the main loop. Every failure, a CVODE return flag or a SUNDIALS call that throws,
  // ends here with the contacts found so far kept (4.).
  in_contact_mode_ = events_.submerged_vertices() > 0;
  try {
    setup(s0);
    integrate();
  } catch (const CvodeFailure& e) {
    std::ostringstream m;
    m << e.message << " at t = " << t_ << " s";
    fail(m.str());
  }
  finish(s0);
}

// 3. Toward t_max, step by step when sampled, to an event (a restart there, or not, by the
// strategy). CVODE is always asked for t_max, never for an output time: it bounds the first step
// of each segment by the distance to the time it is asked for (cvHin), so asking for output times
// made the steps, and the solution within its tolerance, depend on the sampling. Sampled runs take
// one step a call (CV_ONE_STEP) and interpolate the output times inside it (CVodeGetDky, the
// interpolant CV_NORMAL itself uses): they take the steps of a run that records nothing.
void ReferenceSolve::integrate() {
  const bool sampled = o_.record_trajectory && o_.output_dt_s > 0;
  const double eps = std::numeric_limits<double>::epsilon();
  long k_out = 1;
  double t_left = 0;  // the time the last call returned (the interpolant reaches back to here)
  // The output times in (t_left, t_to] (all at or before t_max), interpolated in CVODE's last step;
  // one an event has just reached (within round-off of t_left) was sampled there.
  auto samples_to = [&](double t_to) {
    for (;; ++k_out) {
      const double tk = std::min(o_.t_max_s, static_cast<double>(k_out) * o_.output_dt_s);
      if (tk > t_to) return;
      if (tk - t_left <= 16 * eps * std::max(std::abs(t_left), std::abs(tk))) {
        if (tk >= o_.t_max_s) return;
        continue;
      }
      check(CVodeGetDky(cv_.mem, tk, 0, cv_.dky), "CVodeGetDky");
      RigidState s = from_vector(N_VGetArrayPointer(cv_.dky));
      s.orientation.normalize();
      sample(tk, s);
      if (tk >= o_.t_max_s) return;
    }
  };
  while (!done_) {
    if (t_ >= o_.t_max_s) break;
    long nst = 0;
    check(CVodeGetNumSteps(cv_.mem, &nst), "CVodeGetNumSteps");
    const long total = r_.stats.steps + nst;
    const long left = o_.max_steps - total;
    if (left <= 0) {
      std::ostringstream m;
      m << "too many steps: " << o_.max_steps << " (ReferenceOptions::max_steps) used by t = " << t_ << " s";
      fail(m.str());
      break;
    }
    // Step-collapse guard: a full window of max_steps_per_ms steps must span 1 ms or more.
    if (total - window_steps_ >= o_.max_steps_per_ms) {
      if (t_ - window_t_ < 1e-3 && try_sliding()) continue;
      if (t_ - window_t_ < 1e-3) {
        std::ostringstream m;
        m << "the step size collapsed: " << total - window_steps_ << " steps from t = " << window_t_ << " s to " << t_
          << " s, less than 1 ms (ReferenceOptions::max_steps_per_ms): the right-hand side is probably singular "
             "or discontinuous there, where no event is located (a sliding mode, say)";
        if (problem_.record.sliding_count() > 0)
          m << "; it collapsed while sliding along " << problem_.record.sliding_what() << " (since t = "
            << problem_.record.sliding_since() << " s)"
            << (no_slide_.empty() ? "" : "; no second switch to add: " + no_slide_);
        else if (!no_slide_.empty())
          m << "; no sliding mode was found to treat: " << no_slide_;
        fail(m.str());
        break;
      }
      window_steps_ = total;
      window_t_ = t_;
    }
    // Sliding probe: every kSlideProbeSteps steps the state is looked at for a sliding mode, long
    // before the guard above fires (only where one can be treated; CVODE returns every
    // kSlideProbeSteps steps for it, which does not change its steps).
    const bool probe = sliding_.available();
    if (probe && total - probe_steps_ >= kSlideProbeSteps) {
      probe_steps_ = total;
      if (try_sliding()) continue;
    }
    long steps_now = std::min(left, o_.max_steps_per_ms - (total - window_steps_));
    if (probe) steps_now = std::min(steps_now, kSlideProbeSteps - (total - probe_steps_));
    check(CVodeSetMaxNumSteps(cv_.mem, steps_now), "CVodeSetMaxNumSteps");
    double t_ret = t_;
    const int flag = CVode(cv_.mem, o_.t_max_s, cv_.y, &t_ret, sampled ? CV_ONE_STEP : CV_NORMAL);
    if (flag == CV_ILL_INPUT && last_error_.find("cvRcheck2") != std::string::npos && last_good_t_ != rcheck_restart_t_) {
      // Continuing after an event, CVODE refuses a root function that is exactly zero at the event
      // and still zero a round-off step later (cvRcheck2: "Root found at and very near t"). Its
      // step is ∝ |t|, so this happens near t = 0: a release within µs of a crossing, where a
      // vertex's height z_j, the sum of two numbers of ~1 cm, moves by less than their rounding.
      // A restart there judges such a root inactive until it leaves zero (cvRcheck1): go on from
      // the event's state, once per event.
      rcheck_restart_t_ = last_good_t_;
      ++rcheck_restarts_;
      const StateVector y = to_vector(last_good_);
      std::copy(y.begin(), y.end(), N_VGetArrayPointer(cv_.y));
      t_ = t_left = last_good_t_;
      restart(t_);
      continue;
    }
    if (flag == CV_ROOT_RETURN) {
      // The output times before the event, in the mode before it.
      if (sampled) samples_to(std::nextafter(t_ret, -1.0));
      t_ = t_left = t_ret;
      remember_good(t_ret);
      if (!handle_root(t_)) break;
      continue;
    }
    if (flag == CV_SUCCESS || flag == CV_TSTOP_RETURN) {
      if (sampled) samples_to(t_ret);
      t_ = t_left = t_ret;
      remember_good(t_ret);
      if (!sampled) sample(t_, state());  // at t_max: unsampled runs return only there and at events
      if (flag == CV_TSTOP_RETURN || t_ >= o_.t_max_s) break;
      continue;
    }
    if (flag == CV_TOO_MUCH_WORK) {
      // The window or max_steps is used up: the loop's top says which, or goes on from t_ret.
      t_ = t_ret;
      remember_good(t_ret);  // CVODE returns the solution at t_ret here
      long used = 0;
      check(CVodeGetNumSteps(cv_.mem, &used), "CVodeGetNumSteps");
      if (r_.stats.steps + used < o_.max_steps) continue;
    }
    // CVODE gave up.
    std::ostringstream m;
    if (flag == CV_TOO_MUCH_WORK) {
      m << "too many steps: " << o_.max_steps << " (ReferenceOptions::max_steps) used by t = " << t_ret << " s";
    } else {
      char* name = CVodeGetReturnFlagName(flag);
      m << "CVODE failed at t = " << t_ret << " s: " << (name ? name : "?");
      std::free(name);
      if (!problem_.nan_detail.empty()) m << "; " << problem_.nan_detail;
      if (!last_error_.empty()) m << " (" << last_error_ << ")";
    }
    t_ = t_ret;
    // CVODE returns its last accepted step's solution at t_ret: the throw's end, where finite and
    // past the last state remembered. Failing at once after a restart at an event (t_ret is that
    // event's time), CVODE 6.4 leaves the vector zeroed: the event's state, remembered, stands.
    if (t_ret > last_good_t_) {
      const RigidState s = state();
      const StateVector y = to_vector(s);
      if (std::all_of(y.begin(), y.end(), [](double v) { return std::isfinite(v); })) remember_good(t_ret);
    }
    // Repeated error-test or convergence failures are how a sliding mode can also show.
    if ((flag == CV_ERR_FAILURE || flag == CV_CONV_FAILURE) && try_sliding()) continue;
    if (problem_.record.sliding_count() > 0)
      m << "; it failed while sliding along " << problem_.record.sliding_what() << " (since t = "
        << problem_.record.sliding_since() << " s)";
    else if (!no_slide_.empty() && (flag == CV_ERR_FAILURE || flag == CV_CONV_FAILURE))
      m << "; no sliding mode was found to treat: " << no_slide_;
    fail(m.str());
  }
}

// 4. The end of the throw, also after a failure: the statistics, the end state, the open contact
// closed at the end time, and the result built from every contact logged.
void ReferenceSolve::finish(const RigidState& s0) {
  RigidState s_end = s0;
  if (cv_.mem) {
    try {
      count_steps_to_event();
      add_segment_stats();
    } catch (const CvodeFailure& e) {
      if (r_.outcome != Outcome::failed) fail(e.message);
    }
    renormalise();
    s_end = state();
  }
  // A failed solve ends at the last state CVODE returned, whatever its output vector now holds.
  if (r_.outcome == Outcome::failed) {
    s_end = last_good_;
    t_ = last_good_t_;
  }
  r_.stats.rhs_evaluations += problem_.uncounted_loads;  // right-hand sides are load evaluations
  const bool cut = r_.outcome == Outcome::failed && log_.in_contact();
  if (log_.in_contact()) log_.end(t_, s_end, energy(s_end), false);
  if (o_.record_trajectory && (r_.trajectory.empty() || r_.trajectory.back().t_s < t_)) sample(t_, s_end);
  finish_result(r_, log_, s_end, t_);
  std::ostringstream extra;
  if (cut) extra << "; contact " << r_.contacts.size() << " was still open: it ends at the last state CVODE returned (t = " << t_ << " s)";
  if (resynced_ > 0) extra << "; " << resynced_ << " vertex crossings missed by root finding (fixed from the state)";
  if (rcheck_restarts_ > 0)
    extra << "; restarted at " << rcheck_restarts_ << " event(s) where CVODE refused to continue past a root function "
          << "that stayed exactly zero (cvRcheck2)";
  extra << problem_.record.summary(t_, "collapsed");
  if (max_q_drift_ > kReportedQuaternionDrift) extra << "; quaternion norm drifted by up to " << max_q_drift_ << " between restarts";
  r_.outcome_detail += extra.str();
}

}  // namespace

ThrowResult run_reference(const Stone& stone, const Environment& env, const RigidState& initial,
                          const ReferenceOptions& options) {
  const CpuTimer cpu;
  const WallTimer wall;
  ThrowResult r;
  r.solver = describe(options);
  try {
    ReferenceSolve solve(stone, env, options, r);
    solve.run(initial);
  } catch (const CvodeFailure& e) {
    r.outcome = Outcome::failed;
    r.outcome_detail = e.message;
  }
  r.stats.cpu_s = cpu.seconds();
  r.stats.wall_s = wall.seconds();
  return r;
}

}  // namespace stoneskip
