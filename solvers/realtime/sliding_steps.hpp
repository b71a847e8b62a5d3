#pragma once
// The adaptive real-time stepper's sliding modes (bs32, still water): where its steps stall at a
// loaded-region switch that attracts from both sides (filippov_sliding.hpp), it steps on Filippov's
// sliding field instead of chattering across the switch under its error control, which bounds the
// step by the jump in the loads there (on lens stones at rtol 1e-10 and tighter the step collapsed,
// solvers/README.md). It looks for an attracting switch at zero as the reference does
// (cvode_stone.cpp), but only where kProbeSteps steps advance less than kProbeSpan_s: an explicit
// pair cannot follow a sliding mode without chattering across it, which shrinks its steps (the
// reference's BDF can, so it looks every 20 steps). It slides on one switch or two, and watches
// each rule's root function (a sliding's exit, a hold's end): a step over which one falls through
// zero is cut back to just past it on the step's interpolant and taken again, and the rules
// change at its end.
// A run that never stalls at such a switch is unchanged to the bit.
#include <optional>
#include <string>
#include <vector>

#include "solvers/realtime/adaptive_step.hpp"
#include "solvers/realtime/dense_output.hpp"
#include "solvers/realtime/filippov_sliding.hpp"
#include "solvers/realtime/sliding_record.hpp"

namespace stoneskip {

class SlidingSteps {
 public:
  // Steps that stall: kProbeSteps accepted steps within kProbeSpan_s. bs32 takes steps of 1e-5 to
  // 1e-4 s in a contact at rtol 1e-8 to 1e-11; chattering across an attracting switch at 1e-10 it
  // took 500 steps in 4e-6 s (measured on a lens throw, 5 December).
  static constexpr long kProbeSteps = 500;
  static constexpr double kProbeSpan_s = 1e-4;
  static constexpr std::size_t kMaxSlides = 100;

  // Never active unless enabled: bs32 with RealtimeOptions::slide, in still water (a live surface
  // has no sliding field here).
  SlidingSteps(const Stone& stone, const Environment& env, bool enabled);
  SlidingSteps(const SlidingSteps&) = delete;  // field_ holds this
  SlidingSteps& operator=(const SlidingSteps&) = delete;

  bool active() const { return !record_.rules().empty(); }
  // The right-hand side while active (nullptr when not).
  const FieldFunction* field() const { return active() ? &field_ : nullptr; }
  // The loads' right-hand side at y under the rules (one evaluation's worth of loads counted).
  StateVector rhs(const StateVector& y);

  // After each accepted step (steps so far, time, state): where the steps stall, the switches at
  // zero are tested and a sliding begins if one (or two) attract. True when the rules changed.
  bool probe(long steps, double t, const RigidState& s);
  // A trial's first root of the rules' functions on its interpolant (the fraction of the step), or
  // −1 where none falls through zero over it.
  double first_root(const HermiteStep& step);
  // At an accepted step's end: the rules after any root there (a sliding's exit holds its face; a
  // hold's end releases it, and the state slides at once where a switch attracts). True when the
  // rules changed (the caller's first stage is then stale).
  bool after_step(double t, const StateVector& y);
  // Call where a step begins with the rules in force (the roots' values there).
  void start_step(const StateVector& y);

  // Load evaluations the stepper did not count (a sliding right-hand side evaluates the loads two
  // or four times, a root function as often).
  long extra_loads() const { return extra_loads_; }
  // The rules and the slides (the outcome's account: summary, sliding_what).
  const SlidingRecord& record() const { return record_; }

 private:
  // The rules' root values at y, into g (resized to the rules).
  void roots_at(const StateVector& y, std::vector<double>& g);

  std::optional<FilippovSliding> sliding_;
  bool enabled_;
  const Stone& stone_;
  const Environment& env_;
  SlidingRecord record_;
  FieldFunction field_;
  std::vector<double> roots0_;  // the rules' root values where the step began
  // Scratch for the roots at a step's end and inside it, and the roots found: kept so that a step
  // allocates nothing once they have grown.
  std::vector<double> roots1_, roots_inside_;
  std::vector<int> found_;
  long probe_steps_ = 0;
  double probe_t_ = 0;
  long extra_loads_ = 0;
};

}  // namespace stoneskip
