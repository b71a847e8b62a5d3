#include "solvers/scene/pond_extent.hpp"

#include <cstdio>

namespace stoneskip {

namespace {
std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}
}  // namespace

PondExtent pond_extent(const HeightFieldOptions& field, double origin_x_m, double origin_y_m,
                       const std::vector<ContactRecord>& contacts) {
  PondExtent p;
  p.x0_m = origin_x_m;
  p.y0_m = origin_y_m;
  p.x1_m = origin_x_m + (field.nx - 1) * field.cell_m;
  p.y1_m = origin_y_m + (field.ny - 1) * field.cell_m;
  p.wraps = field.boundary == Boundary::periodic;
  if (p.wraps) return p;
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const Vec3& x = contacts[k].first_touch_m;
    if (x.x() < p.x0_m || x.x() > p.x1_m || x.y() < p.y0_m || x.y() > p.y1_m) p.off.push_back(static_cast<int>(k) + 1);
  }
  return p;
}

std::string off_pond_sentence(const PondExtent& p, const std::vector<ContactRecord>& contacts, bool two_way) {
  if (p.off.empty()) return {};
  std::string s = p.off.size() == 1 ? "contact " : "contacts ";
  for (std::size_t k = 0; k < p.off.size(); ++k) {
    const Vec3& x = contacts[p.off[k] - 1].first_touch_m;
    s += (k ? ", " : "") + std::to_string(p.off[k]) + " (x = " + num(x.x()) + " m, y = " + num(x.y()) + " m)";
  }
  s += p.off.size() == 1 ? " lies" : " lie";
  s += " outside the pond, x in [" + num(p.x0_m) + ", " + num(p.x1_m) + "] m, y in [" + num(p.y0_m) + ", " + num(p.y1_m) +
       "] m: the surface there is the nearest edge's height";
  if (two_way) s += ", and the water takes none of the push (its impulse does not balance the stone's)";
  return s;
}

}  // namespace stoneskip
