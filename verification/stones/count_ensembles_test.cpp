// The two solvers' bounce counts compared on ensembles (count_ensembles.hpp). Oracles: the
// sampling rule's closed form (indices round(k (n − 1)/(s − 1))); the rule's definition at its
// edges; and the study's own stored inputs: each member's count is the count of an independent
// solve of that perturbed throw, and each verdict is what its rule decides from Welch's interval
// recomputed from the stored members.
#include <boost/test/unit_test.hpp>

#include "verification/stones/convergence_throw.hpp"
#include "verification/stones/count_ensembles.hpp"
#include "verification/study/verdict_rules.hpp"

namespace stoneskip {
namespace {

BOOST_AUTO_TEST_SUITE(count_ensembles)

BOOST_AUTO_TEST_CASE(sampled_values_are_evenly_spaced_with_both_ends) {
  const std::vector<double> grid{0, 5, 10, 15, 20, 25, 30, 35, 40};
  BOOST_TEST(sampled_values(grid, 3) == (std::vector<double>{0, 20, 40}), boost::test_tools::per_element());
  BOOST_TEST(sampled_values(grid, 4) == (std::vector<double>{0, 15, 25, 40}), boost::test_tools::per_element());
  BOOST_TEST(sampled_values(grid, 1) == (std::vector<double>{20}), boost::test_tools::per_element());
  BOOST_TEST(sampled_values(grid, 20) == grid, boost::test_tools::per_element());
  BOOST_TEST(sampled_values(grid, 0).empty());
}

BOOST_AUTO_TEST_CASE(a_difference_is_established_only_where_the_interval_excludes_zero) {
  Record in;
  in.set("valid", 1.0).set("difference_low", -0.4).set("difference_high", 1.2).set("count_spread", 2.0);
  BOOST_TEST(decide("ensemble_bounce_agreement", in) == "no difference established");
  in.set("difference_low", 0.01);
  BOOST_TEST(decide("ensemble_bounce_agreement", in) == "different bounce counts");
  in.set("difference_low", -2.0).set("difference_high", -0.01);
  BOOST_TEST(decide("ensemble_bounce_agreement", in) == "different bounce counts");
  in.set("difference_low", 0.0).set("difference_high", 0.0).set("count_spread", 0.0);  // every member the same count
  BOOST_TEST(decide("ensemble_bounce_agreement", in) == "same bounce count");
  in.set("valid", 0.0);
  BOOST_TEST(decide("ensemble_bounce_agreement", in) == "not measured");
}

BOOST_AUTO_TEST_CASE(an_ensemble_with_a_failed_run_decides_nothing) {
  // The stones report's spin-40 paper throw: real-time 4.38 ± 0.87, reference 7.4 ± 2.9 over the
  // runs that finished, interval [-5.13, -0.9], with 3 and 6 of 16 failed. The interval excludes
  // 0, but a failed run's count is unknown and the failures are not a random sample: no verdict.
  Record in;
  in.set("valid", 1.0).set("difference_low", -5.13).set("difference_high", -0.9).set("count_spread", 3.77);
  in.set("realtime_failed", 3.0).set("reference_failed", 6.0);
  BOOST_TEST(decide("ensemble_bounce_agreement", in) == "not decided: runs failed");
  in.set("realtime_failed", 0.0);  // one side alone failing is enough
  BOOST_TEST(decide("ensemble_bounce_agreement", in) == "not decided: runs failed");
  in.set("reference_failed", 0.0);  // no failure: the interval decides again
  BOOST_TEST(decide("ensemble_bounce_agreement", in) == "different bounce counts");
  in.set("difference_low", 0.0).set("difference_high", 0.0).set("count_spread", 0.0).set("reference_failed", 1.0);
  BOOST_TEST(decide("ensemble_bounce_agreement", in) == "not decided: runs failed");  // not "same" either
}

BOOST_AUTO_TEST_CASE(members_are_independent_solves_and_verdicts_follow_welch, *boost::unit_test::timeout(120)) {
  // The convergence throw's first contact and the flight after it (the short sweep of
  // bounce_sweep_test), in the physical convention, real-time against real-time at two steps.
  ThrowProblem base = convergence_throw();
  RealtimeOptions fine = base.realtime;
  fine.dt_s = 1e-3;
  fine.contact_dt_s = 1e-5;
  fine.t_max_s = 0.12;
  RealtimeOptions coarse = fine;
  coarse.contact_dt_s = 1e-4;
  CountEnsembleOptions o;
  o.members = 4;
  o.throws_per_axis = 2;
  o.convention = Convention::physical;
  const auto throws = run_count_ensembles(base, realtime_choice(fine), realtime_choice(coarse),
                                          {{SweepParameter::spin_rev_s, {0.0, 30.0, 60.0}}}, o, ParallelOptions{2, "", {}});
  BOOST_REQUIRE(throws.size() == 2u);
  BOOST_TEST(throws[0].value == 0.0);
  BOOST_TEST(throws[1].value == 60.0);
  const ThrowProblem conv = with_convention(base, Convention::physical);
  for (const auto& t : throws) {
    BOOST_REQUIRE(t.realtime.size() == 4u);
    ThrowParameters tp = conv.parameters;
    tp.spin_rev_s = t.value;
    BOOST_TEST(t.realtime_single == solve(with_parameters(conv, tp), realtime_choice(fine)).bounces);
    tp.speed_m_s *= t.factors[3];
    BOOST_TEST(t.reference[3] == solve(with_parameters(conv, tp), realtime_choice(coarse)).bounces);
    const MeanDifference d = welch_difference(t.realtime, t.reference);
    BOOST_TEST(d.low == t.difference.low);
    BOOST_TEST(d.high == t.difference.high);
  }
  const Record r = count_ensembles_findings(throws, o);
  BOOST_TEST(contradicted_verdicts(r).empty());
  BOOST_TEST(r.number("sampled") == 2.0);
  BOOST_TEST(r.number("different") + r.number("not_established") + r.number("same") == 2.0);
}

BOOST_AUTO_TEST_CASE(invalid_options_are_refused) {
  CountEnsembleOptions o;
  o.members = 3;
  std::string why;
  BOOST_TEST(!o.valid(&why));
  BOOST_TEST(why.find("even") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
