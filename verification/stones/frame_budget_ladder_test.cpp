// The budget ladder's arithmetic (frame_budget_ladder.hpp) on hand-built counts, and one small
// ladder run end to end against the budget's own cap.
#include "verification/stones/frame_budget_ladder.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>

#include "verification/stones/convergence_throw.hpp"

namespace stoneskip {
namespace {

FrameBudgetRung rung(long n, std::vector<int> bounces) {
  FrameBudgetRung r;
  r.rhs_per_frame = n;
  r.bounces = std::move(bounces);
  return r;
}

BOOST_AUTO_TEST_SUITE(frame_budget_ladder)

BOOST_AUTO_TEST_CASE(matches_skip_throws_without_a_reference_and_count_a_failure_as_a_miss) {
  // Oracle: by hand. Reference counts 3, −1 (CVODE's tolerances disagree), 2, 4; the rung's 3, 5,
  // −1 (failed: its forced steps ran away), 4: compared are throws 0, 2 and 3; 0 and 3 match.
  FrameBudgetRung r = rung(64, {3, 5, -1, 4});
  count_budget_matches(r, {3, -1, 2, 4});
  BOOST_TEST(r.compared == 3);
  BOOST_TEST(r.matched == 2);
  FrameBudgetRung none = rung(64, {-1});
  count_budget_matches(none, {3});
  BOOST_TEST(none.match_fraction() == 0.0);
  FrameBudgetRung nothing = rung(64, {2});
  count_budget_matches(nothing, {-1});
  BOOST_TEST(std::isnan(nothing.match_fraction()));
}

BOOST_AUTO_TEST_CASE(the_smallest_budget_meets_the_target_at_every_larger_one) {
  // Oracle: the Wilson lower end by hand, n / (n + z²) for n of n (z = 1.96): 200 of 200 gives
  // 0.9812 ≥ 0.98. Over 200 throws: all match at 16 (by chance), half at 64, all at 256 and 1024:
  // 256, not 16. A largest rung that misses: none (−1). 2 of 2 (lower end 0.34) shows nothing.
  std::vector<int> ref(200), half(200);
  for (int i = 0; i < 200; ++i) {
    ref[i] = 1 + i % 3;
    half[i] = i % 2 ? ref[i] : ref[i] + 1;
  }
  std::vector<FrameBudgetRung> rs{rung(16, ref), rung(64, half), rung(256, ref), rung(1024, ref)};
  for (auto& r : rs) count_budget_matches(r, ref);
  BOOST_TEST(smallest_budget_meeting(rs, 0.98) == 256);
  rs.back() = rung(1024, half);
  count_budget_matches(rs.back(), ref);
  BOOST_TEST(smallest_budget_meeting(rs, 0.98) == -1);
  std::vector<FrameBudgetRung> two{rung(16, {1, 2})};
  count_budget_matches(two.back(), {1, 2});
  BOOST_TEST(two.back().match_fraction() == 1.0);
  BOOST_TEST(smallest_budget_meeting(two, 0.98) == -1);
}

BOOST_AUTO_TEST_CASE(a_ladder_spends_at_most_its_budget_per_frame) {
  // Oracle: the budget itself. Each rung spends at most N right-hand sides in each of the frames
  // its throws span (plus nothing: the first right-hand side counts in the first frame), and the
  // smallest budget forces steps over the tolerance (ratio > 1) in the contact of the convergence
  // throw. About 0.3 s of CPU.
  FrameBudgetLadderOptions o;
  o.rhs_per_frame = {8, 64};
  const auto rungs = run_frame_budget_ladder({convergence_throw()}, {}, o);
  BOOST_REQUIRE_EQUAL(rungs.size(), 2u);
  for (const FrameBudgetRung& r : rungs) {
    BOOST_TEST(r.frames > 0);
    BOOST_TEST(r.rhs_evaluations <= r.rhs_per_frame * r.frames, "budget " << r.rhs_per_frame);
    BOOST_TEST(r.compared == 0);  // no reference counts given
  }
  BOOST_TEST(rungs[0].forced_steps > 0);
  BOOST_TEST(rungs[0].max_error_ratio > 1);
  FrameBudgetLadderOptions bad;
  bad.rhs_per_frame = {64, 16};
  BOOST_CHECK_THROW(run_frame_budget_ladder({convergence_throw()}, {}, bad), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
