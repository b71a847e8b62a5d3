// Contact comparison against hand-built contact lists whose errors are known exactly: a bounce
// position error covers only contacts that end in a bounce, the sinking position is its own
// quantity, and a contact that ends differently in the two runs is a different contact list.
#include "verification/stones/contact_comparison.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>

namespace stoneskip {
namespace {

ContactRecord contact(double start_s, double end_s, const Vec3& exit_m, bool bounced) {
  ContactRecord c;
  c.start_s = start_s;
  c.end_s = end_s;
  c.exit_position_m = exit_m;
  c.bounced = bounced;
  return c;
}

// One bounce (contact 1) and a contact that ends when the stone sinks (contact 2).
ThrowResult bounce_then_sink(const Vec3& bounce_m, const Vec3& sink_m, double sink_s) {
  ThrowResult r;
  r.contacts = {contact(0.05, 0.09, bounce_m, true), contact(0.18, sink_s, sink_m, false)};
  r.bounces = 1;
  r.outcome = Outcome::sank;
  r.end_time_s = sink_s;
  return r;
}

BOOST_AUTO_TEST_SUITE(contact_comparison)

BOOST_AUTO_TEST_CASE(bounce_and_sink_positions_are_separate_errors) {
  // Oracle: the lists differ by 1e-6 m at the bounce and 2e-3 m where the stone sank (the exact
  // differences built in); each error reports its own, not the larger of the two.
  constexpr double kRoundoff_m = 1e-15;  // a few ulps of a 1 m coordinate
  const ThrowResult ref = bounce_then_sink(Vec3(0.7, 0, 0.01), Vec3(3.0, -0.5, -0.01), 0.61);
  const ThrowResult run = bounce_then_sink(Vec3(0.7 + 1e-6, 0, 0.01), Vec3(3.0, -0.5 + 2e-3, -0.01), 0.612);
  const ContactComparison c = compare_contacts(run, ref);
  BOOST_TEST(c.same_contacts());
  BOOST_TEST(std::abs(c.max_exit_position_error_m - 1e-6) <= kRoundoff_m);
  BOOST_TEST(std::abs(c.max_sink_position_error_m - 2e-3) <= kRoundoff_m);
  BOOST_TEST(std::abs(c.sink_time_error_s - 2e-3) <= 1e-15);
}

BOOST_AUTO_TEST_CASE(a_throw_without_a_bounce_has_no_bounce_position_error) {
  // Oracle: nothing to compare — a single contact that ends in sinking has a sinking position
  // error and no bounce position error (NaN, not 0: zero would claim a perfect bounce).
  ThrowResult ref, run;
  ref.contacts = {contact(0.05, 0.065, Vec3(0.5, 0, -0.01), false)};
  run.contacts = {contact(0.05, 0.066, Vec3(0.5, 3e-4, -0.01), false)};
  ref.outcome = run.outcome = Outcome::sank;
  const ContactComparison c = compare_contacts(run, ref);
  BOOST_TEST(std::isnan(c.max_exit_position_error_m));
  BOOST_TEST(std::abs(c.max_sink_position_error_m - 3e-4) <= 1e-15);
}

BOOST_AUTO_TEST_CASE(a_contact_that_ends_differently_is_a_different_contact_list) {
  // Oracle: model/README.md §1.8 — in the reference the only contact ends in a bounce and the stone flies on
  // to t_max; in the run the same contact ends with the stone sinking. The intervals match, the
  // bounce counts do not: the lists are not the same, and neither position error is defined.
  ThrowResult ref, run;
  ref.contacts = {contact(0.05, 0.09, Vec3(0.7, 0, 0.01), true)};
  ref.bounces = 1;
  ref.outcome = Outcome::time_limit;
  run.contacts = {contact(0.05, 0.09, Vec3(0.7, 0, 0.01), false)};
  run.outcome = Outcome::sank;
  const ContactComparison c = compare_contacts(run, ref);
  BOOST_TEST(c.matched == 1);
  BOOST_TEST(c.ending_mismatches == 1);
  BOOST_TEST(std::isnan(c.max_sink_position_error_m));
  BOOST_TEST(!c.same_contacts());
  BOOST_TEST(std::isnan(c.max_exit_position_error_m));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
