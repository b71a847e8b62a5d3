#include "solvers/spectral/damped_mode.hpp"

#include <cmath>

namespace stoneskip {

DampedModeFactors damped_mode(double lambda, double mu, double t) {
  DampedModeFactors f;
  if (t == 0) return f;
  if (lambda == 0) {
    // k = 0: ẑ' decays as e^{−μt}; ẑ = ẑ0 + v̂0 (1 − e^{−μt})/μ (→ v̂0 t as μ → 0).
    f.gz = 1;
    f.gv = mu == 0 ? t : -std::expm1(-mu * t) / mu;
    return f;
  }
  const double D = lambda - 0.25 * mu * mu;
  const double u = -D * t * t;
  double C, S, decay = std::exp(-0.5 * mu * t);
  if (std::abs(u) < 0.5) {
    // Series: 24 terms give u^24/(48)! ≪ 1e-17 for |u| < 0.5.
    double termc = 1, terms = 1;
    C = 1;
    S = 1;
    for (int n = 1; n < 24; ++n) {
      termc *= u / ((2.0 * n - 1) * (2.0 * n));
      terms *= u / ((2.0 * n) * (2.0 * n + 1));
      C += termc;
      S += terms;
    }
    S *= t;
  } else if (D > 0) {
    const double w = std::sqrt(D);
    C = std::cos(w * t);
    S = std::sin(w * t) / w;
  } else {
    // e^{−μt/2} cosh(at) = ½(e^{(a−μ/2)t} + e^{−(a+μ/2)t}); likewise sinh. a < μ/2 when λ > 0.
    // a − μ/2 = (a² − μ²/4)/(a + μ/2) = −λ/(a + μ/2): the difference lost every digit of a slow
    // overdamped mode's decay (λ = 1e-6, μ = 1e6: e^{−λt/μ} read as 1 where it is 1 − 1.5e-7).
    const double a = std::sqrt(-D);
    const double ep = std::exp(-lambda / (a + 0.5 * mu) * t), em = std::exp(-(a + 0.5 * mu) * t);
    const double Cd = 0.5 * (ep + em), Sd = 0.5 * (ep - em) / a;
    f.gz = Cd + 0.5 * mu * Sd;
    f.gv = Sd;
    return f;
  }
  f.gz = decay * (C + 0.5 * mu * S);
  f.gv = decay * S;
  return f;
}

}  // namespace stoneskip
