#pragma once
// Hard cases: throws chosen to break a solver — grazing and steep entry, very
// fast, very high spin, heavy and very light stones, a tumbling asymmetric stone, the paper
// convention at high spin — each solved by the reference and by the real-time stepper with its
// case settings and with one fixed step h for flight and contact alike, growing from tiny to a
// game frame. For every run: does it stay finite, does it miss (tunnel through) or invent contacts
// compared with the reference, does energy grow over a contact where it must not (physical
// convention: the fluids can only take energy out, model/README.md §1.6). And, over throw speed, the largest
// step that stays stable.
#include <string>

#include "verification/study/progress.hpp"
#include <vector>

#include "verification/stones/contact_comparison.hpp"
#include "verification/stones/throw_problem.hpp"

namespace stoneskip {

struct HardCaseOptions {
  std::vector<double> single_steps_s{1e-5, 4e-5, 1.6e-4, 6.4e-4, 2.56e-3, 1.024e-2};
  // The fixed scheme of the single-step runs (the case's own run keeps the case's scheme, by
  // default the adaptive bs32, whose steps no single h describes).
  Scheme single_step_scheme = Scheme::semi_implicit_euler;
  double reference_rtol = 1e-9;
  double reference_atol = 1e-11;
  // Energy created over one contact counts when it exceeds this fraction of the release kinetic
  // energy (the reference's own drift is ~rtol of it; a real-time scheme's is far larger).
  double energy_tolerance_fraction = 1e-4;
  int workers = 2;
  ProgressFactory progress;  // how long runs are shown; empty: silently
};

struct HardRun {
  std::string setting;          // "case settings (bs32, rtol 1e-08)", "single step 0.00064 s (semi_implicit_euler)"
  double dt_s = 0, contact_dt_s = 0;
  ThrowResult result;           // no trajectory
  ContactComparison contacts;   // against the reference
  bool finite = true;           // no NaN/inf (outcome != failed)
  bool energy_created = false;  // max_energy_gain_J above tolerance
  std::string verdict;          // words: "ok", "tunnels through 2 contacts", "NaN at t = ...", ...
};

struct HardCaseResult {
  std::string file;
  std::string title;
  Convention convention = Convention::physical;
  double release_kinetic_J = 0;
  double energy_tolerance_J = 0;
  ThrowResult reference;
  std::string reference_verdict;
  std::vector<HardRun> runs;    // [0]: the case's own settings
};

std::vector<HardCaseResult> run_hard_cases(const std::vector<std::pair<std::string, ThrowProblem>>& cases,
                                           const HardCaseOptions& o);

// Largest stable single step against throw speed.
struct StableStepOptions {
  std::vector<double> speeds_m_s{2, 4, 8, 16, 30};
  std::vector<double> steps_s;  // ascending; default 1e-5 · 2^k, k = 0..11
  double reference_rtol = 1e-9;
  double energy_tolerance_fraction = 1e-4;
  Scheme scheme = Scheme::semi_implicit_euler;
  int workers = 2;
  ProgressFactory progress;  // how long runs are shown; empty: silently
};

struct StableStepRow {
  double speed_m_s = 0;
  int reference_bounces = 0;
  int reference_contacts = 0;
  // Largest h such that every step up to it (in the list) is: finite (the run did not fail: no NaN,
  // and in the physical convention no run-away, stone_stepper.hpp); finite and creates no
  // energy; finite, no energy and the same contact count as the reference. 0: not even the smallest.
  double largest_finite_s = 0;
  double largest_no_energy_gain_s = 0;
  double largest_same_contacts_s = 0;
  std::vector<double> steps_s;
  std::vector<int> bounces;            // per step (−1: failed)
  std::vector<double> energy_gain_J;   // per step
};

std::vector<StableStepRow> run_stable_step(const ThrowProblem& base, const StableStepOptions& o);

}  // namespace stoneskip
