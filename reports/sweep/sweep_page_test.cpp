// The sweep page's prose against counts made by hand from a small table.
#include <boost/test/unit_test.hpp>

#include <string>

#include "reports/sweep/sweep_maps.hpp"
#include "reports/sweep/sweep_page.hpp"
#include "verification/sweep/sweep_run.hpp"

using namespace stoneskip;

namespace {

BOOST_AUTO_TEST_SUITE(sweep_page)

BOOST_AUTO_TEST_CASE(the_contact_counts_run_over_the_throws_the_sentence_names) {
  // Oracle: sums by hand. Four throws on a 1-axis grid, both solvers; the real-time solve of throw
  // 2 failed. Of the 3 throws that both solved, missed contacts 1 + 2 + 8 = 11 and added
  // 1 + 3 + 16 = 20; the failed row's 4 and 5 must not count (main said 15 and 25, summing all rows).
  SweepData d;
  d.solvers = SweepSolvers::both;
  SweepAxis a;
  a.key = "speed_m_s";
  a.from = 1;
  a.to = 4;
  a.count = 4;
  d.design.axes.push_back(a);
  d.throws.columns = sweep_record(d.design, d.solvers).columns();
  const std::size_t w = d.throws.columns.size();
  d.throws.values.assign(4 * w, 0.0);
  const double missed[] = {1, 2, 4, 8}, spurious[] = {1, 3, 5, 16};
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t c = 0; c < w; ++c) {
      const std::string& col = d.throws.columns[c];
      double& v = d.throws.values[i * w + c];
      if (col == "realtime_bounces" || col == "reference_bounces") v = 3;
      if (col == "realtime_outcome" && i == 2) v = kOutcomeFailed;
      if (col == "disagreement_missed_contacts") v = missed[i];
      if (col == "disagreement_spurious_contacts") v = spurious[i];
    }
  const std::string md = sweep_markdown(d, {}, "s.h5");
  BOOST_TEST(md.find("Of 3 throws that both solved") != std::string::npos, md);
  BOOST_TEST(md.find("missed 11 of the reference's contacts and added 20") != std::string::npos, md);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
