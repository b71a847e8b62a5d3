// How far ahead of c a wall's disturbance runs on the leapfrog (model/README.md §2.4, "On a
// disturbed surface"). A walled pond cut out of a swell sends waves in from its walls at t = 0;
// the scene report's grid section runs only while those waves, at c, cannot reach the stone's
// track. The continuum's waves never outrun c; the scheme's front is dispersed, and shows ahead of
// the cone. Oracle: the same swell on a periodic field 5 times as wide, which has no walls near
// (its surface is the pond's minus the walls' waves, to round-off, until they arrive).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "model/water/height_field.hpp"
#include "model/water/stencil.hpp"

using namespace stoneskip;

namespace {
// The shipped scenes' water: 2 cm cells and the isotropic nine-point stencil, with the seed's c,
// step and damping (cases/scenes/seed_8ms.toml: 0.5 m/s, 1/90 s, σ = 0.278, μ = 0.2 /s) and the
// swell's (cases/scenes/swell_8ms.toml: 1.25 m/s, 5 ms, σ = 0.3125, μ = 0); the swell of
// swell_8ms: 2 cm high, 1 m long, across x.
struct Water {
  const char* name;
  double c_m_s, dt_s, mu_per_s;
};
constexpr Water kWaters[] = {{"seed_8ms", 0.5, 1.0 / 90, 0.2}, {"swell_8ms", 1.25, 5e-3, 0.0}};
constexpr double kCell_m = 0.02, kAmplitude_m = 0.02, kWavelength_m = 1.0;
constexpr int kPondCells = 101, kWideCells = 500, kRows = 4;
constexpr int kPondOffset = 18;  // the pond's first cell is the wide field's 18th: walls at 0.35 and 2.37 m, off the crests

HeightFieldOptions field(const Water& w, int nx, Boundary boundary) {
  HeightFieldOptions o;
  o.nx = nx;
  o.ny = kRows;  // the swell is uniform in y: a few rows are the whole story
  o.cell_m = kCell_m;
  o.wave_speed_m_s = w.c_m_s;
  o.damping_per_s = w.mu_per_s;
  o.dt_s = w.dt_s;
  o.stencil = named_stencil("nine_point_isotropic");
  o.boundary = boundary;
  return o;
}

std::vector<double> swell(int nx, int first_cell) {
  std::vector<double> z(static_cast<std::size_t>(nx) * kRows);
  for (int j = 0; j < kRows; ++j)
    for (int i = 0; i < nx; ++i)
      z[static_cast<std::size_t>(j) * nx + i] =
          kAmplitude_m * std::cos(2 * std::numbers::pi * (first_cell + i) * kCell_m / kWavelength_m);
  return z;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(wall_precursor)

BOOST_AUTO_TEST_CASE(a_walls_waves_are_below_a_millionth_at_half_the_cone_and_above_a_thousandth_at_it) {
  for (const Water& water : kWaters) {
    BOOST_TEST_CONTEXT(water.name) {
      HeightField wide(field(water, kWideCells, Boundary::periodic)), pond(field(water, kPondCells, Boundary::reflecting));
      wide.set_state(swell(kWideCells, 0));
      pond.set_state(swell(kPondCells, kPondOffset));
      // Points 10 to 50 cells from the nearest wall (half a cell outside the edge cell, §2.3).
      const std::vector<int> points{10, 20, 30, 50};
      std::vector<double> before_half(points.size(), 0.0), by_cone(points.size(), 0.0);
      const double end_s = 1.1 * (50.5 * kCell_m) / water.c_m_s;
      for (long n = 1; n * water.dt_s <= end_s; ++n) {
        wide.step();
        pond.step();
        const double t = n * water.dt_s;
        for (std::size_t p = 0; p < points.size(); ++p) {
          const double cone_s = (points[p] + 0.5) * kCell_m / water.c_m_s;
          const double gap = std::abs(pond.height(points[p], 1) - wide.height(kPondOffset + points[p], 1)) / kAmplitude_m;
          if (t <= 0.5 * cone_s) before_half[p] = std::max(before_half[p], gap);
          if (t <= cone_s) by_cone[p] = std::max(by_cone[p], gap);
        }
      }
      for (std::size_t p = 0; p < points.size(); ++p) {
        BOOST_TEST_MESSAGE(water.name << ", " << points[p] << " cells from the wall: the walls' waves reach "
                                      << before_half[p] << " of the swell's height by half the cone's time, " << by_cone[p]
                                      << " by the cone's");
        // Below a millionth of the surface's height: the scene section's bound at c leaves nothing there.
        BOOST_TEST(before_half[p] <= 1e-6);
        // A thousandth or more by the time c itself arrives: the front runs ahead of the cone, so the
        // bound at c is a soft one, and the walls' waves are not lost in round-off (the check can fail).
        BOOST_TEST(by_cone[p] >= 1e-3);
      }
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
