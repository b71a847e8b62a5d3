#include "verification/stones/contact_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace stoneskip {

namespace {
double overlap(const ContactRecord& a, const ContactRecord& b, double slack) {
  return std::min(a.end_s, b.end_s) + slack - std::max(a.start_s, b.start_s);
}

enum class Ending { bounce, sink, open };
Ending ending(const ThrowResult& r, std::size_t i) {
  if (r.contacts[i].bounced) return Ending::bounce;
  return i + 1 == r.contacts.size() && r.outcome == Outcome::sank ? Ending::sink : Ending::open;
}
}  // namespace

ContactComparison compare_contacts(const ThrowResult& solver, const ThrowResult& reference, double slack_s) {
  ContactComparison c;
  c.reference_contacts = static_cast<int>(reference.contacts.size());
  c.solver_contacts = static_cast<int>(solver.contacts.size());
  c.reference_bounces = reference.bounces;
  c.solver_bounces = solver.bounces;
  c.match.assign(reference.contacts.size(), -1);
  std::vector<bool> used(solver.contacts.size(), false);
  for (std::size_t i = 0; i < reference.contacts.size(); ++i) {
    double best = 0;
    int best_j = -1;
    for (std::size_t j = 0; j < solver.contacts.size(); ++j) {
      if (used[j]) continue;
      const double o = overlap(reference.contacts[i], solver.contacts[j], slack_s);
      if (o >= 0 && (best_j < 0 || o > best)) {
        best = o;
        best_j = static_cast<int>(j);
      }
    }
    if (best_j >= 0) {
      used[best_j] = true;
      c.match[i] = best_j;
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  int bounces = 0, sinks = 0;
  for (std::size_t i = 0; i < c.match.size(); ++i) {
    if (c.match[i] < 0) {
      ++c.missed;
      continue;
    }
    ++c.matched;
    const ContactRecord& r = reference.contacts[i];
    const ContactRecord& s = solver.contacts[c.match[i]];
    c.max_start_error_s = std::max(c.max_start_error_s, std::abs(s.start_s - r.start_s));
    c.max_end_error_s = std::max(c.max_end_error_s, std::abs(s.end_s - r.end_s));
    c.max_touch_error_m = std::max(c.max_touch_error_m, (s.first_touch_m - r.first_touch_m).norm());
    c.max_exit_speed_error_m_s = std::max(c.max_exit_speed_error_m_s, std::abs(s.exit_speed_m_s - r.exit_speed_m_s));
    const Ending er = ending(reference, i), es = ending(solver, static_cast<std::size_t>(c.match[i]));
    if (er != es) {
      ++c.ending_mismatches;
    } else if (er == Ending::bounce) {
      ++bounces;
      c.max_exit_position_error_m = std::max(c.max_exit_position_error_m, (s.exit_position_m - r.exit_position_m).norm());
    } else if (er == Ending::sink) {
      ++sinks;
      c.max_sink_position_error_m = (s.exit_position_m - r.exit_position_m).norm();
      c.sink_time_error_s = std::abs(s.end_s - r.end_s);
    }
  }
  for (bool u : used) c.spurious += u ? 0 : 1;
  if (c.matched == 0) c.max_start_error_s = c.max_end_error_s = c.max_touch_error_m = c.max_exit_speed_error_m_s = nan;
  if (bounces == 0) c.max_exit_position_error_m = nan;
  if (sinks == 0) c.max_sink_position_error_m = c.sink_time_error_s = nan;
  return c;
}

std::string ContactComparison::brief() const {
  std::ostringstream s;
  s << solver_contacts << " contacts / " << solver_bounces << " bounces vs reference " << reference_contacts << " / "
    << reference_bounces;
  if (missed) s << ", " << missed << " missed";
  if (spurious) s << ", " << spurious << " spurious";
  if (ending_mismatches) s << ", " << ending_mismatches << " ending differently";
  return s.str();
}

}  // namespace stoneskip
