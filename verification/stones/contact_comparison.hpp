#pragma once
// Compares the contact list of a solver with that of the reference (spec §1.8): which reference
// contacts the solver found, missed (it stepped over them: tunnelling) or added (spurious), and
// how far apart the matched contacts are in time and in position. A contact of the solver is
// matched to the reference contact it overlaps most in time.
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
  std::vector<int> match;  // per reference contact: index of the solver contact, or −1
  // Largest errors over the matched contacts (NaN when nothing matched).
  double max_start_error_s = 0;
  double max_end_error_s = 0;
  double max_touch_error_m = 0;          // first-touch point (ill-defined when an edge lands flat)
  double max_exit_position_error_m = 0;  // centre of mass when the contact ended (the bounce position)
  double max_exit_speed_error_m_s = 0;
  bool same_contacts() const { return missed == 0 && spurious == 0 && reference_contacts == solver_contacts; }
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
