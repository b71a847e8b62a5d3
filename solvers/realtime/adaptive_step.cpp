#include "solvers/realtime/adaptive_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stoneskip {

namespace {

StateVector rhs(const Stone& stone, const Environment& env, const StateVector& y, const WaterSurface* surface) {
  StateVector d;
  rigid_body_rhs(stone, env, y.data(), d.data(), surface);
  return d;
}

void normalise_quaternion(StateVector& y) {
  double n = 0;
  for (int k = 0; k < 4; ++k) n += y[kQuaternion + k] * y[kQuaternion + k];
  n = std::sqrt(n);
  if (n > 0)
    for (int k = 0; k < 4; ++k) y[kQuaternion + k] /= n;
}

}  // namespace

Bs32Trial bs32_step(const Stone& stone, const Environment& env, const StateVector& y0, const StateVector& k1,
                    double h, const WaterSurface* surface, const StateVector& atol, double rtol,
                    const FieldFunction* field) {
  auto f = [&](const StateVector& y) {
    if (!field) return rhs(stone, env, y, surface);
    StateVector d;
    (*field)(y.data(), d.data());
    return d;
  };
  // Butcher tableau (Bogacki & Shampine 1989): c = (0, 1/2, 3/4, 1);
  // b = (2/9, 1/3, 4/9, 0) (order 3), b̂ = (7/24, 1/4, 1/3, 1/8) (order 2).
  StateVector y;
  for (int i = 0; i < kStateSize; ++i) y[i] = y0[i] + 0.5 * h * k1[i];
  const StateVector k2 = f(y);
  for (int i = 0; i < kStateSize; ++i) y[i] = y0[i] + 0.75 * h * k2[i];
  const StateVector k3 = f(y);
  Bs32Trial t;
  for (int i = 0; i < kStateSize; ++i) t.y1[i] = y0[i] + h * (2.0 / 9.0 * k1[i] + 1.0 / 3.0 * k2[i] + 4.0 / 9.0 * k3[i]);
  normalise_quaternion(t.y1);
  if (field) {
    t.k4 = f(t.y1);
    t.wetted_area_m2 = std::numeric_limits<double>::quiet_NaN();
  } else {
    // k4 with the loads it used: the wetted area at y1 comes with it.
    Loads loads;
    const StateDerivative d = rigid_body_rhs(stone, env, from_vector(t.y1.data()), surface, &loads);
    to_vector(d, t.k4.data());
    t.wetted_area_m2 = loads.water.wetted_area_m2;
  }
  double sum = 0, position = 0;
  for (int i = 0; i < kStateSize; ++i) {
    // b − b̂ = (−5/72, 1/12, 1/9, −1/8).
    const double e = h * (-5.0 / 72.0 * k1[i] + 1.0 / 12.0 * k2[i] + 1.0 / 9.0 * k3[i] - 1.0 / 8.0 * t.k4[i]);
    const double w = atol[i] + rtol * std::max(std::abs(y0[i]), std::abs(t.y1[i]));
    sum += (e / w) * (e / w);
    if (i >= kPosition && i < kPosition + 3) position += e * e;
  }
  t.position_error_m = std::sqrt(position);
  t.error_norm = std::sqrt(sum / kStateSize);
  return t;
}

double bs32_next_step(double h, double error_norm) {
  constexpr double kSafety = 0.9, kMinFactor = 0.2, kMaxFactor = 5.0;
  if (!(error_norm > 0)) return h * kMaxFactor;
  const double f = kSafety * std::pow(error_norm, -1.0 / 3.0);  // 1/(q + 1), q = 2 the embedded order
  return h * std::clamp(f, kMinFactor, kMaxFactor);
}

}  // namespace stoneskip
