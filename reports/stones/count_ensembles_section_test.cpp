// The ensembles section (count_ensembles_section.cpp) formatted from a record whose counts are
// known: hand-made ensembles, so each failed member and each runaway is counted by hand.
#include <boost/test/unit_test.hpp>

#include "reports/stones/report_sections.hpp"
#include "verification/stones/count_ensembles.hpp"

namespace stoneskip {
namespace {

BOOST_AUTO_TEST_SUITE(count_ensembles_section_)

// Throw 1: real-time 2 of 4 members failed, both ran away; reference 1 failed, not by running away.
// Throw 2: every member finished.
Record two_throws(Convention convention) {
  CountEnsembleThrow a;
  a.value = 40;
  a.factors = {1, 1, 1, 1};
  a.realtime = {3, -1, -1, 5};
  a.reference = {4, -1, 6, 7};
  a.realtime_failed = a.realtime_ran_away = 2;
  a.reference_failed = 1;
  a.difference = welch_difference({3, 5}, {4, 6, 7});
  CountEnsembleThrow b = a;
  b.value = 80;
  b.realtime = {2, 2, 3, 3};
  b.reference = {2, 3, 2, 3};
  b.realtime_failed = b.realtime_ran_away = b.reference_failed = 0;
  b.difference = welch_difference(b.realtime, b.reference);
  CountEnsembleOptions o;
  o.members = 4;
  o.convention = convention;
  return count_ensembles_findings({a, b}, o);
}

BOOST_AUTO_TEST_CASE(failed_members_and_runaways_are_shown_per_throw_and_in_the_tally) {
  const std::string md = count_ensembles_section(two_throws(Convention::paper)).markdown;
  BOOST_TEST(md.find("failed members (of them ran away): real-time / reference") != std::string::npos);
  BOOST_TEST(md.find("| 2 (2) / 1 (0) |") != std::string::npos, md);
  BOOST_TEST(md.find("| 0 (0) / 0 (0) |") != std::string::npos);
  BOOST_TEST(md.find("Of the 3 failed members of all ensembles, 2 ran away") != std::string::npos, md);
  BOOST_TEST(md.find("the printed forces create energy") != std::string::npos);
  BOOST_TEST(md.find("1 failed otherwise") != std::string::npos);
  // The two sampled throws are one family held to 95 %: each at 97.5 % (Bonferroni).
  BOOST_TEST(md.find("at 97.5 % for each of the 2 sampled throws, so that their verdicts hold together at 95 %") !=
                 std::string::npos, md);
  BOOST_TEST(md.find("difference [97.5 % interval]") != std::string::npos, md);
  const std::string physical = count_ensembles_section(two_throws(Convention::physical)).markdown;
  BOOST_TEST(physical.find("the printed forces") == std::string::npos);
  BOOST_TEST(physical.find("so the solver's steps did") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(data_without_the_kinds_of_failure_still_renders) {
  // A table written before the runaways were stored: no ran-away columns.
  Record r = two_throws(Convention::paper);
  const Table& full = r.table("throws");
  Table old{{}, {}};
  for (const std::string& c : full.columns)
    if (c != "realtime_ran_away" && c != "reference_ran_away") old.columns.push_back(c);
  for (std::size_t i = 0; i < full.rows(); ++i) {
    std::vector<double> row;
    for (const std::string& c : old.columns) row.push_back(full.column(c)[i]);
    old.add_row(row);
  }
  r.set_table("throws", old);
  // Nor the family's levels (written before the verdicts were held together): tested at 95 % each,
  // and said so.
  Record older;
  for (const auto& [k, v] : r.numbers())
    if (k != "comparison_confidence" && k != "family_confidence") older.set(k, v);
  for (const auto& [k, v] : r.texts()) older.set(k, v);
  for (const auto& [k, v] : r.tables()) older.set_table(k, v);
  for (const auto& [k, v] : r.string_lists()) older.set_strings(k, v);
  for (const std::string& k : r.child_names()) older.add_child(k, r.at(k));
  const std::string md = count_ensembles_section(older).markdown;
  BOOST_TEST(md.find("Each throw's interval is 95 % on its own, not jointly") != std::string::npos, md);
  BOOST_TEST(md.find("difference [95 % interval]") != std::string::npos);
  BOOST_TEST(md.find("failed members: real-time / reference") != std::string::npos);
  BOOST_TEST(md.find("| 2 / 1 |") != std::string::npos, md);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
