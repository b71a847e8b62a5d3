#include "verification/waves/active_tiles_study.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "model/water/propagator_bound.hpp"
#include "solvers/realtime/clocks.hpp"

namespace stoneskip {

bool TileComparisonOptions::is_valid(std::string* why) const {
  auto fail = [&](const std::string& what) {
    if (why) *why = what;
    return false;
  };
  std::string field_why;
  if (!field.is_valid(&field_why)) return fail(field_why);
  if (tiles.tile_cells < 1 || !(tiles.epsilon_m >= 0)) return fail("tile comparison: tiles need tile_cells >= 1, epsilon_m >= 0");
  if (steps < 1) return fail("tile comparison: steps must be >= 1");
  if (!initial_m.empty() && initial_m.size() != static_cast<std::size_t>(field.nx) * field.ny)
    return fail("tile comparison: initial_m must have nx·ny values");
  if (source != DraughtSource::none && !draught) return fail("tile comparison: a draught source needs a draught function");
  return true;
}

std::string TileComparison::brief() const {
  char buf[400];
  const int len = std::snprintf(buf, sizeof buf, "%s; time saved %.0f %% (CPU %.3g s vs %.3g s); max error %.3g m of %.3g m",
                                tiles.brief().c_str(), 100 * time_saved, tiled_cpu_s, full_cpu_s, max_error_m, max_height_m);
  if (error_bound_m > 0 && len > 0 && len < static_cast<int>(sizeof buf))
    std::snprintf(buf + len, sizeof buf - len, "; end pair error %.3g m %s bound %.3g m", final_pair_error_m,
                  final_pair_error_m <= error_bound_m ? "≤" : "EXCEEDS", error_bound_m);
  return buf;
}

TileComparison compare_active_tiles(const TileComparisonOptions& o) {
  std::string why;
  if (!o.is_valid(&why)) throw std::invalid_argument(why);
  HeightFieldOptions of = o.field, ot = o.field;
  of.mode = StepMode::full;
  ot.mode = StepMode::active_tiles;
  ot.tiles = o.tiles;
  HeightField full(of), tiled(ot);
  const std::size_t n = static_cast<std::size_t>(of.nx) * of.ny;
  const std::vector<double> z0 = o.initial_m.empty() ? std::vector<double>(n, 0.0) : o.initial_m;
  full.set_state(z0);
  tiled.set_state(z0);
  TileComparison r;
  DraughtPatch bf, bt;
  auto run_step = [&](HeightField& f, DraughtPatch& b, double& cpu) {
    if (o.source != DraughtSource::none) o.draught(f.time_s(), f, b);
    CpuTimer timer;
    if (o.source == DraughtSource::none)
      f.step();
    else
      f.step(b);
    cpu += timer.seconds();
  };
  const double mu_dt = of.damping_per_s * of.dt_s;
  const double unit_roundoff = of.precision == Precision::float64 ? 0x1p-53 : 0x1p-24;
  for (long s = 0; s < o.steps; ++s) {
    double z_sq = 0, zm_sq = 0;
    for (int j = 0; j < of.ny; ++j)
      for (int i = 0; i < of.nx; ++i) {
        z_sq += full.height(i, j) * full.height(i, j);
        zm_sq += full.previous_height(i, j) * full.previous_height(i, j);
      }
    r.rounding_sum_m += leapfrog_rounding_bound(of.stencil, of.courant(), mu_dt, std::sqrt(z_sq), std::sqrt(zm_sq), unit_roundoff);
    run_step(full, bf, r.full_cpu_s);
    run_step(tiled, bt, r.tiled_cpu_s);
    for (int j = 0; j < of.ny; ++j)
      for (int i = 0; i < of.nx; ++i) {
        const double zf = full.height(i, j);
        r.max_height_m = std::max(r.max_height_m, std::abs(zf));
        r.max_error_m = std::max(r.max_error_m, std::abs(tiled.height(i, j) - zf));
      }
  }
  double sq = 0, pair = 0;
  for (int j = 0; j < of.ny; ++j)
    for (int i = 0; i < of.nx; ++i) {
      const double e0 = tiled.height(i, j) - full.height(i, j), e1 = tiled.previous_height(i, j) - full.previous_height(i, j);
      sq += e0 * e0;
      pair += e0 * e0 + e1 * e1;
    }
  r.final_rms_error_m = std::sqrt(sq / static_cast<double>(n));
  r.final_pair_error_m = std::sqrt(pair);
  r.tiles = tiled.tile_summary();
  r.time_saved = r.full_cpu_s > 0 ? 1 - r.tiled_cpu_s / r.full_cpu_s : 0;
  if (o.source != DraughtSource::from_field) {
    r.propagator_bound =
        leapfrog_propagator_bound(of.stencil, of.courant(), of.damping_per_s * of.dt_s, of.nx, of.ny, o.steps);
    r.error_bound_m = r.propagator_bound * (r.tiles.dropped_norm_sum_m + r.rounding_sum_m);
  }
  return r;
}

}  // namespace stoneskip
