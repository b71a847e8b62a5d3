#include "solvers/reference/absolute_tolerance.hpp"

#include <algorithm>
#include <cmath>

namespace stoneskip {

StateVector absolute_tolerances(const ReferenceOptions& o, const StateScales& scales) {
  StateVector a;
  a.fill(o.atol);
  if (o.atol_scaling == ToleranceScaling::uniform) return a;
  return scaled_absolute_tolerances(o.atol, scales);
}

}  // namespace stoneskip
