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

double planing_share(const Vec3& v, double g, double beam_m) {
  const double vh = std::hypot(v.x(), v.y());
  const double reference = std::sqrt(g * beam_m);  // C_v = 1
  if (!(reference > 0) || vh >= reference) return 1;
  return vh / reference;
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

// x^k for the exponents in use: whole k ≤ 4 by multiplication (std::pow costs as much as the
// rest of a face's integral), any other k by std::pow.
double power(double x, double k, int whole) {
  switch (whole) {
    case 0: return 1;
    case 1: return x;
    case 2: return x * x;
    case 3: return x * x * x;
    case 4: return (x * x) * (x * x);
  }
  return std::pow(x, k);
}

int whole_exponent(double k) { return (k >= 0 && k <= 4 && k == std::floor(k)) ? static_cast<int>(k) : -1; }

// A fan triangle's area: ½ |(b − a) × (c − a)|, or its component along the polygon's unit normal.
double fan_area(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3* n) {
  const Vec3 cr = (b - a).cross(c - a);
  return 0.5 * (n ? std::abs(cr.dot(*n)) : cr.norm());
}

void add_triangle(const Vec3& a, const Vec3& b, const Vec3& c, const WettedSpan& span, double k, int whole,
                  const Vec3* n, WeightedIntegrals& out) {
  const double area = fan_area(a, b, c, n);
  if (!(area > 0)) return;
  auto at = [&](double la, double lb, double lc, double w) {
    const Vec3 x = la * a + lb * b + lc * c;
    const double xi = std::max(span.xi(x), 0.0);
    const double f = w * area * (k + 1) * power(xi, k, whole);
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

// The quadratic weight w = 3ξ² on a triangle where ξ ≥ 0 (ξ linear, vertex values xa, xb, xc) in
// closed form, from ∫ λ_A^i λ_B^j λ_C^l dA = 2S i! j! l! / (i + j + l + 2)! (S the area):
//   ∫ 3ξ² dA   = S/2 Q,                     Q = xa² + xb² + xc² + xa xb + xb xc + xc xa,
//   ∫ 3ξ² x dA = S/10 Σ_V x_V (Q + ξ_V (ξ_V + xa + xb + xc)).
// Equal to the 7-point rule (exact for this degree) to round-off, at a fraction of its cost.
void add_quadratic_triangle(const Vec3& a, const Vec3& b, const Vec3& c, double xa, double xb, double xc,
                            const Vec3* n, WeightedIntegrals& out) {
  const double area = fan_area(a, b, c, n);
  if (!(area > 0)) return;
  const double q = xa * xa + xb * xb + xc * xc + xa * xb + xb * xc + xc * xa, sum = xa + xb + xc;
  out.weight_m2 += 0.5 * area * q;
  out.moment_m3 += (0.1 * area) * ((q + xa * (xa + sum)) * a + (q + xb * (xb + sum)) * b + (q + xc * (xc + sum)) * c);
}

WeightedIntegrals integrate(const ClippedPolygon& poly, const WettedSpan& span, double exponent, const Vec3* n) {
  WeightedIntegrals out;
  if (exponent == 2) {
    // Savitsky's weight on a polygon inside the span (the loads' case): in closed form.
    double xi[4];
    bool inside = true;
    const double per_length = 1 / span.length_m;  // span.xi with one division per polygon
    for (int k = 0; k < poly.count; ++k) {
      xi[k] = (span.direction.dot(poly.vertices[k]) - span.start_m) * per_length;
      inside = inside && xi[k] >= 0;
    }
    if (inside) {
      for (int k = 1; k + 1 < poly.count; ++k)
        add_quadratic_triangle(poly.vertices[0], poly.vertices[k], poly.vertices[k + 1], xi[0], xi[k], xi[k + 1], n, out);
      return out;
    }
  }
  // Elsewhere (another exponent, or part of the polygon behind the trailing edge, where w is cut
  // to 0): Radon's rule, exact for whole k ≤ 4 where ξ ≥ 0.
  const int whole = whole_exponent(exponent);
  for (int k = 1; k + 1 < poly.count; ++k)
    add_triangle(poly.vertices[0], poly.vertices[k], poly.vertices[k + 1], span, exponent, whole, n, out);
  return out;
}

}  // namespace

WeightedIntegrals integrate_weight(const ClippedPolygon& poly, const WettedSpan& span, double exponent) {
  return integrate(poly, span, exponent, nullptr);
}

WeightedIntegrals integrate_weight(const ClippedPolygon& poly, const WettedSpan& span, double exponent,
                                   const Vec3& unit_normal) {
  return integrate(poly, span, exponent, &unit_normal);
}

double waterline_rise_m(PressureDistribution d, double deepest_depth_m) {
  if (d != PressureDistribution::savitsky_wagner || !(deepest_depth_m > 0)) return 0;
  return (kWagnerRiseFactor - 1) * deepest_depth_m;  // Wagner 1932: wetted length × π/2
}

int underside_side(const Mat3& R) { return R(2, 2) >= 0 ? 1 : -1; }

}  // namespace stoneskip
