// Tests of the verdict rules added for issue 11 (the laws' validation, ranking and the restart
// strategies): each rule at and beside its edges.
#include <boost/test/unit_test.hpp>

#include <limits>

#include "verification/study/verdict_rules.hpp"

namespace stoneskip {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

BOOST_AUTO_TEST_SUITE(verdict_rules)

Record exponent(double lo, double hi, double points) {
  Record in;
  in.set("valid", 1.0).set("exponent", 0.5 * (lo + hi)).set("exponent_low", lo).set("exponent_high", hi);
  in.set("points", points).set("expected", 1.0).set("tolerance", 0.25);
  return in;
}

BOOST_AUTO_TEST_CASE(a_power_law_exponent_is_judged_by_its_interval) {
  // Oracle: the rule's definition (verdict_rules.hpp): the interval within 1 ± 0.25, entirely
  // outside it, or neither; fewer than 3 points or no fit is too few. Edges are inclusive.
  BOOST_TEST(decide("power_law_exponent", exponent(0.75, 1.25, 3)) == "consistent with the expected exponent");
  BOOST_TEST(decide("power_law_exponent", exponent(0.74, 1.1, 3)) == "exponent not established");
  BOOST_TEST(decide("power_law_exponent", exponent(1.26, 1.5, 5)) == "excludes the expected exponent");
  BOOST_TEST(decide("power_law_exponent", exponent(0.1, 0.74, 5)) == "excludes the expected exponent");
  BOOST_TEST(decide("power_law_exponent", exponent(0.9, 1.1, 2)) == "too few points to fit");
  Record none = exponent(0.9, 1.1, 5);
  none.set("valid", 0.0);
  BOOST_TEST(decide("power_law_exponent", none) == "too few points to fit");
}

BOOST_AUTO_TEST_CASE(a_law_skips_like_a_stone_only_near_the_measurements_and_holding_its_attitude) {
  // Oracle: distance ≤ bound and |attack change| ≤ bound (both inclusive); a NaN attack change (no
  // contact) does not hold, a NaN distance is not near.
  Record in;
  in.set("distance", 0.4).set("distance_bound", 0.4).set("attack_change_deg", -5.0).set("attack_bound_deg", 5.0);
  BOOST_TEST(decide("skips_like_a_stone", in) == "skips like a real stone");
  in.set("attack_change_deg", 5.01);
  BOOST_TEST(decide("skips_like_a_stone", in) == "does not hold its attitude");
  in.set("attack_change_deg", kNaN);
  BOOST_TEST(decide("skips_like_a_stone", in) == "does not hold its attitude");
  in.set("attack_change_deg", 0.0).set("distance", 0.41);
  BOOST_TEST(decide("skips_like_a_stone", in) == "too far from the measurements");
  in.set("distance", kNaN).set("attack_change_deg", -30.0);
  BOOST_TEST(decide("skips_like_a_stone", in) == "too far from the measurements and does not hold its attitude");
}

BOOST_AUTO_TEST_CASE(the_cheapest_passing_law_is_named_and_failing_laws_are_not) {
  // Oracle: by hand — of three laws, the cheapest (nagahiro_hayakawa) fails on attitude, so the next
  // cheapest that passes (planing) is named; when none passes, none is.
  Record in;
  in.set("distance_bound", 0.5).set("attack_bound_deg", 5.0);
  in.set("newtonian.distance", 0.9).set("newtonian.attack_change_deg", 1.0).set("newtonian.cost_s", 2e-3);
  in.set("planing.distance", 0.3).set("planing.attack_change_deg", -2.0).set("planing.cost_s", 3e-3);
  in.set("nagahiro_hayakawa.distance", 0.2).set("nagahiro_hayakawa.attack_change_deg", -20.0).set("nagahiro_hayakawa.cost_s", 1e-3);
  BOOST_TEST(decide("cheapest_skipping_law", in) == "planing is the cheapest law that skips like a real stone");
  in.set("nagahiro_hayakawa.attack_change_deg", 4.0);  // now it passes and is cheaper
  BOOST_TEST(decide("cheapest_skipping_law", in) == "nagahiro_hayakawa is the cheapest law that skips like a real stone");
  in.set("nagahiro_hayakawa.cost_s", 3e-3);  // a tie in cost goes to the smaller distance
  BOOST_TEST(decide("cheapest_skipping_law", in) == "nagahiro_hayakawa is the cheapest law that skips like a real stone");
  in.set("nagahiro_hayakawa.distance", 0.6).set("planing.distance", 0.51);
  BOOST_TEST(decide("cheapest_skipping_law", in) == "no law skips like a real stone");
}

BOOST_AUTO_TEST_CASE(the_cheapest_restart_strategy_that_keeps_the_contact_times_is_named) {
  // Oracle: by hand — never is cheapest but fails a run; at_jumps is next and its error ratio is
  // exactly 1 (kept); when at_jumps misses (ratio > 1, or NaN: no successful run), every_event is.
  Record in;
  in.set("never.failed", 1.0).set("never.error_ratio", 0.5).set("never.rhs_evaluations", 1000.0);
  in.set("at_jumps.failed", 0.0).set("at_jumps.error_ratio", 1.0).set("at_jumps.rhs_evaluations", 2000.0);
  in.set("every_event.failed", 0.0).set("every_event.error_ratio", 0.5).set("every_event.rhs_evaluations", 9000.0);
  BOOST_TEST(decide("restart_strategy", in) == "at_jumps is the cheapest strategy that keeps the contact times");
  in.set("at_jumps.error_ratio", 1.0000001);
  BOOST_TEST(decide("restart_strategy", in) == "every_event is the cheapest strategy that keeps the contact times");
  in.set("at_jumps.error_ratio", kNaN);
  BOOST_TEST(decide("restart_strategy", in) == "every_event is the cheapest strategy that keeps the contact times");
  in.set("every_event.failed", 2.0);
  BOOST_TEST(decide("restart_strategy", in) == "no strategy keeps the contact times");
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
