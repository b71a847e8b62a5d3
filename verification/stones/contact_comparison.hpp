#pragma once
// Compares the contact list of a solver with that of the reference (model/README.md §1.8): which reference
// contacts the solver found, missed (it stepped over them: tunnelling) or added (spurious), and
// how far apart the matched contacts are in time and in position. A contact of the solver is
// matched to the reference contact it overlaps most in time. How a contact ends is part of it:
// with a bounce (the stone leaves the water), with the stone sinking (the last contact of a throw
// whose outcome is `sank`), or still open when the run stopped; a matched pair that ends in two
// different ways is an ending mismatch, and the lists are then not the same.
#include <string>
#include <vector>

#include "solvers/realtime/throw_result.hpp"

namespace stoneskip {

struct ContactComparison {
  int reference_contacts = 0;
  int solver_contacts = 0;
  int reference_bounces = 0;
  int solver_bounces = 0;
  int matched = 0;
  int missed = 0;      // reference contacts that no solver contact overlaps
  int spurious = 0;    // solver contacts that overlap no reference contact
  int ending_mismatches = 0;  // matched contacts that end differently (bounce / sink / still open)
  std::vector<int> match;  // per reference contact: index of the solver contact, or −1
  // Largest errors over the matched contacts (NaN when nothing matched).
  double max_start_error_s = 0;
  double max_end_error_s = 0;
  double max_touch_error_m = 0;          // first-touch point (ill-defined when an edge lands flat)
  double max_exit_speed_error_m_s = 0;
  // The bounce positions: centre of mass where a contact ends with the stone leaving the water,
  // over the matched contacts that both end in a bounce (NaN when there is none).
  double max_exit_position_error_m = 0;
  // Where the stone sank: centre of mass and time, when both runs end by sinking in matched
  // contacts (NaN otherwise). Kept apart from the bounce positions: a sinking point is located
  // differently and its error is often far larger.
  double max_sink_position_error_m = 0;
  double sink_time_error_s = 0;
  bool same_contacts() const {
    return missed == 0 && spurious == 0 && ending_mismatches == 0 && reference_contacts == solver_contacts;
  }
  bool same_bounces() const { return reference_bounces == solver_bounces; }
  std::string brief() const;
};

// slack_s widens each interval when testing for overlap, so that a short contact shifted a little
// in time still matches its counterpart (5 ms: shorter than any flight between real bounces here,
// longer than the shift of a sensitive late contact between two tight references).
constexpr double kContactMatchSlack_s = 5e-3;
ContactComparison compare_contacts(const ThrowResult& solver, const ThrowResult& reference,
                                   double slack_s = kContactMatchSlack_s);

}  // namespace stoneskip
