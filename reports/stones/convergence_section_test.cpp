// The convergence section's words on the study's adaptive schemes (convergence_section.cpp) follow
// the series stored: a study of bs32 alone keeps the sentence it always had; one with dp54 beside
// it names both and each fixed-step member's order; one without an adaptive scheme says nothing
// of tolerances. Oracle: the sentence of the section before dp54 could be in it, and the schemes'
// formal orders as the series store them.
#include <boost/test/unit_test.hpp>

#include <string>
#include <utility>
#include <vector>

#include "reports/stones/report_sections.hpp"

namespace stoneskip {
namespace {

// A record with, for each (scheme, against the tolerance, formal order), one series.
Record with_series(const std::vector<std::pair<std::string, std::pair<bool, double>>>& series) {
  Record r;
  std::vector<std::string> keys;
  for (const auto& [scheme, kind] : series) {
    const std::string key = (kind.first ? "start_time." : "flight_state.") + scheme;
    Record& s = r.child("series").child(key);
    s.set("scheme", scheme);
    s.set("against_tolerance", kind.first);
    s.set("formal_order", kind.second);
    keys.push_back(key);
  }
  r.set_strings("series_keys", keys);
  return r;
}

BOOST_AUTO_TEST_SUITE(convergence_section_)

BOOST_AUTO_TEST_CASE(the_adaptive_schemes_are_named_as_the_series_store_them) {
  const ConvergenceAdaptiveWords one =
      convergence_adaptive_words(with_series({{"rk4", {false, 4}}, {"bs32", {false, 3}}, {"bs32", {true, 1}}}));
  BOOST_TEST(one.runs == ", its adaptive scheme (`bs32`) with shrinking tolerances (rtol = atol_m)");
  BOOST_TEST(one.members == ", and `bs32`'s fixed-step member 3 when the scheme runs alone");
  BOOST_TEST(one.proportional.find("; the adaptive scheme's error should fall in proportion to its tolerance") == 0);

  const ConvergenceAdaptiveWords two = convergence_adaptive_words(with_series(
      {{"rk4", {false, 4}}, {"bs32", {false, 3}}, {"dp54", {false, 5}}, {"bs32", {true, 1}}, {"dp54", {true, 1}}}));
  BOOST_TEST(two.runs == ", its adaptive schemes (`bs32` and `dp54`) with shrinking tolerances (rtol = atol_m)");
  BOOST_TEST(two.members == ", and the fixed-step members of `bs32` (3) and `dp54` (5) when the scheme runs alone");
  BOOST_TEST(two.proportional.find("; an adaptive scheme's error") == 0);
  BOOST_TEST(two.fitted == " The adaptive schemes' errors against their tolerances are fitted with a single power.");

  const ConvergenceAdaptiveWords none = convergence_adaptive_words(with_series({{"rk4", {false, 4}}}));
  BOOST_TEST((none.runs + none.members + none.proportional + none.fitted).empty());
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
