#pragma once
// The real-time stepper against CVODE on a chaotic bounce count, decided on ensembles (model/
// README.md §2.4, "Both"; the rule ensemble_bounce_agreement, verification/study/verdict_rules.hpp):
// the throw is run by both with its speed × 1 ± ε (ε log-spaced over [smallest, largest], both signs:
// verification/study/ensemble_difference.hpp), direction, attitude and spin kept, and the two
// ensembles' mean counts are compared. One run of each decides nothing where a 1e-9 change of the
// speed changes the count (the paper convention). Used by the captures report for the capture's
// nominal throw and by the capture scene on still water.
#include <string>
#include <vector>

#include "solvers/realtime/stone_stepper.hpp"
#include "solvers/reference/reference_options.hpp"
#include "verification/study/ensemble_difference.hpp"
#include "verification/study/record.hpp"

namespace stoneskip {

struct NudgedAgreementOptions {
  int members = 16;  // per solver (even; 0: none run)
  double perturbation_smallest = 1e-9, perturbation_largest = 1e-4;
  bool valid(std::string* why = nullptr) const;
};

struct NudgedAgreement {
  std::vector<double> factors;             // the speed factors
  std::vector<double> realtime, reference;  // counts per member (−1: the solve failed)
  int realtime_failed = 0, reference_failed = 0;
  MeanDifference difference;               // real-time − reference, over the members that ran
  double cpu_s = 0, wall_s = 0;            // both ensembles (solvers/realtime/clocks.hpp)
};

NudgedAgreement nudged_agreement(const Stone& stone, const Environment& env, const RigidState& initial,
                                 const RealtimeOptions& realtime, const ReferenceOptions& reference,
                                 const NudgedAgreementOptions& options);

// Writes the ensembles (table `count_ensemble`: factor, realtime_bounces, reference_bounces; numbers
// `count_ensemble_members`, `count_ensemble_cpu_s`, `count_ensemble_wall_s`) into r and decides r's child `key` by
// ensemble_bounce_agreement, its reason the single runs' words (`single`) and the ensembles' numbers.
void decide_nudged_agreement(Record& r, const std::string& key, const NudgedAgreement& a, const std::string& single,
                             const std::string& realtime_name, const std::string& reference_name);

}  // namespace stoneskip
