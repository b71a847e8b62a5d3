#include "model/stone/pressure_distribution.hpp"

#include <algorithm>
#include <cmath>

namespace stoneskip {

WettedSpanBuilder::WettedSpanBuilder(const Vec3& v) {
  const Vec3 h(v.x(), v.y(), 0);
  const double n = h.norm();
  // Below a micrometre per second of horizontal speed no direction is meaningful.
  if (n > 1e-6) {
    direction_ = h / n;
    has_direction_ = true;
  }
}

void WettedSpanBuilder::add(const ClippedPolygon& p) {
  if (!has_direction_) return;
  for (int k = 0; k < p.count; ++k) {
    const double s = direction_.dot(p.vertices[k]);
    lo_ = std::min(lo_, s);
    hi_ = std::max(hi_, s);
  }
}

WettedSpan WettedSpanBuilder::span() const {
  WettedSpan out;
  if (!has_direction_ || !(hi_ > lo_)) return out;
  out.direction = direction_;
  out.start_m = lo_;
  out.length_m = hi_ - lo_;
  return out;
}

namespace {

// Radon's 7-point rule, exact for polynomials of degree 5 on a triangle (Stroud 1971, T2:5-1):
// barycentric points and weights (summing to 1).
constexpr double kA1 = 0.059715871789769820, kB1 = 0.470142064105115090;
constexpr double kA2 = 0.797426985353087322, kB2 = 0.101286507323456339;
constexpr double kW0 = 0.225, kW1 = 0.132394152788506181, kW2 = 0.125939180544827153;

void add_triangle(const Vec3& a, const Vec3& b, const Vec3& c, const WettedSpan& span, double k,
                  WeightedIntegrals& out) {
  const double area = 0.5 * (b - a).cross(c - a).norm();
  if (!(area > 0)) return;
  auto at = [&](double la, double lb, double lc, double w) {
    const Vec3 x = la * a + lb * b + lc * c;
    const double xi = std::max(span.xi(x), 0.0);
    const double f = w * area * (k + 1) * std::pow(xi, k);
    out.weight_m2 += f;
    out.moment_m3 += f * x;
  };
  at(1.0 / 3, 1.0 / 3, 1.0 / 3, kW0);
  at(kA1, kB1, kB1, kW1);
  at(kB1, kA1, kB1, kW1);
  at(kB1, kB1, kA1, kW1);
  at(kA2, kB2, kB2, kW2);
  at(kB2, kA2, kB2, kW2);
  at(kB2, kB2, kA2, kW2);
}

}  // namespace

WeightedIntegrals integrate_weight(const ClippedPolygon& poly, const WettedSpan& span, double exponent) {
  WeightedIntegrals out;
  for (int k = 1; k + 1 < poly.count; ++k)
    add_triangle(poly.vertices[0], poly.vertices[k], poly.vertices[k + 1], span, exponent, out);
  return out;
}

double waterline_rise_m(PressureDistribution d, double deepest_depth_m) {
  if (d != PressureDistribution::savitsky_wagner || !(deepest_depth_m > 0)) return 0;
  return (kWagnerRiseFactor - 1) * deepest_depth_m;  // Wagner 1932: wetted length × π/2
}

}  // namespace stoneskip
