// The per-throw record against hand-built solver results: each column holds the field it names,
// the first contact's values (NaN without a contact), the disagreement columns are real-time
// minus reference and the contact comparison of verification/stones, and exactly the cost_
// columns carry where and at what cost a throw ran.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "verification/sweep/throw_record.hpp"

using namespace stoneskip;

namespace {

ThrowResult result(int bounces, double distance_m, std::vector<std::pair<double, double>> contacts) {
  ThrowResult r;
  r.bounces = bounces;
  r.distance_m = distance_m;
  r.lateral_m = -0.25;
  r.outcome = Outcome::sank;
  r.end_time_s = 1.5;
  r.stats.steps = 1234;
  r.stats.cpu_s = 0.003;
  r.stats.wall_s = 0.004;
  for (const auto& [start, end] : contacts) {
    ContactRecord c;
    c.start_s = start;
    c.end_s = end;
    c.entry_speed_m_s = 7.5;
    c.exit_speed_m_s = 6.0;
    r.contacts.push_back(c);
  }
  return r;
}

double at(const ThrowRecord& rec, const std::vector<double>& row, const std::string& column) {
  for (std::size_t c = 0; c < rec.columns().size(); ++c)
    if (rec.columns()[c] == column) return row[c];
  BOOST_FAIL("no column " << column);
  return NAN;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(sweep_throw_record)

BOOST_AUTO_TEST_CASE(a_row_holds_what_its_columns_name) {
  // Oracle: the hand-built results.
  const ThrowRecord rec({"throw.speed_m_s", "throw.spin_rev_s"}, SweepSolvers::both);
  const ThrowResult rt = result(3, 12.0, {{0.10, 0.11}, {0.30, 0.32}, {0.5, 0.6}});
  const ThrowResult ref = result(2, 10.5, {{0.1002, 0.1101}, {0.31, 0.33}});
  SweepThrowCost cost;
  cost.rank = 2;
  cost.thread = 1;
  cost.setup_wall_s = 3e-5;
  std::vector<ThrowNote> notes;
  const std::vector<double> row = rec.row(17, {8.0, 12.5}, &rt, &ref, cost, NAN, notes);
  BOOST_REQUIRE_EQUAL(row.size(), rec.width());
  BOOST_TEST(at(rec, row, "throw") == 17);
  BOOST_TEST(at(rec, row, "throw.spin_rev_s") == 12.5);
  BOOST_TEST(at(rec, row, "realtime_bounces") == 3);
  BOOST_TEST(at(rec, row, "reference_distance_m") == 10.5);
  BOOST_TEST(at(rec, row, "realtime_first_contact_start_s") == 0.10);
  BOOST_TEST(at(rec, row, "reference_first_contact_end_s") == 0.1101);
  BOOST_TEST(at(rec, row, "realtime_steps") == 1234);
  BOOST_TEST(at(rec, row, "disagreement_bounces") == 1);
  BOOST_TEST(at(rec, row, "disagreement_distance_m") == 1.5);
  BOOST_TEST(at(rec, row, "disagreement_spurious_contacts") == 1);  // the real-time contact at 0.5 s
  BOOST_TEST(at(rec, row, "disagreement_missed_contacts") == 0);
  BOOST_TEST(std::abs(at(rec, row, "disagreement_first_contact_start_s") + 2e-4) < 1e-15);
  BOOST_TEST(at(rec, row, "cost_realtime_wall_s") == 0.004);
  BOOST_TEST(at(rec, row, "cost_rank") == 2);
  BOOST_TEST(notes.empty());
  BOOST_TEST(std::isnan(at(rec, row, "shortest_resolved_flight_s")));  // not assessed: no count either
  BOOST_TEST(std::isnan(at(rec, row, "realtime_bounces_before_short_flight")));
}

BOOST_AUTO_TEST_CASE(bounces_before_a_flight_shorter_than_the_mesh_resolves_are_counted_per_solver) {
  // Oracle: the hand-built contacts. Real time: bounces end at 0.11 (next start 0.1105: a 0.5 ms
  // flight), 0.12 (next 0.30) and 0.32 (the last: no flight after it); reference: 0.11 → 0.1115
  // (1.5 ms). With τ = 1 ms only real time's first bounce precedes a shorter flight; a contact
  // that did not bounce (the reference's second) is not counted whatever follows it.
  const ThrowRecord rec({"throw.spin_rev_s"}, SweepSolvers::both);
  ThrowResult rt = result(3, 12.0, {{0.10, 0.11}, {0.1105, 0.12}, {0.30, 0.32}});
  ThrowResult ref = result(1, 10.5, {{0.10, 0.11}, {0.1115, 0.12}, {0.1201, 0.2}});
  for (auto& c : rt.contacts) c.bounced = true;
  ref.contacts[0].bounced = true;
  std::vector<ThrowNote> notes;
  const std::vector<double> row = rec.row(0, {40.0}, &rt, &ref, {}, 1e-3, notes);
  BOOST_TEST(at(rec, row, "shortest_resolved_flight_s") == 1e-3);
  BOOST_TEST(at(rec, row, "realtime_bounces_before_short_flight") == 1);
  BOOST_TEST(at(rec, row, "reference_bounces_before_short_flight") == 0);
  BOOST_TEST(at(rec, row, "realtime_bounces") == 3);  // still counted (spec §1.8)
}

BOOST_AUTO_TEST_CASE(no_contact_leaves_the_first_contact_columns_nan_and_a_failure_leaves_a_note) {
  // Oracle: a result without contacts that failed.
  const ThrowRecord rec({"stone.radius_m"}, SweepSolvers::reference);
  ThrowResult r = result(0, 0.0, {});
  r.outcome = Outcome::failed;
  r.outcome_detail = "too many steps";
  std::vector<ThrowNote> notes;
  const std::vector<double> row = rec.row(4, {0.03}, nullptr, &r, {}, NAN, notes);
  BOOST_TEST(std::isnan(at(rec, row, "reference_first_contact_start_s")));
  BOOST_TEST(at(rec, row, "reference_outcome") == kOutcomeFailed);
  BOOST_REQUIRE_EQUAL(notes.size(), 1u);
  BOOST_TEST(notes[0].throw_index == 4u);
  BOOST_TEST(notes[0].detail == "too many steps");
}

BOOST_AUTO_TEST_CASE(a_failed_solve_has_no_disagreement) {
  // Oracle: a failed run's counts are those at its failure (`run` says "not compared"): with the
  // reference failed after 2 bounces against the real-time model's 3, every disagreement is NaN,
  // not the 1 that a row of two finished runs holds (a_row_holds_what_its_columns_name).
  const ThrowRecord rec({"throw.speed_m_s"}, SweepSolvers::both);
  const ThrowResult rt = result(3, 12.0, {{0.10, 0.11}, {0.30, 0.32}, {0.5, 0.6}});
  ThrowResult ref = result(2, 10.5, {{0.1002, 0.1101}, {0.31, 0.33}});
  ref.outcome = Outcome::failed;
  std::vector<ThrowNote> notes;
  const std::vector<double> row = rec.row(3, {8.0}, &rt, &ref, {}, NAN, notes);
  for (std::size_t c = 0; c < rec.width(); ++c)
    if (rec.columns()[c].rfind("disagreement_", 0) == 0) BOOST_TEST(std::isnan(row[c]), rec.columns()[c]);
  BOOST_TEST(at(rec, row, "reference_bounces") == 2);  // the run's own columns keep what it reached
}

BOOST_AUTO_TEST_CASE(only_cost_columns_depend_on_where_a_throw_ran) {
  // Oracle: the same results with two different sites and costs differ only in cost_ columns.
  const ThrowRecord rec({"a"}, SweepSolvers::realtime);
  ThrowResult r1 = result(1, 2.0, {{0.1, 0.2}}), r2 = r1;
  r2.stats.wall_s = 0.5;  // the solver's own wall clock is a cost
  SweepThrowCost c1, c2;
  c2.rank = 5;
  c2.thread = 3;
  c2.start_unix_s = 1.7e9;
  c2.setup_wall_s = 1;
  c2.realtime_cpu_s = 2;
  std::vector<ThrowNote> notes;
  const auto a = rec.row(0, {1.0}, &r1, nullptr, c1, 1e-3, notes), b = rec.row(0, {1.0}, &r2, nullptr, c2, 1e-3, notes);
  for (std::size_t c = 0; c < rec.width(); ++c)
    BOOST_TEST((a[c] != b[c]) == rec.is_cost_column(c), rec.columns()[c]);
  // The wall column holds the solve's wall clock, not its CPU time (which a sweep of more threads
  // than cores leaves far below it).
  ThrowResult r3 = r1;
  r3.stats.wall_s = 0.75;
  r3.stats.cpu_s = 0.25;
  const auto w = rec.row(0, {1.0}, &r3, nullptr, c1, 1e-3, notes);
  BOOST_TEST(at(rec, w, "cost_realtime_wall_s") == 0.75);
  BOOST_TEST(at(rec, w, "cost_realtime_cpu_s") == c1.realtime_cpu_s);
  const auto n = rec.not_run_row(9, {1.0}, c2);
  BOOST_TEST(at(rec, n, "realtime_outcome") == kOutcomeNotRun);
  BOOST_TEST(std::isnan(at(rec, n, "realtime_bounces")));
  BOOST_TEST(at(rec, n, "cost_setup_wall_s") == 1);
}

BOOST_AUTO_TEST_SUITE_END()
