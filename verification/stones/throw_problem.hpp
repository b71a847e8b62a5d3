#pragma once
// One throw to be solved (stone, environment, initial state, the case's solver settings) and the
// choice of solver, so that every stone study runs the real-time stepper and the CVODE reference
// through one function and compares like with like.
#include <string>

#include "model/stone/throw.hpp"
#include "solvers/realtime/stone_stepper.hpp"
#include "solvers/reference/reference_options.hpp"

namespace stoneskip {

struct ThrowProblem {
  std::string label;               // the case title, plus what a study changed
  Stone stone;
  Environment environment;
  bool from_parameters = true;     // false: the case gave a full initial state
  ThrowParameters parameters;
  RigidState initial;
  RealtimeOptions realtime;        // the case's [solver] settings
  ReferenceOptions reference;      // the case's [reference] settings
};

// The same problem thrown with other parameters (the initial state is rebuilt, model/README.md §1.7).
ThrowProblem with_parameters(const ThrowProblem& p, const ThrowParameters& tp);
ThrowProblem with_convention(const ThrowProblem& p, Convention c);

enum class SolverKind { realtime, reference };

struct SolverChoice {
  SolverKind kind = SolverKind::realtime;
  RealtimeOptions realtime;
  ReferenceOptions reference;
  std::string label() const;  // "realtime semi_implicit_euler dt=0.001/0.0001 s", "CVODE bdf rtol=1e-10"
};

SolverChoice realtime_choice(const RealtimeOptions& o);
SolverChoice reference_choice(const ReferenceOptions& o);

// Solves the throw; t_max_s and record_trajectory of the choice are used as given.
ThrowResult solve(const ThrowProblem& p, const SolverChoice& s);
// The bounce count of a solve as the sweeps take it, −1 where the solve failed. No trajectory is
// recorded (a count needs none; either solver takes the same steps with samples as without,
// solvers/README.md).
int sweep_bounce_count(const ThrowProblem& p, SolverChoice s);

// Whether a failed solve ran away: its last state holds more than a thousand times the release
// energy, the release energy floored at 1 mJ (so over 1 J at least) — the rule the real-time stepper names a paper-convention runaway by
// (solvers/realtime/stone_stepper.cpp): the printed forces create energy (spec §1.6), so such a
// stone skips on, gaining speed, until a solver gives up; its count is not a finished throw's.
// False for a solve that did not fail, or failed with its energy in bounds.
bool ran_away(const ThrowProblem& p, const ThrowResult& r);

// A sweep's count and, where the solve failed (bounces −1), whether it ran away.
struct SweepCount {
  int bounces = -1;
  bool ran_away = false;
};
SweepCount sweep_count(const ThrowProblem& p, SolverChoice s);

// Solves `repeats` times and returns the last result with stats.cpu_s the minimum over the runs
// (the least disturbed measurement of the cost on a shared machine).
ThrowResult solve_min_cpu(const ThrowProblem& p, const SolverChoice& s, int repeats);

// Solves from the problem's initial state up to t_s and returns the state there (free flight,
// contacts, whatever happens: the solver's own t_max handling lands exactly on t_s).
struct StateAt {
  bool ok = false;
  std::string problem;
  RigidState state;
};
StateAt state_at(const ThrowProblem& p, const SolverChoice& s, double t_s);

}  // namespace stoneskip
