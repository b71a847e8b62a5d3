// The grid section's pond (scene_findings_support.hpp): a case's initial surface sampled afresh on
// the pond's grid, and where the pond's walls stand against the first contact.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "solvers/scene/seed_throw_scene.hpp"
#include "verification/scene/scene_findings_support.hpp"

using namespace stoneskip;
using namespace stoneskip::scene_findings;

namespace {

// A walled case of 400 × 300 cells of 2.5 cm at (−1, −3) m, starting from `d` sampled on its grid.
SceneStudyCase walled_case(const Disturbance& d) {
  SceneStudyCase c;
  c.name = "hump";
  c.scene.stone.disk_radius_m = 0.03;
  SceneWater w;
  w.field.nx = 400;
  w.field.ny = 300;
  w.field.cell_m = 0.025;
  w.field.dt_s = 0.01;
  w.field.wave_speed_m_s = 1.25;
  w.field.boundary = Boundary::reflecting;
  w.placement = FieldPlacement{-1.0, -3.0};
  sample_disturbance(d, w.field.nx, w.field.ny, w.field.cell_m, w.initial_m);
  c.scene.water = w;
  c.initial = d;
  return c;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(grid_section_pond)

BOOST_AUTO_TEST_CASE(the_pond_samples_the_cases_surface_at_the_same_places) {
  // Oracle 1: where a pond cell lands on a case cell (the pond's origin a whole number of case
  // cells from the case's, the same cell), its height is the case's height there; up to the
  // round-off of the origins' difference (1e-12 of the peak). Oracle 2: the Gaussian
  // A exp(−r²/w²) at the pond's points in the throw's frame, a finer pond at an offset of no whole
  // cell, the bump far from every edge of the case's grid (its images below e^-42): 1e-12 of the peak.
  Disturbance d;
  d.kind = DisturbanceKind::gaussian;
  d.amplitude_m = 0.02;
  d.width_m = 0.3;
  d.x_m = 4.0;  // the case's frame: at (3, 0.75) m in the throw's
  d.y_m = 3.75;
  const SceneStudyCase c = walled_case(d);
  const double pond = 2.0, cell = 0.025;
  // Pond origin = first touch − (¼, ½) pond: 92 and 110 case cells from the case's.
  const Vec3 touch(-1.0 + 92 * cell + 0.25 * pond, -3.0 + 110 * cell + 0.5 * pond, 0.0);
  SceneOptions s = c.scene;
  place_on_pond(s, c, touch, pond, cell, 0.01);
  const int n = s.water->field.nx;
  BOOST_TEST_REQUIRE(n == 81);
  BOOST_TEST_REQUIRE(s.water->initial_m.size() == std::size_t(n) * n);
  double gap = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      gap = std::max(gap, std::abs(s.water->initial_m[std::size_t(j) * n + i] - c.scene.water->initial_m[std::size_t(j + 110) * 400 + i + 92]));
  BOOST_TEST(gap / d.amplitude_m < 1e-12);
  // A finer pond, around a touch at no whole cell.
  const Vec3 near(2.713, 0.4187, 0.0);
  SceneOptions f = c.scene;
  const double fine = 0.0071;
  place_on_pond(f, c, near, pond, fine, 0.003);
  const int m = f.water->field.nx;
  const double ox = near.x() - 0.25 * pond, oy = near.y() - 0.5 * pond;
  BOOST_TEST(f.water->placement.origin_x_m == ox);
  double worst = 0, peak = 0;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const double x = ox + i * fine - 3.0, y = oy + j * fine - 0.75;  // from the bump's centre
      const double exact = d.amplitude_m * std::exp(-(x * x + y * y) / (d.width_m * d.width_m));
      worst = std::max(worst, std::abs(f.water->initial_m[std::size_t(j) * m + i] - exact));
      peak = std::max(peak, exact);
    }
  BOOST_TEST(peak > 0.99 * d.amplitude_m);  // the bump lies on the pond
  BOOST_TEST(worst / d.amplitude_m < 1e-12);
}

BOOST_AUTO_TEST_CASE(a_still_case_gets_still_water_on_every_pond) {
  // Oracle: a case whose [water.initial] has amplitude 0 holds heights of 0 on its own grid; the
  // pond, another grid, must not keep them (a vector of the wrong size stops the scene).
  Disturbance d;
  d.amplitude_m = 0;
  SceneStudyCase c = walled_case(d);
  c.initial.reset();
  SceneOptions s = c.scene;
  place_on_pond(s, c, Vec3(1, 0, 0), 2.0, 0.05, 0.01);
  BOOST_TEST(s.water->initial_m.empty());
  BOOST_TEST(!starts_disturbed(c));
}

BOOST_AUTO_TEST_CASE(the_walls_stand_where_the_pond_puts_them) {
  // Oracle: by hand. Touch (1, 0.5) m, pond 2 m of 0.02 m cells: 101 points from (0.5, −0.5) to
  // (2.5, 1.5) m. The track runs from (0.97, 0.5) to (1.17, 0.51) m; less the disk's 0.03 m the
  // nearest wall is the one behind, 0.97 − 0.5 − 0.03 = 0.44 m away, 0.44 / 1.25 = 0.352 s at c.
  Disturbance d;
  d.kind = DisturbanceKind::plane_wave;
  const SceneStudyCase c = walled_case(d);
  ContactRecord k;
  k.first_touch_m = Vec3(1.0, 0.5, 0.0);
  k.entry_position_m = Vec3(0.97, 0.5, 0.01);
  k.exit_position_m = Vec3(1.17, 0.51, 0.01);
  const PondWalls w = pond_walls(c, k, 2.0, 0.02);
  BOOST_TEST(w.nearest_m == 0.44, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(w.reach_s == 0.352, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(w.inside_case);  // the case's field covers x ∈ [−1, 8.975], y ∈ [−3, 4.475] m
  // A touch near the case's far corner: the pond reaches past its walls.
  k.first_touch_m = Vec3(8.5, 4.0, 0.0);
  BOOST_TEST(!pond_walls(c, k, 2.0, 0.02).inside_case);
  // A grid's own first contact on the pond placed at the still-water touch (1, 0.5) m: planing on
  // to (2.2, 0.6) m, it comes within 2.5 − 2.2 − 0.03 = 0.27 m of the wall ahead, 0.216 s at c; past
  // x = 2.53 m its disk leaves the pond.
  ContactRecord own;
  own.entry_position_m = Vec3(0.97, 0.5, 0.01);
  own.exit_position_m = Vec3(2.2, 0.6, 0.01);
  const PondWalls ahead = pond_walls(c, Vec3(1.0, 0.5, 0.0), own, 2.0, 0.02);
  BOOST_TEST(ahead.nearest_m == 0.27, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(ahead.reach_s == 0.216, boost::test_tools::tolerance(1e-12));
  own.exit_position_m = Vec3(2.6, 0.6, 0.01);
  BOOST_TEST(pond_walls(c, Vec3(1.0, 0.5, 0.0), own, 2.0, 0.02).nearest_m < 0);
}

BOOST_AUTO_TEST_CASE(a_pond_whose_walls_reach_the_contact_in_time_is_not_run) {
  // Oracle: the domain of dependence, with pond_walls' distances (checked by hand above). The seed's
  // throw onto a 1 m swell, c = 0.5 m/s; the section ends 5 contact durations and 0.05 s after the
  // first contact's start on still water (end_s, above 0.15 s: that start is about 55 ms and a
  // contact of this throw lasts over 10 ms). A 0.3 m pond's wall behind the touch stands 7.5 cm
  // from the touching corner; the centre lies at most R = 3 cm ahead of it, and the disk reaches R
  // back from the centre: that wall is at most 7.5 cm from the track, 0.15 s at c, before the end.
  // No grid is run, and the reason names the key to widen. On a 0.2 m pond the track itself
  // leaves the pond: refused for that, on any case.
  SceneStudiesOptions o;
  SceneStudyCase c;
  c.name = "swell";
  c.scene = seed_throw_scene(150, 150, -1.1, -1.5, 0.6);
  Disturbance d;
  d.kind = DisturbanceKind::plane_wave;
  d.amplitude_m = 0.005;
  d.wavelength_m = 1.0;
  sample_disturbance(d, 150, 150, c.scene.water->field.cell_m, c.scene.water->initial_m);
  c.initial = d;
  o.cases.push_back(c);
  o.grid.pond_m = 0.3;
  std::string why;
  BOOST_TEST_REQUIRE(o.valid(&why), why);
  const Record r = scene_grid_findings(o, {});
  BOOST_TEST(r.table("grids").rows() == 0u);
  BOOST_TEST(r.number("wall_distance_m") > 0);  // the track lies on the pond
  BOOST_TEST(r.number("walls_reach_s") <= 0.075 / 0.5 + 1e-12);
  BOOST_TEST(r.number("end_s") > 0.15);
  std::string reason = r.at("verdict").text("reason");
  BOOST_TEST(reason.find("waves they send") != std::string::npos, reason);
  BOOST_TEST(reason.find("widen grid.pond_m") != std::string::npos, reason);
  BOOST_TEST(r.text("initial_surface").find("plane wave") != std::string::npos);
  o.grid.pond_m = 0.2;
  const Record small = scene_grid_findings(o, {});
  BOOST_TEST(small.table("grids").rows() == 0u);
  BOOST_TEST(small.number("wall_distance_m") < 0);
  reason = small.at("verdict").text("reason");
  BOOST_TEST(reason.find("reaches") != std::string::npos, reason);
  BOOST_TEST(reason.find("past the walls") != std::string::npos, reason);
  // The same walls far away: a 4 m pond's nearest wall is 1 m behind the touch, 2 s at c.
  ContactRecord k;
  k.first_touch_m = Vec3(0.4, 0.0, 0.0);
  k.entry_position_m = k.exit_position_m = k.first_touch_m;
  BOOST_TEST(pond_walls(c, k, 4.0, 0.02).reach_s == (1.0 - 0.03) / 0.5, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(a_pond_too_large_for_the_section_runs_nothing_and_says_so) {
  // Oracle: the section's size bound (2048² cells). A 50 m pond of the seed's 2 cm cells is 2501²:
  // every grid of the sequence and the water-step part are left out, by name, instead of running
  // for minutes a run (a 100 m pond's water-step part took 217 s a run, 14 runs, 7 December).
  SceneStudiesOptions o;
  SceneStudyCase c;
  c.name = "seed";
  c.scene = seed_throw_scene(150, 150, -1.1, -1.5, 0.6);
  o.cases.push_back(c);
  o.grid.pond_m = 50;
  o.grid.head_widths_m.clear();
  const Record r = scene_grid_findings(o, {});
  BOOST_TEST(r.table("grids").rows() == 0u);
  BOOST_TEST(r.number("left_out") == double(o.grid.cell_fractions.size()));
  BOOST_TEST(!r.has_child("water_step"));
  BOOST_TEST(r.text("water_step_left_out").find("2501² cells") != std::string::npos, r.text("water_step_left_out"));
}

BOOST_AUTO_TEST_SUITE_END()
