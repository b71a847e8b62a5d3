#include "solvers/realtime/adaptive_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stoneskip {

namespace {

StateVector rhs(const Stone& stone, const Environment& env, const StateVector& y, const WaterSurface* surface,
                const LoadMode* mode) {
  StateVector d;
  rigid_body_rhs(stone, env, y.data(), d.data(), surface, nullptr, mode);
  return d;
}

void normalise_quaternion(StateVector& y) {
  double n = 0;
  for (int k = 0; k < 4; ++k) n += y[kQuaternion + k] * y[kQuaternion + k];
  n = std::sqrt(n);
  if (n > 0)
    for (int k = 0; k < 4; ++k) y[kQuaternion + k] /= n;
}

// A stage: the loads' right-hand side at y (in the held loaded region, if any), or the field's
// where one is given.
StateVector stage(const Stone& stone, const Environment& env, const WaterSurface* surface, const FieldFunction* field,
                  const LoadMode* mode, const StateVector& y) {
  if (!field) return rhs(stone, env, y, surface, mode);
  StateVector d;
  (*field)(y.data(), d.data());
  return d;
}

// The last stage, f(y1) (FSAL: the next step's first), with the loads it used: the wetted area at
// y1 comes with it (with a field, NaN: the caller measures it).
void last_stage(const Stone& stone, const Environment& env, const WaterSurface* surface, const FieldFunction* field,
                const LoadMode* mode, AdaptiveTrial& t) {
  if (field) {
    (*field)(t.y1.data(), t.k4.data());
    t.wetted_area_m2 = std::numeric_limits<double>::quiet_NaN();
  } else {
    Loads loads;
    const StateDerivative d = rigid_body_rhs(stone, env, from_vector(t.y1.data()), surface, &loads, nullptr, mode);
    to_vector(d, t.k4.data());
    t.wetted_area_m2 = loads.water.wetted_area_m2;
  }
}

// The error estimate e = y1 − ŷ1 measured: its RMS against atol_i + rtol max(|y0_i|, |y1_i|), and
// the position's part in metres.
void measure_error(const StateVector& e, const StateVector& y0, const StateVector& atol, double rtol, AdaptiveTrial& t) {
  double sum = 0, position = 0;
  for (int i = 0; i < kStateSize; ++i) {
    const double w = atol[i] + rtol * std::max(std::abs(y0[i]), std::abs(t.y1[i]));
    sum += (e[i] / w) * (e[i] / w);
    if (i >= kPosition && i < kPosition + 3) position += e[i] * e[i];
  }
  t.position_error_m = std::sqrt(position);
  t.error_norm = std::sqrt(sum / kStateSize);
}

// Hairer, Nørsett & Wanner §II.4, Eq. 4.13, with q the embedded solution's order.
double next_step(double h, double error_norm, int q) {
  constexpr double kSafety = 0.9, kMinFactor = 0.2, kMaxFactor = 5.0;
  if (!(error_norm > 0)) return h * kMaxFactor;
  const double f = kSafety * std::pow(error_norm, -1.0 / (q + 1));
  return h * std::clamp(f, kMinFactor, kMaxFactor);
}

}  // namespace

AdaptiveTrial bs32_step(const Stone& stone, const Environment& env, const StateVector& y0, const StateVector& k1,
                        double h, const WaterSurface* surface, const StateVector& atol, double rtol,
                        const FieldFunction* field, const LoadMode* mode) {
  auto f = [&](const StateVector& y) { return stage(stone, env, surface, field, mode, y); };
  // Butcher tableau (Bogacki & Shampine 1989): c = (0, 1/2, 3/4, 1);
  // b = (2/9, 1/3, 4/9, 0) (order 3), b̂ = (7/24, 1/4, 1/3, 1/8) (order 2).
  StateVector y;
  for (int i = 0; i < kStateSize; ++i) y[i] = y0[i] + 0.5 * h * k1[i];
  const StateVector k2 = f(y);
  for (int i = 0; i < kStateSize; ++i) y[i] = y0[i] + 0.75 * h * k2[i];
  const StateVector k3 = f(y);
  AdaptiveTrial t;
  for (int i = 0; i < kStateSize; ++i) t.y1[i] = y0[i] + h * (2.0 / 9.0 * k1[i] + 1.0 / 3.0 * k2[i] + 4.0 / 9.0 * k3[i]);
  normalise_quaternion(t.y1);
  last_stage(stone, env, surface, field, mode, t);
  StateVector e;
  // b − b̂ = (−5/72, 1/12, 1/9, −1/8).
  for (int i = 0; i < kStateSize; ++i)
    e[i] = h * (-5.0 / 72.0 * k1[i] + 1.0 / 12.0 * k2[i] + 1.0 / 9.0 * k3[i] - 1.0 / 8.0 * t.k4[i]);
  measure_error(e, y0, atol, rtol, t);
  return t;
}

AdaptiveTrial dp54_step(const Stone& stone, const Environment& env, const StateVector& y0, const StateVector& k1,
                        double h, const WaterSurface* surface, const StateVector& atol, double rtol,
                        const FieldFunction* field, const LoadMode* mode) {
  auto f = [&](const StateVector& y) { return stage(stone, env, surface, field, mode, y); };
  // Butcher tableau (Dormand & Prince 1980, J. Comput. Appl. Math. 6(1), 19–26; Hairer, Nørsett &
  // Wanner, Solving ODEs I, §II.5, Table 5.2): c = (0, 1/5, 3/10, 4/5, 8/9, 1, 1); the fifth-order
  // weights b are the last row of a (FSAL), the fourth-order ones
  // b̂ = (5179/57600, 0, 7571/16695, 393/640, −92097/339200, 187/2100, 1/40).
  constexpr double a21 = 1.0 / 5;
  constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
  constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
  constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
  constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                   a65 = -5103.0 / 18656;
  constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84;
  // e = b − b̂ (b₂ = b̂₂ = 0, b₇ = 0).
  constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                   e6 = 22.0 / 525, e7 = -1.0 / 40;
  StateVector y;
  for (int i = 0; i < kStateSize; ++i) y[i] = y0[i] + h * (a21 * k1[i]);
  const StateVector k2 = f(y);
  for (int i = 0; i < kStateSize; ++i) y[i] = y0[i] + h * (a31 * k1[i] + a32 * k2[i]);
  const StateVector k3 = f(y);
  for (int i = 0; i < kStateSize; ++i) y[i] = y0[i] + h * (a41 * k1[i] + a42 * k2[i] + a43 * k3[i]);
  const StateVector k4 = f(y);
  for (int i = 0; i < kStateSize; ++i) y[i] = y0[i] + h * (a51 * k1[i] + a52 * k2[i] + a53 * k3[i] + a54 * k4[i]);
  const StateVector k5 = f(y);
  for (int i = 0; i < kStateSize; ++i)
    y[i] = y0[i] + h * (a61 * k1[i] + a62 * k2[i] + a63 * k3[i] + a64 * k4[i] + a65 * k5[i]);
  const StateVector k6 = f(y);
  AdaptiveTrial t;
  for (int i = 0; i < kStateSize; ++i)
    t.y1[i] = y0[i] + h * (b1 * k1[i] + b3 * k3[i] + b4 * k4[i] + b5 * k5[i] + b6 * k6[i]);
  normalise_quaternion(t.y1);
  last_stage(stone, env, surface, field, mode, t);
  // The continuous extension's quartic term (dense_output.hpp; Hairer's DOPRI5, CONTD5):
  // d = (−12715105075/11282082432, 0, 87487479700/32700410799, −10690763975/1880347072,
  //      701980252875/199316789632, −1453857185/822651844, 69997945/29380423).
  constexpr double d1 = -12715105075.0 / 11282082432, d3 = 87487479700.0 / 32700410799,
                   d4 = -10690763975.0 / 1880347072, d5 = 701980252875.0 / 199316789632,
                   d6 = -1453857185.0 / 822651844, d7 = 69997945.0 / 29380423;
  for (int i = 0; i < kStateSize; ++i)
    t.quartic[i] = h * (d1 * k1[i] + d3 * k3[i] + d4 * k4[i] + d5 * k5[i] + d6 * k6[i] + d7 * t.k4[i]);
  t.has_quartic = true;
  StateVector e;
  for (int i = 0; i < kStateSize; ++i)
    e[i] = h * (e1 * k1[i] + e3 * k3[i] + e4 * k4[i] + e5 * k5[i] + e6 * k6[i] + e7 * t.k4[i]);
  measure_error(e, y0, atol, rtol, t);
  return t;
}

double dp54_next_step(double h, double error_norm) { return next_step(h, error_norm, 4); }

double bs32_next_step(double h, double error_norm) { return next_step(h, error_norm, 2); }

}  // namespace stoneskip
