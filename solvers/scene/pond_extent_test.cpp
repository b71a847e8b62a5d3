#include "solvers/scene/pond_extent.hpp"

#include <boost/test/unit_test.hpp>

namespace {

// A contact whose first touch is at (x, y).
stoneskip::ContactRecord touching(double x, double y) {
  stoneskip::ContactRecord c;
  c.first_touch_m = stoneskip::Vec3(x, y, 0);
  return c;
}

stoneskip::HeightFieldOptions field(stoneskip::Boundary b) {
  stoneskip::HeightFieldOptions f;
  f.nx = 11;  // x from the origin to origin + 10 × 0.5 m
  f.ny = 5;   // y from the origin to origin + 4 × 0.5 m
  f.cell_m = 0.5;
  f.boundary = b;
  return f;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(pond_extent_)

BOOST_AUTO_TEST_CASE(a_contact_is_off_a_walled_pond_exactly_when_its_first_touch_is_beyond_the_grid_points) {
  // Oracle: the grid's span by hand, origin (1, −1) m: x in [1, 6] m, y in [−1, 1] m (grid points
  // i·d). Points on the rim are on; a hair beyond it (1e-12 m) is off, on each of the four sides.
  using stoneskip::Boundary;
  const std::vector<stoneskip::ContactRecord> contacts = {
      touching(3, 0),  touching(1, -1), touching(6, 1),     touching(1 - 1e-12, 0), touching(6 + 1e-12, 0),
      touching(3, -1 - 1e-12), touching(3, 1 + 1e-12), touching(-40, 200)};
  const stoneskip::PondExtent p = stoneskip::pond_extent(field(Boundary::reflecting), 1, -1, contacts);
  BOOST_TEST(p.x0_m == 1);
  BOOST_TEST(p.x1_m == 6);
  BOOST_TEST(p.y0_m == -1);
  BOOST_TEST(p.y1_m == 1);
  BOOST_TEST(!p.wraps);
  BOOST_TEST(p.off == (std::vector<int>{4, 5, 6, 7, 8}), boost::test_tools::per_element());
  BOOST_TEST(stoneskip::pond_extent(field(Boundary::fixed), 1, -1, contacts).off.size() == 5u);
  // A periodic pond tiles the plane: every point is on it.
  const stoneskip::PondExtent wraps = stoneskip::pond_extent(field(Boundary::periodic), 1, -1, contacts);
  BOOST_TEST(wraps.wraps);
  BOOST_TEST(wraps.off.empty());
  BOOST_TEST(stoneskip::off_pond_sentence(wraps, contacts, true).empty());
}

BOOST_AUTO_TEST_CASE(the_sentence_names_each_contact_where_it_began_and_the_push_only_when_two_way) {
  using stoneskip::Boundary;
  const std::vector<stoneskip::ContactRecord> one = {touching(3, 0), touching(12.5, -0.25)};
  const stoneskip::PondExtent p = stoneskip::pond_extent(field(Boundary::reflecting), 1, -1, one);
  BOOST_TEST(stoneskip::off_pond_sentence(p, one, false) ==
             "contact 2 (x = 12.5 m, y = -0.25 m) lies outside the pond, x in [1, 6] m, y in [-1, 1] m: the surface "
             "there is the nearest edge's height");
  BOOST_TEST(stoneskip::off_pond_sentence(p, one, true) ==
             stoneskip::off_pond_sentence(p, one, false) +
                 ", and the water takes none of the push (its impulse does not balance the stone's)");
  const std::vector<stoneskip::ContactRecord> two = {touching(0, 0), touching(7, 0)};
  const stoneskip::PondExtent q = stoneskip::pond_extent(field(Boundary::reflecting), 1, -1, two);
  BOOST_TEST(stoneskip::off_pond_sentence(q, two, false).rfind("contacts 1 (x = 0 m, y = 0 m), 2 (x = 7 m, y = 0 m) lie outside", 0) == 0u);
  const stoneskip::PondExtent none = stoneskip::pond_extent(field(Boundary::reflecting), 1, -1, {touching(2, 0)});
  BOOST_TEST(stoneskip::off_pond_sentence(none, {touching(2, 0)}, true).empty());
}

BOOST_AUTO_TEST_SUITE_END()
