// The sweep table's check against tables built by the record itself (throw_record.hpp): what a
// sweep writes passes, and each kind of edit is refused with a message naming the column, the
// throw and what is wrong.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <functional>
#include <limits>

#include "tools/io/input_error.hpp"
#include "verification/sweep/sweep_table_check.hpp"

using namespace stoneskip;

namespace {

SweepDesign grid_design() {
  SweepDesign d;
  d.kind = DesignKind::grid;
  SweepAxis spin;
  spin.key = "throw.spin_rev_s";
  spin.from = 0;
  spin.to = 40;
  spin.count = 3;
  SweepAxis speed;
  speed.key = "throw.speed_m_s";
  speed.from = 4;
  speed.to = 16;
  speed.count = 2;
  speed.scale = AxisScale::log;
  d.axes = {spin, speed};
  return d;
}

ThrowResult result(int bounces, int contacts) {
  ThrowResult r;
  r.bounces = bounces;
  r.outcome = Outcome::sank;
  r.contacts.resize(static_cast<std::size_t>(contacts));
  return r;
}

// The table a sweep of the design writes: throw 4 not run, the others solved (counts vary).
Table written(const SweepDesign& d, SweepSolvers solvers) {
  std::vector<std::string> keys;
  for (const auto& a : d.axes) keys.push_back(a.key);
  const ThrowRecord rec(keys, solvers);
  Table t;
  t.columns = rec.columns();
  std::vector<ThrowNote> notes;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const ThrowResult rt = result(static_cast<int>(i % 3), static_cast<int>(i % 3) + 1), ref = result(1, 2);
    const bool realtime = solvers != SweepSolvers::reference, reference = solvers != SweepSolvers::realtime;
    t.add_row(i == 4 ? rec.not_run_row(i, d.point(i), {})
                     : rec.row(i, d.point(i), realtime ? &rt : nullptr, reference ? &ref : nullptr, {},
                               i % 2 == 0 ? 0.03 : NAN, notes));  // τ_δ assessed on even throws
  }
  return t;
}

void set(Table& t, std::size_t row, const std::string& column, double v) {
  for (std::size_t c = 0; c < t.columns.size(); ++c)
    if (t.columns[c] == column) {
      t.values[row * t.columns.size() + c] = v;
      return;
    }
  BOOST_FAIL("no column " << column);
}

// The message of the refusal, or "" when the table passes.
std::string refusal(const SweepDesign& d, SweepSolvers s, const Table& t) {
  try {
    check_sweep_table("f.h5", d, s, t);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(sweep_table_check)

BOOST_AUTO_TEST_CASE(what_a_sweep_writes_passes) {
  // Oracle: the record's own rows (a log axis, a throw not run, every solver choice).
  const SweepDesign d = grid_design();
  for (SweepSolvers s : {SweepSolvers::realtime, SweepSolvers::reference, SweepSolvers::both})
    BOOST_TEST(refusal(d, s, written(d, s)) == "", to_string(s));
}

BOOST_AUTO_TEST_CASE(each_kind_of_edit_is_refused_naming_the_column_and_the_throw) {
  const SweepDesign d = grid_design();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Edit {
    std::size_t row;
    const char* column;
    double value;
    const char* message;  // the whole message
  };
  const Edit edits[] = {
      {3, "throw", 7, "f.h5: throws.throw: throw 3: the row holds throw 7 (rows are in throw-index order)"},
      {1, "throw.speed_m_s", 5, "f.h5: throws.throw.speed_m_s: throw 1: 5 is not the design's value 16"},
      {0, "realtime_outcome", 9, "f.h5: throws.realtime_outcome: throw 0: 9 is not an outcome code (0=sank,1=time_limit,2=failed,3=not_run)"},
      {2, "realtime_bounces", 2.5, "f.h5: throws.realtime_bounces: throw 2: 2.5 is not a count (a whole number, 0 or more)"},
      {2, "reference_bounces", -7, "f.h5: throws.reference_bounces: throw 2: -7 is not a count (a whole number, 0 or more)"},
      {2, "reference_contacts", nan, "f.h5: throws.reference_contacts: throw 2: nan is not a count (a whole number, 0 or more)"},
      {1, "realtime_bounces", 1e300, "f.h5: throws.realtime_bounces: throw 1: 1.0000000000000001e+300 is not a count (a whole number, 0 or more)"},
      {1, "realtime_bounces", 5, "f.h5: throws.realtime_bounces: throw 1: 5 bounces in 2 contacts (each bounce ends a contact)"},
      {4, "realtime_bounces", 3, "f.h5: throws.realtime_bounces: throw 4: 3 for a throw that did not run (NaN expected)"},
      {5, "disagreement_bounces", 0, "f.h5: throws.disagreement_bounces: throw 5: 0 is not realtime_bounces − reference_bounces (1)"},
      {0, "disagreement_contacts", 3, "f.h5: throws.disagreement_contacts: throw 0: 3 is not realtime_contacts − reference_contacts (-1)"},
  };
  for (const Edit& e : edits) {
    Table t = written(d, SweepSolvers::both);
    set(t, e.row, e.column, e.value);
    BOOST_TEST(refusal(d, SweepSolvers::both, t) == e.message);
  }
}

BOOST_AUTO_TEST_CASE(a_failed_solves_disagreement_is_nan_or_in_older_tables_the_difference) {
  // Oracle: the rule of throw_record.hpp (NaN where either solve failed); a table written before it
  // holds the difference, which still passes; any other value is refused.
  const SweepDesign d = grid_design();
  Table t = written(d, SweepSolvers::both);
  set(t, 5, "reference_outcome", kOutcomeFailed);
  set(t, 5, "disagreement_bounces", std::nan(""));
  set(t, 5, "disagreement_contacts", std::nan(""));
  BOOST_TEST(refusal(d, SweepSolvers::both, t) == "");
  set(t, 5, "disagreement_bounces", 1);  // realtime 2 − reference 1: the older tables' difference
  set(t, 5, "disagreement_contacts", 1);
  BOOST_TEST(refusal(d, SweepSolvers::both, t) == "");
  set(t, 5, "disagreement_bounces", 0);
  BOOST_TEST(refusal(d, SweepSolvers::both, t) ==
             "f.h5: throws.disagreement_bounces: throw 5: 0 for a throw whose solve failed (NaN expected)");
}

BOOST_AUTO_TEST_CASE(columns_other_than_the_records_are_refused) {
  const SweepDesign d = grid_design();
  Table t = written(d, SweepSolvers::both);
  t.columns[3] = "realtime_bounce";
  BOOST_TEST(refusal(d, SweepSolvers::both, t) ==
             "f.h5: throws: column 3 is 'realtime_bounce' where a sweep writes 'realtime_bounces'");
  // A table of one solver read as both.
  BOOST_TEST(refusal(d, SweepSolvers::both, written(d, SweepSolvers::realtime)).find("f.h5: throws: has ") == 0u);
}

BOOST_AUTO_TEST_CASE(the_short_flight_counts_are_checked_and_an_older_table_without_them_is_read) {
  // Oracle: the record's rules (throw_record.hpp): a subset of the bounces, NaN exactly where
  // shortest_resolved_flight_s is NaN; a table written before those columns existed is read as it
  // is (sweep-plot and --resume refused every such file).
  const SweepDesign d = grid_design();
  for (const SweepSolvers s : {SweepSolvers::realtime, SweepSolvers::both}) {
    Table t = written(d, s);
    BOOST_TEST(refusal(d, s, t).empty(), refusal(d, s, t));
    Table more = t;
    set(more, 2, "realtime_bounces_before_short_flight", 3);  // throw 2 has 2 bounces
    BOOST_TEST(refusal(d, s, more).find("throws.realtime_bounces_before_short_flight: throw 2: 3 is not a count of at most the 2 bounces") !=
                   std::string::npos,
               refusal(d, s, more));
    Table unassessed = t;
    set(unassessed, 0, "shortest_resolved_flight_s", NAN);
    BOOST_TEST(refusal(d, s, unassessed).find("throw 0: 0 where shortest_resolved_flight_s is") != std::string::npos,
               refusal(d, s, unassessed));
    // The older layout: the same table without the three columns.
    std::vector<std::string> keys;
    for (const auto& a : d.axes) keys.push_back(a.key);
    const std::vector<std::string> older = ThrowRecord(keys, s).columns_without_short_flights();
    Table old;
    old.columns = older;
    for (std::size_t i = 0; i < t.rows(); ++i) {
      std::vector<double> row;
      for (const auto& c : older)
        for (std::size_t k = 0; k < t.columns.size(); ++k)
          if (t.columns[k] == c) row.push_back(t.values[i * t.columns.size() + k]);
      old.add_row(row);
    }
    BOOST_TEST(old.columns.size() + (s == SweepSolvers::both ? 3u : 2u) == t.columns.size());
    BOOST_TEST(refusal(d, s, old).empty(), refusal(d, s, old));
  }
}

BOOST_AUTO_TEST_SUITE_END()
