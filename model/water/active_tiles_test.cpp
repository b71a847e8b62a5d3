#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstring>

#include "model/water/disturbance.hpp"
#include "model/water/height_field.hpp"
#include "model/water/propagator_bound.hpp"

namespace stoneskip {
namespace {

// A prescribed draught: a paraboloid of depth 3 cm and radius 4 cells whose centre moves at
// constant speed along a line that crosses the domain's edges (wraps on a periodic field, leaves
// through the wall on others). Not computed from the field, so a full and a tiled run are forced
// identically and their difference is the tiles' doing alone.
void moving_draught(const HeightFieldOptions& o, long step, DraughtPatch& p) {
  const double r_cells = 4, cx = 10 + 0.21 * step, cy = 30 - 0.13 * step;
  const int i0 = static_cast<int>(std::ceil(cx - r_cells)), j0 = static_cast<int>(std::ceil(cy - r_cells));
  p.reset(i0, j0, 9, 9);
  for (int c = 0; c < 9; ++c)
    for (int a = 0; a < 9; ++a) {
      const double dx = i0 + a - cx, dy = j0 + c - cy, q = 1 - (dx * dx + dy * dy) / (r_cells * r_cells);
      p.at(a, c) = q > 0 ? 0.03 * q : 0;
    }
  if (o.boundary == Boundary::periodic) {  // keep the box's origin on the grid
    p.i0 = ((p.i0 % o.nx) + o.nx) % o.nx;
    p.j0 = ((p.j0 % o.ny) + o.ny) % o.ny;
  }
}

HeightFieldOptions tiled_field(Boundary b, StepMode mode, double eps, int threads = 1) {
  HeightFieldOptions o;
  o.nx = 96;
  o.ny = 64;
  o.cell_m = 1.0 / 64;
  o.wave_speed_m_s = 1;
  o.damping_per_s = 1;
  o.dt_s = 0.25 * o.cell_m;  // waves cross 90 cells in 360 steps: the far side stays quiet a while
  o.stencil = named_stencil("nine_point_isotropic");
  o.boundary = b;
  o.mode = mode;
  o.tiles.tile_cells = 8;
  o.tiles.epsilon_m = eps;
  o.threads = threads;
  return o;
}

std::vector<double> local_bump(const HeightFieldOptions& o) {
  Disturbance d;
  d.amplitude_m = 0.01;
  d.width_m = 0.03;
  d.x_m = 0.7;
  d.y_m = 0.25;
  std::vector<double> z;
  sample_disturbance(d, o.nx, o.ny, o.cell_m, z);
  for (double& v : z)
    if (std::abs(v) < 1e-12) v = 0;  // a compact start, so that most tiles begin quiet
  return z;
}

// ‖(z_n, z_{n−1})‖₂ over the cells of the difference of two fields.
double pair_difference_norm(const HeightField& a, const HeightField& b) {
  double s = 0;
  for (int j = 0; j < a.ny(); ++j)
    for (int i = 0; i < a.nx(); ++i) {
      const double d0 = a.height(i, j) - b.height(i, j), d1 = a.previous_height(i, j) - b.previous_height(i, j);
      s += d0 * d0 + d1 * d1;
    }
  return std::sqrt(s);
}

BOOST_AUTO_TEST_SUITE(active_tiles_)

BOOST_AUTO_TEST_CASE(exact_tiles_equal_the_full_field_at_every_step_with_a_moving_draught) {
  // Oracle: model/README.md §2.6 — with ε = 0 a tile is skipped only when it and its neighbours hold exact
  // zeros, whose update is zero, so every value must be == the full field's, at every step of a
  // 700-step run with a draught crossing the domain, periodic and reflecting, on 1 and 2 threads.
  for (auto b : {Boundary::periodic, Boundary::reflecting})
    for (int threads : {1, 2}) {
      const auto of = tiled_field(b, StepMode::full, 0), ot = tiled_field(b, StepMode::active_tiles, 0, threads);
      HeightField full(of), tiled(ot);
      full.set_state(local_bump(of));
      tiled.set_state(local_bump(ot));
      DraughtPatch p;
      long mismatches = 0;
      for (long s = 0; s < 700; ++s) {
        moving_draught(of, s, p);
        full.step(p);
        tiled.step(p);
        for (int j = 0; j < of.ny; ++j)
          for (int i = 0; i < of.nx; ++i)
            if (!(full.height(i, j) == tiled.height(i, j))) ++mismatches;
      }
      BOOST_TEST(mismatches == 0, to_string(b) << ", " << threads << " threads");
      // The test is not vacuous: tiles were skipped while the waves spread.
      BOOST_TEST(tiled.tile_summary().fraction() < 1, tiled.tile_summary().brief());
      BOOST_TEST(tiled.tile_summary().drops + tiled.tile_summary().border_drops == 0);
      BOOST_TEST(tiled.tile_summary().dropped_norm_sum_m == 0);
    }
}

BOOST_AUTO_TEST_CASE(dropped_tiles_bound_the_error_through_the_free_propagator) {
  // Oracle: the scheme is linear and both runs get the same draught, so full − tiled is the free
  // evolution of what the tiles dropped (plus rounding differences once the runs differ at all):
  // ‖(e_n, e_{n−1})‖₂ ≤ K_n Σ_{k≤n} (‖drop_k‖₂ + ρ_k), K_n from leapfrog_propagator_bound (exact
  // per-mode powers), ρ_k from leapfrog_rounding_bound on the full run's levels. Checked at several times of a run with ε = 1e-5 m
  // (1e-3 of the start's amplitude), where drops and a nonzero error must occur.
  for (auto b : {Boundary::periodic, Boundary::reflecting}) {
    const auto of = tiled_field(b, StepMode::full, 0), ot = tiled_field(b, StepMode::active_tiles, 1e-4);
    HeightField full(of), tiled(ot);
    full.set_state(local_bump(of));
    tiled.set_state(local_bump(ot));
    DraughtPatch p;
    const long steps = 360;
    const double k_n = leapfrog_propagator_bound(of.stencil, of.courant(), of.damping_per_s * of.dt_s, of.nx, of.ny, steps);
    double error = 0, rounding = 0;
    for (long s = 0; s < steps; ++s) {
      double zs = 0, zms = 0;
      for (int j = 0; j < of.ny; ++j)
        for (int i = 0; i < of.nx; ++i) {
          zs += full.height(i, j) * full.height(i, j);
          zms += full.previous_height(i, j) * full.previous_height(i, j);
        }
      rounding += leapfrog_rounding_bound(of.stencil, of.courant(), of.damping_per_s * of.dt_s, std::sqrt(zs), std::sqrt(zms), 0x1p-53);
      moving_draught(of, s, p);
      full.step(p);
      tiled.step(p);
      if ((s + 1) % 40 == 0) {
        error = pair_difference_norm(full, tiled);
        const double bound = k_n * (tiled.tile_summary().dropped_norm_sum_m + rounding);
        BOOST_TEST(error <= bound, to_string(b) << " step " << s + 1 << ": error " << error << " > bound " << bound);
      }
    }
    const auto& sum = tiled.tile_summary();
    BOOST_TEST(sum.drops + sum.border_drops > 0, sum.brief());
    BOOST_TEST(error > 0);
    BOOST_TEST(sum.dropped_max_m <= 2e-5);  // |z| ≤ ε and |z − z⁻| ≤ ε ⇒ |z⁻| ≤ 2ε
    BOOST_TEST_MESSAGE(to_string(b) << ": K = " << k_n << ", " << sum.brief() << ", final error " << error
                                    << ", rounding allowance " << rounding);
  }
}

BOOST_AUTO_TEST_CASE(propagator_bound_holds_the_mean_modes_closed_form) {
  // Oracle: undamped, the mean mode (s = 0) has M = [[2, −1], [1, 0]] and Mᴺ = [[N + 1, −N],
  // [N, 1 − N]] exactly, whose 2-norm grows like 2N: K_N must be at least that. Damped, the mean
  // mode's momentum decays and K saturates: K_2000 = K_1000 to 1e-9.
  const Stencil st = named_stencil("five_point");
  const long n = 300;
  const double a = n + 1, b = -static_cast<double>(n), c = n, d = 1.0 - n;
  const double fro = a * a + b * b + c * c + d * d, det = a * d - b * c;
  const double mean_norm = std::sqrt(0.5 * (fro + std::sqrt(fro * fro - 4 * det * det)));
  BOOST_TEST(leapfrog_propagator_bound(st, 0.5, 0.0, 8, 8, n) >= mean_norm * (1 - 1e-12));
  const double k1 = leapfrog_propagator_bound(st, 0.5, 0.05, 8, 8, 1000), k2 = leapfrog_propagator_bound(st, 0.5, 0.05, 8, 8, 2000);
  BOOST_TEST(std::abs(k2 - k1) <= 1e-9 * k1);
  BOOST_TEST(k1 <= 2 / 0.05 + 2);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
