// Prose lists for the reports' sentences (markdown.hpp): every section that names several things
// ("`bs32` and `dp54`", "a, b and c") writes them through and_list.
#include <boost/test/unit_test.hpp>

#include <string>
#include <vector>

#include "reports/common/markdown.hpp"

using namespace stoneskip;

BOOST_AUTO_TEST_SUITE(markdown)

BOOST_AUTO_TEST_CASE(a_list_reads_as_prose_with_and_before_its_last_item) {
  BOOST_TEST(and_list({}) == "");
  BOOST_TEST(and_list({"a"}) == "a");
  BOOST_TEST(and_list({"a", "b"}) == "a and b");
  BOOST_TEST(and_list({"a", "b", "c"}) == "a, b and c");
  BOOST_TEST(and_list({"`bs32`", "`dp54`", "x", "y"}) == "`bs32`, `dp54`, x and y");
}

BOOST_AUTO_TEST_SUITE_END()
