#pragma once
// The range of a symmetric colour scale for a signed field (a water surface): large enough that
// the data it claims to show are shown, not saturated by a grid-scale speck nor washed out by one
// splash. The robust largest |z|: the 99th percentile of |z| over the disturbed cells — those with
// |z| above 1 % of the largest — so that at most 1 % of the disturbed cells lie beyond the scale,
// whatever the share of still water in the view.
#include <cstddef>
#include <vector>

namespace stoneskip {

struct RobustScale {
  double scale = 0;        // the colour scale is ±scale (0: the field is flat)
  double largest = 0;      // the largest |z|
  std::size_t disturbed = 0, beyond = 0;  // disturbed cells; of them, beyond ±scale (drawn at the ends)
};

inline constexpr double kDisturbedFraction = 0.01;  // of the largest |z|
inline constexpr double kScalePercentile = 0.99;    // of the disturbed cells' |z|

RobustScale robust_scale(const std::vector<double>& z);

}  // namespace stoneskip
