#pragma once
// Where a water law's pressure acts on the wetted region (model/README.md §1.4, "Where the pressure acts").
// Uniform pressure on each clipped face puts the centre of pressure at the wetted centroid, near
// the trailing edge; planing theory puts it near the spray root. The distributions weight the
// pressure along ξ ∈ [0, 1], the position along the stone's horizontal velocity ĥ from the
// trailing edge of the wetted region (0) to its waterline ahead (1), with
//     w(ξ) = (k + 1) ξ^k,   ∫₀¹ w dξ = 1,   centroid (k + 1)/(k + 2) = c  ⇒  k = (2c − 1)/(1 − c),
// c = 0.75 the centre of pressure of a planing plate as a fraction of its wetted length from the
// trailing edge (Savitsky 1964, the high-speed limit of l_p/(λb) = 0.75 − 1/(5.21 C_v²/λ² + 2.39)):
// k = 2. Only c is Savitsky's; the power-law form is this code's, the lowest-order monomial with
// that centroid per unit width. The Wagner variant first lengthens the wetted region by the water
// rising ahead of the stone: a flat plate entering water wets π/2 times its geometric length
// (Wagner 1932; essential to continual skipping in Hewitt, Balmforth & McElwaine, JFM 669, 2011),
// i.e. the region below a waterline raised by (π/2 − 1) × the deepest vertex's depth. Either way
// the law's total force (Σ p_i S_i over the geometric wetted area) is kept: only where it acts
// moves. fluid_forces.cpp applies these; each face's force and torque are exact integrals.
#include <numbers>

#include "model/stone/environment.hpp"
#include "model/stone/triangle_clip.hpp"

namespace stoneskip {

constexpr double kSavitskyCentreFraction = 0.75;             // Savitsky 1964, high-speed limit
constexpr double kWagnerRiseFactor = std::numbers::pi / 2;    // Wagner 1932, flat plate

// The exponent k of w(ξ) = (k + 1) ξ^k whose centroid is the fraction c of the length.
constexpr double power_weight_exponent(double c) { return (2 * c - 1) / (1 - c); }

// The wetted region's extent along the stone's horizontal velocity: s = direction·x runs from
// start_m (trailing edge, ξ = 0) to start_m + length_m (waterline ahead, ξ = 1).
struct WettedSpan {
  Vec3 direction = Vec3::UnitX();  // unit, horizontal
  double start_m = 0, length_m = 0;
  bool valid() const { return length_m > 0; }
  double xi(const Vec3& x) const { return (direction.dot(x) - start_m) / length_m; }
};

// The span of a set of wetted polygons along the horizontal part of velocity_m_s (invalid when the
// velocity has no horizontal part or the polygons have no extent along it).
class WettedSpanBuilder {
 public:
  explicit WettedSpanBuilder(const Vec3& velocity_m_s);
  void add(const ClippedPolygon& p);
  WettedSpan span() const;

 private:
  Vec3 direction_ = Vec3::Zero();
  bool has_direction_ = false;
  double lo_ = 1e300, hi_ = -1e300;
};

// ∫ w(ξ) dA and ∫ w(ξ) x dA over a convex polygon, w(ξ) = (k + 1) max(ξ, 0)^k.
struct WeightedIntegrals {
  double weight_m2 = 0;
  Vec3 moment_m3 = Vec3::Zero();
};
// Exact for whole k ≤ 4 (the 7-point degree-5 rule of Radon 1948 on each fan triangle: w x is a
// polynomial of degree k + 1 there, ξ being linear in x); for k = 2 on a polygon with ξ ≥ 0 at
// every vertex, the same integrals in closed form (equal to round-off, several times cheaper).
WeightedIntegrals integrate_weight(const ClippedPolygon& poly, const WettedSpan& span, double exponent);
// The same for a polygon in the plane of the unit normal n (fan areas without a square root, as
// area_of(poly, n) in triangle_clip.hpp).
WeightedIntegrals integrate_weight(const ClippedPolygon& poly, const WettedSpan& span, double exponent,
                                   const Vec3& unit_normal);

// The share β ∈ [0, 1] of the planing distribution in the pressure actually applied,
//     w_β = (1 − β) · 1 + β · w(ξ),   β = min(1, C_v),   C_v = |v_h| / √(g b),
// the rest uniform. w(ξ) is planing's picture: a wetted length along the horizontal motion ĥ. It
// needs forward motion, and its direction ĥ = v_h/|v_h| turns arbitrarily fast as v_h → 0 (a stone
// sinking nearly straight down): the load's derivative grows as 1/|v_h|, and no integrator steps
// across such a point (the 2 g stone of cases/hard/: 2 million CVODE steps). The uniform
// distribution has no direction, so blending towards it as |v_h| → 0 makes the load Lipschitz
// there. C_v is Savitsky's (1964) speed coefficient on the beam b (here the stone's disk
// diameter); the ramp's end at C_v = 1 is this code's choice, not a source's. At C_v ≥ 1 β = 1
// and the loads are those of w alone, bit for bit. C_v = 1 is 0.77 m/s for the 3 cm stone: a
// stone skips at metres per second, and only the slow end of a last contact is blended.
double planing_share(const Vec3& velocity_m_s, double gravity_m_s2, double beam_m);

// The depth offset that raises the waterline for a distribution (the Wagner rise): (π/2 − 1) d_max
// for savitsky_wagner with d_max > 0, else 0.
double waterline_rise_m(PressureDistribution d, double deepest_depth_m);

// Where the Wagner rise wets: the stone's underside only. The water piled up ahead of a planing
// bottom runs up along that bottom (Wagner 1932: the wetted length of the planing surface × π/2);
// it does not wet the stone's flanks or top above the undisturbed waterline, where a rise loaded
// with the distribution's leading-edge peak would turn the lift into drag (a deep contact's lift
// then fell with depth: model/README.md §1.9). The underside is the faces whose body normal points
// away from the side of the body z axis (the disk normal) that faces up: body n_z · s < 0, with
// s = underside_side(R) = +1 while the body z axis points up (R₂₂ ≥ 0), −1 for a stone turned over.
// Faces with body n_z = 0 (a prism's rim) are not on it: |n_z| ≤ 1e-9 counts as 0, since a rim
// face's normal, a normalised cross product, carries round-off of 1e-17 either way (which would
// wet one of a mirror-symmetric rim's twin faces and not the other).
int underside_side(const Mat3& R);
inline bool on_underside(const Vec3& body_normal, int side) { return body_normal.z() * side < -1e-9; }

}  // namespace stoneskip
