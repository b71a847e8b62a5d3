#pragma once
// A wave case file (TOML, documented in cases/README.md, section "Wave cases") resolved into the
// height field's options, the initial disturbance and the end time: [water], [initial], and
// optionally [case], [stencil] (custom weights, with water.stencil = "custom") and [reference].
// Every error is a one-line InputError naming the file and the line or key.
#include <cmath>
#include <string>
#include <vector>

#include "model/water/disturbance.hpp"
#include "model/water/height_field.hpp"
#include "tools/io/toml_table.hpp"

namespace stoneskip {

// Plausibility bounds of the water keys (documented per key in cases/README.md).
struct WaterBounds {
  double lo, hi;
};
constexpr long long kMinCells = 4, kMaxCells = 16384;     // nx, ny
constexpr WaterBounds kCellSize_m{1e-6, 1e3};             // cell_m
constexpr WaterBounds kWaveSpeed_m_s{1e-6, 1e4};          // wave_speed_m_s
constexpr double kMaxDamping_per_s = 1e6;                 // damping_per_s in [0, this]
constexpr WaterBounds kWaterStep_s{1e-12, 1e3};           // dt_s (and the least t_end_s)
constexpr double kMaxWaterDuration_s = 1e6;               // t_end_s
constexpr double kMaxWaveSteps = 1e8;                     // t_end_s / dt_s
constexpr double kMaxStencilWeight = 1e6;                 // |centre|, |orth|, |diag| of [stencil]
constexpr double kMaxAmplitude_m = 1e3;                   // |amplitude_m|
constexpr WaterBounds kDisturbanceLength_m{1e-9, 1e6};    // width_m, wavelength_m; |x_m|, |y_m|, radius_m <= hi

struct WaveCase {
  std::string file;
  std::string text;
  std::vector<std::string> overrides;
  std::string title;
  HeightFieldOptions water;
  double t_end_s = 0;
  Disturbance initial;
  bool reference_semi_discrete = false;  // [reference] symbol = "stencil": compare with the
                                         // stencil's exact semi-discrete solution (time error only)
  long steps() const;                    // ⌈t_end/Δt⌉ (the run ends at steps·Δt)
  std::string resolved_settings() const; // every setting as TOML, after defaults and overrides
};

// The pieces, shared with stone cases that put the stone on a live water surface:
// [water] (t_end_s read only when t_end_s != nullptr; [stencil] from `top` for custom weights)
// and a disturbance table ([initial] here, [water.initial] in a stone case).
HeightFieldOptions read_height_field(TomlTable t, TomlTable& top, double* t_end_s);
Disturbance read_disturbance(TomlTable t);

// Whether the free water is stable at its σ = cΔt/d: the exact von Neumann limit of its stencil
// (model/water/stencil.hpp: leapfrog_courant_limit, the same for every μΔt ≥ 0), said the same way
// by `wave` and by a scene's check of its water.
struct WaterStability {
  std::string stencil;
  double sigma = 0, mu_dt = 0;
  double limit = 0;  // the plane's von Neumann limit; +∞: unbounded (the stencil couples no cells); 0: no stable step
  // The same over the grid's own modes (leapfrog_courant_limit with its wavenumbers), which decides:
  // ≥ limit, above it on a grid that holds no mode at the zone's corner (odd periodic, reflecting,
  // fixed). A 5 × 5 periodic grid at σ = 0.74 is stable (its limit 0.7435), though above 1/√2.
  double grid_limit = 0;
  std::string grid;  // "5 × 5 periodic"
  bool stable() const { return sigma <= grid_limit; }
  bool unbounded() const { return std::isinf(limit); }
  bool no_stable_step() const { return limit == 0; }
  std::string limit_kind() const;  // "bounded", "unbounded" or "none"
  // "stable up to 0.7071", "stable at every sigma: the stencil couples no cells", or "no stable
  // step: a mode of the stencil grows at every sigma > 0".
  std::string limit_text() const;
  // "sigma = 0.7168 exceeds the von Neumann limit 0.7071 of five_point (at every mu dt)", or that
  // it is within it, or that the stencil has no stable step.
  std::string reason() const;
};
WaterStability water_stability(const HeightFieldOptions& water);

WaveCase load_wave_case(const std::string& path, const std::vector<std::string>& overrides = {});
WaveCase wave_case_from_document(const TomlDocument& doc);

}  // namespace stoneskip
