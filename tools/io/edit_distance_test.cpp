// Oracle: distances worked by hand.
#include <boost/test/unit_test.hpp>

#include "tools/io/edit_distance.hpp"

using stoneskip::edit_distance;
using stoneskip::looks_misspelt;

BOOST_AUTO_TEST_SUITE(edit_distance_)

BOOST_AUTO_TEST_CASE(a_swap_of_neighbours_is_one_edit_and_the_rest_are_levenshteins) {
  BOOST_TEST(edit_distance("cuont", "count") == 1u);  // u and o swapped
  BOOST_TEST(edit_distance("radiuss_m", "radius_m") == 1u);
  BOOST_TEST(edit_distance("Solver", "solver") == 0u);  // case is not an edit
  BOOST_TEST(edit_distance("kitten", "sitting") == 3u);  // Levenshtein's example
  BOOST_TEST(edit_distance("ca", "abc") == 3u);  // optimal string alignment: no edit of a swapped pair
  BOOST_TEST(edit_distance("", "abc") == 3u);
  // "cuont" was called "missing key count" with no hint: a five-letter key allows one edit.
  BOOST_TEST(looks_misspelt("cuont", "count"));
  BOOST_TEST(!looks_misspelt("ab", "xy"));
  BOOST_TEST(!looks_misspelt("count", "count"));
}

BOOST_AUTO_TEST_SUITE_END()
