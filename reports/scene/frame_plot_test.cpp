// The pond map's ticks (reports/scene/frame_plot.hpp). Oracle: the map box's geometry by hand. The
// movie's frames are 1280 × 540 px with three panels, the map 0.44 × 0.94 of them less 110 px across
// and 90 px down for the labels: a 453 × 418 px room. A pond 8 m long and 0.3 m wide fills its width:
// 453 × 0.3 / 8 = 17 px high, under one 25 px label, so it gets one y tick step (the pond's width
// rounded up to 1, 2, 5 × 10^k: 0.5) and one colour-bar label (0) where five ran into one another.
// A square pond fills the room's height (418 px): gnuplot's own ticks and all five colour labels.
#include <boost/test/unit_test.hpp>

#include <string>

#include "reports/scene/frame_plot.hpp"

using namespace stoneskip;

namespace {

FramePlot pond(double x_m, double y_m) {
  FramePlot p;
  p.top = "'top.bin' binary";
  p.near = "'near.bin' binary";
  p.side_faces = "'side.dat'";  // the movie's three panels
  p.pond_x0_m = -1;
  p.pond_x1_m = -1 + x_m;
  p.pond_y0_m = -0.5 * y_m;
  p.pond_y1_m = 0.5 * y_m;
  p.scale_m = 0.012;
  return p;
}

bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

BOOST_AUTO_TEST_SUITE(frame_plot)

BOOST_AUTO_TEST_CASE(a_long_narrow_pond_gets_the_ticks_its_strip_has_room_for) {
  const std::string thin = frame_plot_commands(pond(8, 0.3));
  BOOST_TEST(has(thin, "set ytics 0.5\n"), thin);
  BOOST_TEST(has(thin, "set xtics auto\nset ytics 0.5"), thin);  // 453 px across: room for gnuplot's own
  BOOST_TEST(has(thin, "set cbtics ('0' 0)\n"), thin);
  // The 3-D panel after it takes its own ticks again (its window here is the default [0, 1]²:
  // steps of 0.2, no x tick past 0.9 nor y tick below 0.1, next test).
  BOOST_TEST(has(thin, "unset colorbox\nset xtics 0, 0.2, 0.85\nset ytics 0.2, 0.2, 1.05\n"), thin);

  const std::string square = frame_plot_commands(pond(6, 6));
  BOOST_TEST(has(square, "set xtics auto\nset ytics auto\nset xrange"), square);
  BOOST_TEST(has(square, "set cbtics ('-12' -0.012, '-6' -0.006, '0' 0, '6' 0.006, '12' 0.012)\n"), square);

  // 8 m by 1.6 m: 91 px high, room for three labels (1.6 m / 3 rounded up: a 1 m step) and for the
  // colour bar's three (±12 mm and 0), not its five.
  const std::string strip = frame_plot_commands(pond(8, 1.6));
  BOOST_TEST(has(strip, "set ytics 1\n"), strip);
  BOOST_TEST(has(strip, "set cbtics ('-12' -0.012, '0' 0, '12' 0.012)\n"), strip);
  // A pond of micrometre cells (the smallest cell_m allowed, 1e-6 m): its step is printed, not 0.
  FramePlot tiny = pond(8e-5, 3e-6);
  BOOST_TEST(has(frame_plot_commands(tiny), "set ytics 5e-06\n"), frame_plot_commands(tiny));
}

BOOST_AUTO_TEST_CASE(the_3d_view_has_no_x_and_y_label_printed_into_each_other_at_its_corner) {
  // A channel's window, x in [0.3, 0.55] m, y in [-0.15, 0.15] m: gnuplot's own ticks labelled x =
  // 0.55 and y = -0.15 at the corner where the two axes meet, drawn as one "0.550.15". By hand: a
  // fifth of each span rounded up to 1, 2, 5 × 10^k gives steps 0.05 and 0.1; no x tick past
  // 0.55 − 0.025 (the last is 0.5) and no y tick below −0.15 + 0.03 (the first is −0.1); each end
  // is printed a quarter step past the last tick.
  FramePlot p = pond(8, 0.3);
  p.near_x0_m = 0.3;
  p.near_x1_m = 0.55;
  p.near_y0_m = -0.15;
  p.near_y1_m = 0.15;
  const std::string g = frame_plot_commands(p);
  BOOST_TEST(has(g, "set xtics 0.3, 0.05, 0.5125\nset ytics -0.1, 0.1, 0.125\n"), g);
  // The seed's window, x in [-0.8, 1.6], y in [-1.2, 1.2]: steps 0.5, x ticks -0.5 to 1.0 (1.5
  // is within 0.24 of the corner), y ticks -0.5 to 1.0 (-1.0 is within 0.24 of it).
  p.near_x0_m = -0.8;
  p.near_x1_m = 1.6;
  p.near_y0_m = -1.2;
  p.near_y1_m = 1.2;
  const std::string seed = frame_plot_commands(p);
  BOOST_TEST(has(seed, "set xtics -0.5, 0.5, 1.125\nset ytics -0.5, 0.5, 1.125\n"), seed);
}

BOOST_AUTO_TEST_SUITE_END()
