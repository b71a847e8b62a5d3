#include "verification/waves/active_tiles_study.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>

#include "model/water/disturbance.hpp"

namespace stoneskip {
namespace {

// A 128 × 96 reflecting pond, a ring from a compact bump in one corner and a disk of draught held
// in another for the first 0.4 s (100 steps); waves cross about 60 cells in 240 steps at σ = 0.25.
TileComparisonOptions pond(double eps) {
  TileComparisonOptions o;
  o.field.nx = 128;
  o.field.ny = 96;
  o.field.cell_m = 0.02;
  o.field.wave_speed_m_s = 0.5;
  o.field.damping_per_s = 0.8;
  o.field.dt_s = 0.25 * o.field.cell_m / o.field.wave_speed_m_s;
  o.field.stencil = named_stencil("five_point");
  o.field.boundary = Boundary::reflecting;
  o.tiles.tile_cells = 16;
  o.tiles.epsilon_m = eps;
  o.steps = 240;
  Disturbance d;
  d.amplitude_m = 0.005;
  d.width_m = 0.06;
  d.x_m = 0.4;
  d.y_m = 0.4;
  sample_disturbance(d, o.field.nx, o.field.ny, o.field.cell_m, o.initial_m);
  for (double& z : o.initial_m)
    if (std::abs(z) < 1e-15) z = 0;
  o.source = DraughtSource::prescribed;
  o.draught = [](double t_s, const HeightField&, DraughtPatch& b) {
    if (t_s > 0.4) {
      b.clear();
      return;
    }
    b.reset(90, 60, 7, 7);
    for (int c = 0; c < 7; ++c)
      for (int a = 0; a < 7; ++a) b.at(a, c) = (a - 3) * (a - 3) + (c - 3) * (c - 3) <= 9 ? 0.004 : 0.0;
  };
  return o;
}

BOOST_AUTO_TEST_SUITE(active_tiles_study_)

BOOST_AUTO_TEST_CASE(exact_tiles_show_no_error_and_skip_work) {
  // Oracle: model/README.md §2.6 — ε = 0 is the full field to the bit (max error exactly 0), and tiles the
  // waves have not reached are skipped (fraction < 1).
  const TileComparison r = compare_active_tiles(pond(0));
  BOOST_TEST(r.max_error_m == 0);
  BOOST_TEST(r.tiles.fraction() < 1, r.brief());
  BOOST_TEST(r.tiles.dropped_norm_sum_m == 0);
}

BOOST_AUTO_TEST_CASE(tiles_with_a_threshold_stay_within_the_bound_of_what_they_dropped) {
  // Oracle: the difference from the full field is the free evolution of what was dropped, so
  // ‖(e_N, e_{N−1})‖₂ ≤ K_N Σ‖dropped‖₂ (propagator bound); the threshold must also save tile-steps
  // against ε = 0.
  const double eps = 2e-5;  // 0.4 % of the bump's height
  const TileComparison exact = compare_active_tiles(pond(0));
  const TileComparison r = compare_active_tiles(pond(eps));
  BOOST_TEST(r.max_error_m > 0);
  BOOST_TEST(r.final_pair_error_m <= r.error_bound_m, r.brief());
  BOOST_TEST(r.tiles.fraction() < exact.tiles.fraction(), r.brief() << " vs " << exact.brief());
  BOOST_TEST_MESSAGE("ε = 0: " << exact.brief() << "\nε = " << eps << ": " << r.brief());
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
