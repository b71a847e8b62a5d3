#pragma once
// Where a scene's pond lies in the throw's frame, and which contacts of a throw began beyond its
// rim. Off a walled pond the surface the stone reads is the nearest edge's height
// (HeightField::interpolate clamps) and a two-way field takes none of the push (DraughtWindow drops
// the points beyond the rim): such a contact is not on the live water the case names, and every
// output that shows a throw on a pond says so (`run`'s notes, `scene`'s summary).
#include <string>
#include <vector>

#include "model/water/height_field.hpp"
#include "solvers/realtime/throw_result.hpp"

namespace stoneskip {

struct PondExtent {
  double x0_m = 0, x1_m = 0, y0_m = 0, y1_m = 0;  // the grid points' span: origin + (n − 1)·cell_m
  bool wraps = false;                             // periodic: the surface tiles the plane, no contact is off
  std::vector<int> off;                           // contacts (1-based) whose first touch lies outside the span
};

PondExtent pond_extent(const HeightFieldOptions& field, double origin_x_m, double origin_y_m,
                       const std::vector<ContactRecord>& contacts);

// One sentence naming the contacts off the pond, where they began and what that means (empty when
// none is off); `two_way`: the water took none of their push.
std::string off_pond_sentence(const PondExtent& p, const std::vector<ContactRecord>& contacts, bool two_way);

}  // namespace stoneskip
