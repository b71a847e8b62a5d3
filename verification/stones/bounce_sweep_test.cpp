// The bisection of a bounce-count threshold always ends: with a tolerance below
// the spacing of doubles (1e-300) the midpoint rounds onto an end and main looped forever; now the
// bracket stops when no double lies strictly between its ends. Oracle: IEEE 754 — the stopped
// bracket's ends are neighbouring doubles (std::nextafter of one is the other), and each end
// still has the count the threshold says.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "verification/stones/bounce_sweep.hpp"
#include "solvers/realtime/stone_stepper.hpp"
#include "verification/stones/convergence_throw.hpp"
#include "verification/stones/throw_problem.hpp"

namespace stoneskip {
namespace {

BOOST_AUTO_TEST_SUITE(bounce_sweep)

BOOST_AUTO_TEST_CASE(a_tolerance_below_the_double_spacing_ends_at_neighbouring_doubles,
                     *boost::unit_test::timeout(120)) {
  BounceSweepSpec s;
  s.name = "tiny_tolerance";
  s.base = convergence_throw();
  s.parameter = SweepParameter::spin_rev_s;
  s.values = {0.0, 60.0};
  RealtimeOptions o = s.base.realtime;
  o.dt_s = 1e-3;
  o.contact_dt_s = 1e-5;
  o.t_max_s = 0.12;  // the first contact (53–96 ms) and the flight after it
  s.solver = realtime_choice(o);
  s.threshold_tolerance = 1e-300;
  const auto r = run_bounce_sweeps({s}, ParallelOptions{1, "", {}});
  BOOST_REQUIRE(r.at(0).counts.size() == 2u);
  BOOST_REQUIRE_MESSAGE(r[0].counts[0] != r[0].counts[1], "the grid must straddle a threshold");
  BOOST_REQUIRE(r[0].thresholds.size() == 1u);
  const CountThreshold& t = r[0].thresholds[0];
  BOOST_TEST(t.bisected);
  BOOST_TEST(std::nextafter(t.lo, INFINITY) == t.hi);
  BOOST_TEST(t.lo > 0.0);
  BOOST_TEST(t.hi < 60.0);
  // About 52 + log2(60 / |t|) halvings reach neighbouring doubles: the runs are bounded by that.
  BOOST_TEST(r[0].runs <= 2 + 64);
}

BOOST_AUTO_TEST_CASE(a_cell_holding_more_than_one_change_says_so, *boost::unit_test::timeout(300)) {
  // Oracle: independent solves of the same throw. The convergence throw makes 1 bounce at a path
  // angle of 22°, 2 at 24° and none at 26° (measured on a 2° grid when written). Bisection follows
  // one change; where the count just above it (a solve at its bracket's upper end) is not the
  // grid's 0 at 26°, a second change lies between them, and the threshold must say so: the stones
  // report had listed "10.88 (1→2)" in a cell that ends at 0, as if that were the only change.
  BounceSweepSpec s;
  s.name = "wide_cell";
  s.base = convergence_throw();
  s.parameter = SweepParameter::path_angle_deg;
  s.values = {22.0, 26.0};
  s.solver = realtime_choice(s.base.realtime);
  s.threshold_tolerance = 0.5;
  const auto r = run_bounce_sweeps({s}, ParallelOptions{2, "", {}});
  BOOST_REQUIRE(r.at(0).thresholds.size() == 1u);
  const CountThreshold& t = r[0].thresholds[0];
  BOOST_TEST_MESSAGE("counts " << r[0].counts[0] << ", " << r[0].counts[1] << "; change " << t.lo << " .. " << t.hi << ": "
                               << t.count_below << " -> " << t.count_above);
  BOOST_TEST(t.count_at_cell_end == r[0].counts[1]);
  ThrowParameters p = s.base.parameters;
  p.path_angle_deg = t.hi;
  RealtimeOptions o = s.base.realtime;
  o.record_trajectory = false;
  const ThrowProblem q = with_parameters(s.base, p);
  const int above = run_realtime(q.stone, q.environment, q.initial, o).bounces;
  BOOST_TEST(above == t.count_above);
  BOOST_REQUIRE_MESSAGE(above != r[0].counts[1], "the premise: the count above the located change is not the cell's end count");
  BOOST_TEST(t.more_in_cell());
}

BOOST_AUTO_TEST_CASE(a_failed_run_stops_the_bisection_and_leaves_the_change_unlocated) {
  // Oracle: a step function with a failing region, where every midpoint is known in advance. The
  // count is 1 below 5.8 and 3 from it; runs in [5.9, 6.0) fail. The bracket [5, 10] halves to
  // 7.5 (3), 6.25 (3), 5.625 (1), 5.9375 (fails): the stones report had listed the failure as a
  // change "1→failed", located to the tolerance, where a failed run says nothing of the change.
  auto count = [](double x) { return x >= 5.9 && x < 6.0 ? -1 : x < 5.8 ? 1 : 3; };
  CountThreshold grid;
  grid.lo = 5.0;
  grid.hi = 10.0;
  grid.count_below = 1;
  grid.count_above = grid.count_at_cell_end = 3;
  const CountThreshold t = bisect_threshold(grid, 0.25, count);
  BOOST_TEST(!t.bisected);
  BOOST_TEST(t.failed_at == 5.9375);
  BOOST_TEST(t.lo == 5.625);  // the last bracket whose ends both have counts
  BOOST_TEST(t.hi == 6.25);
  BOOST_TEST(t.count_above == 3);
  BOOST_TEST(!t.more_in_cell());
  // Without the failing region the same bracket is located: [5.78125, 5.9375], 1 → 3.
  const CountThreshold u = bisect_threshold(grid, 0.25, [](double x) { return x < 5.8 ? 1 : 3; });
  BOOST_TEST(u.bisected);
  BOOST_TEST(std::isnan(u.failed_at));
  BOOST_TEST(u.lo == 5.78125);
  BOOST_TEST(u.hi == 5.9375);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
