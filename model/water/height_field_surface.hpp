#pragma once
// A height field seen as the water surface a stone is clipped against (model/stone/water_surface.hpp):
// η(x, y) bilinear between cell points, with the field's origin placed at (origin_x_m, origin_y_m)
// of the scene. The field is held by reference and must outlive the adapter.
#include "model/stone/water_surface.hpp"
#include "model/water/height_field.hpp"

namespace stoneskip {

class HeightFieldSurface : public WaterSurface {
 public:
  HeightFieldSurface(const HeightField& field, double origin_x_m = 0, double origin_y_m = 0)
      : field_(field), origin_x_m_(origin_x_m), origin_y_m_(origin_y_m) {}
  double height_m(double x_m, double y_m) const override {
    return field_.interpolate(x_m - origin_x_m_, y_m - origin_y_m_);
  }

 private:
  const HeightField& field_;
  double origin_x_m_, origin_y_m_;
};

}  // namespace stoneskip
