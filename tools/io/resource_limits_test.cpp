// The limits decided before any work: an estimate above its limit is refused with the
// estimate and the limit in one line; the flags lift them. Oracle: the numbers put in.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>

#include "tools/io/input_error.hpp"
#include "tools/io/resource_limits.hpp"

using namespace stoneskip;

namespace {
std::string refusal(const ResourceEstimate& e, const ResourceLimits& l) {
  try {
    enforce_limits(e, l, "case.toml");
    return "";
  } catch (const InputError& x) {
    return x.what();
  }
}
}  // namespace

BOOST_AUTO_TEST_SUITE(resource_limits)

BOOST_AUTO_TEST_CASE(an_estimate_above_its_limit_is_refused_with_both_numbers) {
  ResourceEstimate e;
  e.add_memory(22.5e9, "10.5 arrays of 16384 x 16384 cells");
  const std::string m = refusal(e, ResourceLimits{});
  BOOST_TEST(m == "case.toml: needs about 22.5 GB of memory (10.5 arrays of 16384 x 16384 cells), above the limit of "
                  "8 GB (cases/README.md, Limits); --max-memory-gb raises it");
  BOOST_TEST(refusal(e, ResourceLimits{23e9, false}) == "");
  ResourceEstimate w;
  w.add_work(4.4e9, 2e9, "triangle evaluations");
  const std::string s = refusal(w, ResourceLimits{});
  BOOST_TEST(s.find("case.toml: about 4.4e+09 triangle evaluations, above the limit of 2e+09") == 0u, s);
  BOOST_TEST(s.find("--allow-large") != std::string::npos);
  BOOST_TEST(refusal(w, ResourceLimits{8e9, true}) == "");
}

BOOST_AUTO_TEST_CASE(an_estimate_that_cannot_be_made_is_refused_even_with_allow_large) {
  // Oracle: NaN and infinity compare false with any limit: an estimate from absurd inputs is not
  // a large run but a broken one.
  ResourceEstimate w;
  w.add_work(INFINITY, 2e9, "steps");
  BOOST_TEST(refusal(w, ResourceLimits{}) != "");
  BOOST_TEST(refusal(w, ResourceLimits{8e9, true}).find("cannot be estimated") != std::string::npos);
  ResourceEstimate m;
  m.add_memory(NAN, "x");
  BOOST_TEST(refusal(m, ResourceLimits{1e18, true}) != "");
}

BOOST_AUTO_TEST_SUITE_END()
