// Tests of the verdict rules of the scene report (phrases in verdict_rules.hpp): each rule
// at and beside its edges. Oracle: the rules' definitions as the header states them.
#include <boost/test/unit_test.hpp>

#include <limits>

#include "verification/study/verdict_rules.hpp"

namespace stoneskip {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

BOOST_AUTO_TEST_SUITE(scene_verdict_rules)

BOOST_AUTO_TEST_CASE(a_coupling_change_is_an_ensemble_count_change_before_a_time_change) {
  Record in;
  in.set("difference_low", 0.0).set("difference_high", 0.0).set("count_spread", 0.0);
  in.set("max_time_change_s", 1e-4).set("time_tolerance_s", 1e-4);
  BOOST_TEST(decide("coupling_change", in) == "no visible change");  // the tolerance is inclusive
  in.set("max_time_change_s", 1.01e-4);
  BOOST_TEST(decide("coupling_change", in) == "moves the contacts");
  in.set("difference_low", -0.5).set("difference_high", 2.5).set("count_spread", 3.0);
  BOOST_TEST(decide("coupling_change", in) == "no difference established");  // the interval holds 0
  in.set("difference_low", 0.1);
  BOOST_TEST(decide("coupling_change", in) == "changes the bounce count");
  in.set("difference_low", -3.0).set("difference_high", -0.01);
  BOOST_TEST(decide("coupling_change", in) == "changes the bounce count");
  // A failed run has no count and the failures are not a random sample: nothing is decided.
  in.set("failed_runs", 1.0);
  BOOST_TEST(decide("coupling_change", in) == "not decided: runs failed");
  in.set("failed_runs", 0.0);
  BOOST_TEST(decide("coupling_change", in) == "changes the bounce count");
}

BOOST_AUTO_TEST_CASE(the_coupled_limit_needs_all_three_runs_to_agree) {
  Record in;
  in.set("growth_below", 1.001).set("growth_above", 1.5).set("growth_free_above", 0.999).set("growth_tolerance", 1e-3);
  BOOST_TEST(decide("coupled_limit", in) == "stable below the limit, unstable above it");
  in.set("growth_below", 1.0011);
  BOOST_TEST(decide("coupled_limit", in) == "the limit is not confirmed");  // grows below the limit
  in.set("growth_below", 1.0).set("growth_above", 1.0005);
  BOOST_TEST(decide("coupled_limit", in) == "the limit is not confirmed");  // does not grow above it
  in.set("growth_above", 1.5).set("growth_free_above", 1.2);
  BOOST_TEST(decide("coupled_limit", in) == "the limit is not confirmed");  // the free field grows: not the stone's doing
}

BOOST_AUTO_TEST_CASE(a_ring_speed_is_judged_by_its_interval_against_group_speed_and_c) {
  Record in;
  in.set("valid", 1.0).set("speed_low", 0.46).set("speed_high", 0.48).set("predicted_low", 0.465).set("predicted_high", 0.5);
  BOOST_TEST(decide("ring_speed", in) == "within c less the scheme's dispersion");  // overlaps [group, c]
  in.set("speed_low", 0.501).set("speed_high", 0.52);
  BOOST_TEST(decide("ring_speed", in) == "faster than c");
  in.set("speed_low", 0.40).set("speed_high", 0.464);
  BOOST_TEST(decide("ring_speed", in) == "slower than the scheme's dispersion explains");
  in.set("valid", 0.0).set("speed_low", kNaN).set("speed_high", kNaN);
  BOOST_TEST(decide("ring_speed", in) == "not measured");
}

BOOST_AUTO_TEST_CASE(a_shortcut_is_exact_only_with_no_difference_at_all) {
  Record in;
  in.set("field_relative", 0.0).set("start_change_s", 0.0).set("count_change", 0.0);
  in.set("field_tolerance", 1e-3).set("time_tolerance_s", 1e-4);
  BOOST_TEST(decide("shortcut", in) == "exact");
  in.set("field_relative", 1e-3);
  BOOST_TEST(decide("shortcut", in) == "within tolerance");  // inclusive
  in.set("start_change_s", 2e-4);
  BOOST_TEST(decide("shortcut", in) == "beyond tolerance");
  in.set("start_change_s", 0.0).set("count_change", 1.0);
  BOOST_TEST(decide("shortcut", in) == "beyond tolerance");
}

BOOST_AUTO_TEST_CASE(a_speed_target_is_met_at_or_above_it) {
  Record in;
  in.set("value", 3000.0).set("target", 3000.0);
  BOOST_TEST(decide("speed_target", in) == "meets the target");
  in.set("value", 2999.0);
  BOOST_TEST(decide("speed_target", in) == "misses the target");
  in.set("value", kNaN);
  BOOST_TEST(decide("speed_target", in) == "misses the target");  // not measured is not met
}

BOOST_AUTO_TEST_CASE(the_scene_converges_under_refinement_only_where_every_change_shrinks) {
  // Oracle: the rule's definition (verification/scene/scene_grid_findings.cpp): the largest change
  // of each quantity over the one before must be below 1; a NaN ratio (a change after none) is not;
  // fewer than three grids decide nothing.
  Record in;
  in.set("grids", 4.0).set("ratio_pressure_work_J", 0.5).set("ratio_first_duration_s", 0.99).set("ratio_first_exit_m_s", 0.0);
  BOOST_TEST(decide("grid_differences", in) == "the changes shrink as the cells halve");
  in.set("ratio_first_duration_s", 1.0);
  BOOST_TEST(decide("grid_differences", in) ==
             "does not converge: first_duration_s change no less as the cells get finer");
  in.set("ratio_first_duration_s", 0.5).set("ratio_pressure_work_J", kNaN);
  BOOST_TEST(decide("grid_differences", in).find("does not converge: pressure_work_J") == 0u);
  // A change that does not shrink but is no larger than halving the water step moves the quantity
  // is the step's: not decided; one larger than that does not converge.
  in.set("ratio_pressure_work_J", 0.5).set("ratio_first_duration_s", 1.5);
  in.set("last_change_first_duration_s", 6e-5).set("time_change_first_duration_s", 1.2e-4);
  BOOST_TEST(decide("grid_differences", in) ==
             "not decided: first_duration_s change no more than halving the water step moves them");
  in.set("time_change_first_duration_s", 3e-5);
  BOOST_TEST(decide("grid_differences", in) ==
             "does not converge: first_duration_s change no less as the cells get finer");
  // A first contact that bounces on one grid and not on another is not one contact refined,
  // whatever its changes do (found on the swell: 30 ms and a bounce at 2 cm, 158 and 140 ms and no
  // bounce at 1 and 0.5 cm, "shrinking" by the ratios).
  in.set("ratio_first_duration_s", 0.138).set("outcome_changes", 0.0);
  BOOST_TEST(decide("grid_differences", in) == "the changes shrink as the cells halve");
  in.set("outcome_changes", 1.0);
  BOOST_TEST(decide("grid_differences", in) == "does not converge: the first contact bounces on some grids and not on others");
  // A grid whose own first contact the pond's walls reach (or which leaves the pond) is partly the
  // pond's: nothing is decided, whatever the changes or the endings do.
  in.set("walls_reach_track", 0.0);
  BOOST_TEST(decide("grid_differences", in) == "does not converge: the first contact bounces on some grids and not on others");
  in.set("walls_reach_track", 1.0);
  BOOST_TEST(decide("grid_differences", in) == "not decided: on some grid the pond's walls are not clear of the first contact");
  in.set("grids", 2.0);
  BOOST_TEST(decide("grid_differences", in) == "not decided: fewer than three grids");
}

BOOST_AUTO_TEST_CASE(a_level_reading_is_closer_only_where_every_resolved_comparison_says_so) {
  // Oracle: the rule's definition (verification/scene/scene_step_findings.cpp): the counts of
  // resolved comparisons each reading wins; none resolved, or a run without contact, decides nothing.
  Record in;
  in.set("closer", 9.0).set("farther", 0.0).set("unresolved", 3.0).set("missing", 0.0);
  BOOST_TEST(decide("level_in_time", in) == "the extrapolated level is closer to the reference wherever the difference is resolved");
  in.set("farther", 1.0);
  BOOST_TEST(decide("level_in_time", in) == "neither level is closer at every step");
  in.set("finest_closer", 3.0).set("finest_farther", 0.0);  // the held level won only on coarser steps
  BOOST_TEST(decide("level_in_time", in) == "the extrapolated level is closer at the finest step, not at every step");
  in.set("finest_closer", 0.0).set("finest_farther", 1.0);
  BOOST_TEST(decide("level_in_time", in) == "the held level is closer at the finest step, not at every step");
  in.set("finest_closer", 2.0);
  BOOST_TEST(decide("level_in_time", in) == "neither level is closer at every step");
  in.set("closer", 0.0);
  BOOST_TEST(decide("level_in_time", in) == "the held level is closer to the reference wherever the difference is resolved");
  in.set("farther", 0.0);
  BOOST_TEST(decide("level_in_time", in) == "not decided: the reference does not resolve the difference");
  in.set("closer", 5.0).set("missing", 1.0);
  BOOST_TEST(decide("level_in_time", in) == "not decided: a run made no contact");
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
