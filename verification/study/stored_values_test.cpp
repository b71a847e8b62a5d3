// Stored numbers a report needs as counts or finite coordinates. Oracle: the definitions in
// stored_values.hpp; the refused values are those a hand-edited data.h5 produced in a mutation run
// of `report render` (2^62, NaN, a negative count, a fraction, infinity).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "verification/study/stored_values.hpp"

using namespace stoneskip;

namespace {
std::string refusal(const std::function<void()>& read) {
  try {
    read();
  } catch (const RecordError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

BOOST_AUTO_TEST_SUITE(stored_values)

BOOST_AUTO_TEST_CASE(a_count_is_a_whole_number_within_its_bound_and_a_coordinate_is_finite) {
  Record parent;
  Record& r = parent.child("frames");
  r.set("n", 7.0).set("zero", 0.0).set("most", 10.0).set("x", -0.25);
  BOOST_TEST(stored_count(r, "n", 10) == 7u);
  BOOST_TEST(stored_count(r, "zero", 10) == 0u);
  BOOST_TEST(stored_count(r, "most", 10) == 10u);  // the bound itself is allowed
  BOOST_TEST(stored_finite(r, "x") == -0.25);
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  for (double bad : {11.0, -1.0, 2.5, nan, inf, 4611686018427387904.0}) {
    r.set("bad", bad);
    const std::string e = refusal([&] { stored_count(r, "bad", 10); });
    BOOST_TEST(e.find("/frames: 'bad' must be a whole number in [0, 10]") != std::string::npos, bad << ": " << e);
  }
  for (double bad : {nan, inf, -inf}) {
    r.set("bad", bad);
    const std::string e = refusal([&] { stored_finite(r, "bad"); });
    BOOST_TEST(e.find("/frames: 'bad' must be a finite number") != std::string::npos, bad << ": " << e);
  }
  BOOST_TEST(stored_in(r, "x", -0.25, 0) == -0.25);  // both ends allowed
  BOOST_TEST(stored_in(r, "zero", -0.25, 0) == 0);
  for (double bad : {nan, inf, -0.5, 1e308}) {
    r.set("bad", bad);
    const std::string e = refusal([&] { stored_in(r, "bad", -0.25, 0); });
    BOOST_TEST(e.find("/frames: 'bad' must be a number in [-0.25, 0]") != std::string::npos, bad << ": " << e);
  }
  BOOST_TEST(refusal([&] { stored_count(r, "absent", 10); }).find("no number 'absent'") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
