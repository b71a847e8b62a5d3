#pragma once
// The water surface height η(x, y) the stone is clipped against (model/README.md §1.4 step 1). Still water
// is η = 0 and is the default (a null pointer wherever a surface is taken). A height field
// provides its own implementation (bilinear interpolation) when a scene couples the two.
namespace stoneskip {

class WaterSurface {
 public:
  virtual ~WaterSurface() = default;
  virtual double height_m(double x_m, double y_m) const = 0;
};

}  // namespace stoneskip
