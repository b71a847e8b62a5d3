// Oracle: the rule itself, on records made by hand. The attack angle of the lowest minimum speed is
// a result only where the grid holds two angles or more: with one (the quick preset's [20]) the
// argmin is the input, and it was scored as a match at distance 0 ("5 of 9 rows").
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "verification/stones/validation_scored_value.hpp"

namespace stoneskip {
namespace {

Record variant_with_angles(const std::vector<double>& angles, const std::vector<double>& speeds, double best) {
  Record g;
  Table t{{"attack_deg", "min_speed_m_s", "half_width_m_s"}, {}};
  for (std::size_t i = 0; i < angles.size(); ++i) t.add_row({angles[i], speeds[i], 0.01});
  g.set_table("min_speed", t);
  g.set("best_attack_deg", best);
  g.set("best_attack_tied_low_deg", best);
  g.set("best_attack_tied_high_deg", best);
  return g;
}

BOOST_AUTO_TEST_SUITE(validation_scored_value)

BOOST_AUTO_TEST_CASE(the_best_attack_angle_of_a_one_angle_grid_is_not_measured) {
  const ValidationOptions o;
  const ScoredValue one = scored_value(variant_with_angles({20}, {2.6}, 20), "clanet_best_attack", o);
  BOOST_TEST(!one.has_value);
  BOOST_TEST(one.note.find("not measured: the grid holds one attack angle (20°)") == 0u, one.note);
  const ScoredValue two = scored_value(variant_with_angles({15, 20}, {2.9, 2.6}, 20), "clanet_best_attack", o);
  BOOST_TEST(two.has_value);
  BOOST_TEST(two.model == 20.0);
}

BOOST_AUTO_TEST_CASE(a_bent_contact_time_series_has_no_exponent_to_score) {
  // Oracle: the rule itself. A fit whose points bend (the shape test's "curved") is no power law:
  // the row counts none (skip_inputs), and the distance must not score its slope (a bent series'
  // −1.04 had been scored as a near hit beside a verdict "misses contact exponent").
  const ValidationOptions o;
  Record g;
  Record& e = g.child("contact_exponent");
  e.set("valid", 1.0).set("points", 6.0).set("exponent", -1.04).set("curved", 0.0);
  BOOST_TEST(scored_value(g, "clanet_contact_exponent", o).has_value);
  BOOST_TEST(scored_value(g, "clanet_contact_exponent", o).model == -1.04);
  e.set("curved", 1.0);
  const ScoredValue bent = scored_value(g, "clanet_contact_exponent", o);
  BOOST_TEST(!bent.has_value);
  BOOST_TEST(bent.note == "the points bend: no single power law");
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
