#include "verification/stones/throw_problem.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "model/stone/rigid_body.hpp"
#include "solvers/reference/cvode_stone.hpp"

namespace stoneskip {

ThrowProblem with_parameters(const ThrowProblem& p, const ThrowParameters& tp) {
  ThrowProblem q = p;
  q.parameters = tp;
  q.from_parameters = true;
  q.initial = initial_state(q.stone, tp);
  return q;
}

ThrowProblem with_convention(const ThrowProblem& p, Convention c) {
  ThrowProblem q = p;
  set_convention(q.environment, c);  // the paper convention takes its printed law and C_w
  return q;
}

std::string SolverChoice::label() const {
  std::ostringstream s;
  if (kind == SolverKind::realtime && is_adaptive(realtime.scheme))
    s << "realtime " << to_string(realtime.scheme) << " rtol=" << realtime.rtol << " atol=" << realtime.atol_m << " m";
  else if (kind == SolverKind::realtime)
    s << "realtime " << to_string(realtime.scheme) << " dt=" << realtime.dt_s << "/" << realtime.contact_dt_s << " s";
  else
    s << "CVODE " << to_string(reference.method) << " rtol=" << reference.rtol;
  return s.str();
}

SolverChoice realtime_choice(const RealtimeOptions& o) {
  SolverChoice s;
  s.kind = SolverKind::realtime;
  s.realtime = o;
  return s;
}

SolverChoice reference_choice(const ReferenceOptions& o) {
  SolverChoice s;
  s.kind = SolverKind::reference;
  s.reference = o;
  return s;
}

ThrowResult solve(const ThrowProblem& p, const SolverChoice& s) {
  if (s.kind == SolverKind::realtime) return run_realtime(p.stone, p.environment, p.initial, s.realtime);
  return run_reference(p.stone, p.environment, p.initial, s.reference);
}

ThrowResult solve_min_cpu(const ThrowProblem& p, const SolverChoice& s, int repeats) {
  ThrowResult r = solve(p, s);
  double best = r.stats.cpu_s;
  for (int k = 1; k < repeats; ++k) {
    r = solve(p, s);
    best = std::min(best, r.stats.cpu_s);
  }
  r.stats.cpu_s = best;
  return r;
}

StateAt state_at(const ThrowProblem& p, const SolverChoice& s, double t_s) {
  SolverChoice c = s;
  c.realtime.t_max_s = t_s;
  c.reference.t_max_s = t_s;
  c.realtime.record_trajectory = false;
  c.reference.record_trajectory = false;
  const ThrowResult r = solve(p, c);
  StateAt out;
  if (r.outcome == Outcome::failed) {
    out.problem = r.outcome_detail;
    return out;
  }
  if (std::abs(r.end_time_s - t_s) > 1e-12 * std::max(1.0, t_s)) {
    std::ostringstream m;
    m << "the throw ended (" << to_string(r.outcome) << ") at t = " << r.end_time_s << " s, before " << t_s << " s";
    out.problem = m.str();
    return out;
  }
  out.ok = true;
  out.state = r.final_state;
  return out;
}

int sweep_bounce_count(const ThrowProblem& p, SolverChoice s) { return sweep_count(p, s).bounces; }

bool ran_away(const ThrowProblem& p, const ThrowResult& r) {
  if (r.outcome != Outcome::failed) return false;
  const double released_J = mechanical_energy(p.stone, p.environment, p.initial).total_J();
  const double last_J = mechanical_energy(p.stone, p.environment, r.final_state).total_J();
  return last_J > 1e3 * std::max(std::abs(released_J), 1e-3);  // a NaN state is a failure, not a runaway
}

SweepCount sweep_count(const ThrowProblem& p, SolverChoice s) {
  s.realtime.record_trajectory = false;
  s.reference.record_trajectory = false;
  const ThrowResult r = solve(p, s);
  SweepCount c;
  if (r.outcome == Outcome::failed) c.ran_away = ran_away(p, r);
  else c.bounces = r.bounces;
  return c;
}

}  // namespace stoneskip
