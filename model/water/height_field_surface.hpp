#pragma once
// A height field seen as the water surface a stone is clipped against (model/stone/water_surface.hpp):
// η(x, y) bilinear between cell points, with the field's origin placed at (origin_x_m, origin_y_m)
// of the scene. The field is held by reference and must outlive the adapter.
//
// The field holds levels at its own steps t_n = n Δt; the stone reads it at its own clock t, set
// by set_time (model/README.md §2.4, "The level between water steps"):
//   held          η(t) = zⁿ, the last level taken, held until the next (the real-time loop's way):
//                 an error of (t − t_n) ∂z/∂t, first order in Δt;
//   extrapolated  η(t) = zⁿ + θ (zⁿ − zⁿ⁻¹), θ = (t − t_n)/Δt, the line through the last two
//                 levels: an error of θ(1 + θ) Δt² ∂²z/∂t² / 2, second order, and causal (the
//                 stone never reads a level the water has not computed).
#include "model/stone/water_surface.hpp"
#include "model/water/height_field.hpp"

namespace stoneskip {

enum class LevelInTime { held, extrapolated };

class HeightFieldSurface : public WaterSurface {
 public:
  HeightFieldSurface(const HeightField& field, double origin_x_m = 0, double origin_y_m = 0,
                     LevelInTime in_time = LevelInTime::held)
      : field_(field), origin_x_m_(origin_x_m), origin_y_m_(origin_y_m), in_time_(in_time) {}
  // The stone's clock: what extrapolated reads at (held ignores it).
  void set_time(double t_s) { t_s_ = t_s; }
  double height_m(double x_m, double y_m) const override {
    const double x = x_m - origin_x_m_, y = y_m - origin_y_m_;
    if (in_time_ == LevelInTime::held) return field_.interpolate(x, y);
    const auto [z, z_previous] = field_.interpolate_both_levels(x, y);
    const double theta = (t_s_ - field_.time_s()) / field_.options().dt_s;
    return z + theta * (z - z_previous);
  }

 private:
  const HeightField& field_;
  double origin_x_m_, origin_y_m_;
  LevelInTime in_time_;
  double t_s_ = 0;
};

}  // namespace stoneskip
