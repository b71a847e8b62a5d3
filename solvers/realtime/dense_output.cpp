#include "solvers/realtime/dense_output.hpp"

#include <cmath>
#include <functional>

namespace stoneskip {

StateVector HermiteStep::at(double theta) const {
  // Hermite basis (Hairer, Nørsett & Wanner §II.6, Eq. 6.7).
  const double t = theta, t2 = t * t, t3 = t2 * t;
  const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t, h01 = -2 * t3 + 3 * t2, h11 = t3 - t2;
  StateVector y;
  for (int i = 0; i < kStateSize; ++i) y[i] = h00 * y0[i] + h10 * h_s * f0[i] + h01 * y1[i] + h11 * h_s * f1[i];
  if (has_quartic) {
    const double q = t2 * (1 - t) * (1 - t);
    for (int i = 0; i < kStateSize; ++i) y[i] += q * quartic[i];
  }
  return y;
}

RigidState HermiteStep::state_at(double theta) const {
  const StateVector y = at(theta);
  RigidState s = from_vector(y.data());
  s.orientation.normalize();
  return s;
}

double vertex_depth(const Stone& stone, const RigidState& s, const WaterSurface* surface, int k) {
  const Vec3 w = s.position_m + s.orientation.toRotationMatrix() * stone.body_mesh.vertices[k];
  const double eta = surface ? surface->height_m(w.x(), w.y()) : 0.0;
  return eta - w.z();
}

double sign_change_fraction(const std::function<double(double)>& g, double g0, double g1, double fraction_tolerance,
                            double wanted_below) {
  constexpr int kMaxIterations = 100;
  // Keep a bracket [a, b] whose ends differ in (g > 0), as the callers' tests do.
  double a = 0, b = 1, fa = g0, fb = g1;
  const bool a_positive = fa > 0;
  int side = 0;
  for (int it = 0; it < kMaxIterations && b - a > fraction_tolerance && a < wanted_below; ++it) {
    double c = (fa == fb) ? 0.5 * (a + b) : a + (b - a) * fa / (fa - fb);
    if (!(c > a && c < b)) c = 0.5 * (a + b);
    const double fc = g(c);
    if ((fc > 0) == a_positive) {
      a = c;
      fa = fc;
      if (side == -1) fb *= 0.5;  // Illinois: halve the stale end's value
      side = -1;
    } else {
      b = c;
      fb = fc;
      if (side == 1) fa *= 0.5;
      side = 1;
    }
  }
  return b;  // the first fraction at which g is on the end's side
}

double crossing_fraction(const HermiteStep& step, const Stone& stone, const WaterSurface* surface, int k, double d0,
                         double d1, double fraction_tolerance) {
  // "Under" is d > 0, as the caller's test (d ≤ 0 against d > 0).
  return sign_change_fraction([&](double c) { return vertex_depth(stone, step.state_at(c), surface, k); }, d0, d1,
                              fraction_tolerance);
}

}  // namespace stoneskip
