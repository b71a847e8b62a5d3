#pragma once
// What stepping only the active tiles (model/README.md §2.6) costs in accuracy and saves in time: the same
// water run twice in lockstep, once in full and once on active tiles with a given ε, from the same
// start and with the same draught source. Reported: the largest difference over the run, the
// difference at the end, the fraction of tile-steps done, the CPU time of each run's steps, and —
// when the draught does not depend on the field — the a-priori bound K_N · (Σ‖dropped‖ + Σ rounding)
// (model/water/propagator_bound.hpp), which the measured difference must respect: the dropped
// content's free evolution, plus the ulp-level differences that rounding can make once two runs'
// inputs differ at all.
#include <functional>
#include <string>
#include <vector>

#include "model/water/height_field.hpp"

namespace stoneskip {

enum class DraughtSource {
  none,        // free water
  prescribed,  // b(t) given, the same in both runs: the error is exactly the dropped content's evolution
  from_field,  // b computed from each run's own surface (a stone in two-way coupling): no a-priori bound
};

struct TileComparisonOptions {
  HeightFieldOptions field;        // the water; mode is set per run, threads as given
  ActiveTileOptions tiles;         // the tiled run's tile size and ε
  long steps = 1000;
  std::vector<double> initial_m;   // z(0), at rest (empty: flat water)
  DraughtSource source = DraughtSource::none;
  // The draught of the step that starts at t, from that run's field (prescribed sources ignore it).
  std::function<void(double t_s, const HeightField& field, DraughtPatch& out)> draught;
  bool is_valid(std::string* why = nullptr) const;
};

struct TileComparison {
  ActiveTileSummary tiles;           // the tiled run's
  double full_cpu_s = 0;             // thread CPU time of the full run's steps (both runs in this thread
  double tiled_cpu_s = 0;            // when field.threads = 1; with more, the calling thread's share)
  double time_saved = 0;             // 1 − tiled_cpu_s / full_cpu_s
  double max_error_m = 0;            // max over steps and cells of |z_tiled − z_full|
  double final_rms_error_m = 0;      // RMS over cells at the end
  double final_pair_error_m = 0;     // ‖(e_N, e_{N−1})‖₂ over cells at the end
  double max_height_m = 0;           // max over steps and cells of |z_full| (the scale)
  double propagator_bound = 0;       // K_N (prescribed or no draught; 0 otherwise)
  double rounding_sum_m = 0;         // Σ over steps of leapfrog_rounding_bound on the full run's levels
  double error_bound_m = 0;          // K_N · (tiles.dropped_norm_sum_m + rounding_sum_m) (0 when not applicable)
  std::string brief() const;
};

// Throws std::invalid_argument for invalid options.
TileComparison compare_active_tiles(const TileComparisonOptions& options);

}  // namespace stoneskip
