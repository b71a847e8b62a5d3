#include "verification/convergence/gci.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace stoneskip {

const char* to_string(ConvergenceKind k) {
  switch (k) {
    case ConvergenceKind::monotone: return "monotone";
    case ConvergenceKind::oscillatory: return "oscillatory";
    case ConvergenceKind::divergent: return "divergent";
    case ConvergenceKind::converged_to_roundoff: return "converged to round-off";
  }
  return "?";
}

std::string GciResult::brief() const {
  char buf[240];
  if (kind == ConvergenceKind::divergent || kind == ConvergenceKind::converged_to_roundoff) {
    std::snprintf(buf, sizeof buf, "%s (no GCI)", to_string(kind));
  } else if (reverted) {
    std::snprintf(buf, sizeof buf,
                  "%s, p = %.3g (not reasonable: the formal %.3g and Fs = %.3g used), phi_ext = %.6g, GCI_fine = %.3g %%",
                  to_string(kind), order, order_used, safety_factor, extrapolated, 100 * gci_fine);
  } else {
    std::snprintf(buf, sizeof buf, "%s, p = %.3g, phi_ext = %.6g, GCI_fine = %.3g %%", to_string(kind), order,
                  extrapolated, 100 * gci_fine);
  }
  return buf;
}

namespace {

// The apparent order: the least positive root of Celik's Eq. 4,
//   f(p) = p ln r21 − ln|ε32/ε21| − q(p),  q(p) = ln((r21^p − s)/(r32^p − s)),
// found by bisection inside the first sign change of f over a geometric scan of [kLeast, kMost].
// Celik solves it by fixed-point iteration, which converges only where |q'(p)| < ln r21: on ratios
// such as r21 = 1.5, r32 = 3 it runs away (the map's slope is −1.25 at p = 2) and would call exact
// second-order data divergent. No root in the range: no positive order (NaN).
constexpr double kLeast = 1e-3, kMost = 50;
double apparent_order(double r21, double r32, double lratio, double s, int& steps) {
  const double l21 = std::log(r21);
  auto f = [&](double p) {
    const double a = std::pow(r21, p) - s, b = std::pow(r32, p) - s;
    if (!(a > 0) || !(b > 0)) return std::numeric_limits<double>::quiet_NaN();
    return p * l21 - lratio - std::log(a / b);
  };
  constexpr int kScan = 2000;
  double lo = kLeast, flo = f(lo);
  steps = 0;
  for (int k = 1; k <= kScan; ++k) {
    double hi = kLeast * std::pow(kMost / kLeast, static_cast<double>(k) / kScan);
    const double fhi = f(hi);
    if (std::isfinite(flo) && flo == 0) return lo;
    if (std::isfinite(flo) && std::isfinite(fhi) && (flo < 0) != (fhi < 0)) {
      while (steps < 200 && hi - lo > 1e-15 * hi) {
        ++steps;
        const double mid = 0.5 * (lo + hi), fm = f(mid);
        if (fm == 0) return mid;
        if ((fm < 0) == (flo < 0)) {
          lo = mid;
          flo = fm;
        } else {
          hi = mid;
        }
      }
      return 0.5 * (lo + hi);
    }
    lo = hi;
    flo = fhi;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

GciResult grid_convergence_index(double phi1, double phi2, double phi3, double h1, double h2, double h3,
                                 const GciOptions& o) {
  GciResult g;
  g.ratio_21 = h2 / h1;  // Celik et al. 2008, Eq. 2 uses r = h_coarse / h_fine
  g.ratio_32 = h3 / h2;
  const double eps21 = phi2 - phi1;
  const double eps32 = phi3 - phi2;
  // Differences at the level of round-off in φ carry no information about the order.
  const double scale = std::max({std::abs(phi1), std::abs(phi2), std::abs(phi3)});
  const double roundoff = 64 * std::numeric_limits<double>::epsilon() * std::max(scale, 1e-300);
  if (std::abs(eps21) <= roundoff && std::abs(eps32) <= roundoff) {
    g.kind = ConvergenceKind::converged_to_roundoff;
    g.extrapolated = phi1;
    return g;
  }
  if (std::abs(eps21) <= roundoff) {
    // The two finest agree to round-off while the coarse pair differs: Eq. 9 would scale a
    // round-off difference into a band of round-off size, whatever the order. No GCI from it.
    g.kind = ConvergenceKind::converged_to_roundoff;
    g.extrapolated = phi1;
    return g;
  }
  if (eps32 == 0 || !(g.ratio_21 > 1) || !(g.ratio_32 > 1)) {
    g.kind = ConvergenceKind::divergent;  // no order can be inferred
    return g;
  }
  const double s = (eps32 / eps21) > 0 ? 1.0 : -1.0;  // Celik Eq. 5: s = sign(ε32/ε21)
  // Celik takes |·| of q's bracket; we keep its sign (a bracket ≤ 0 has no root there), so that a
  // negative (divergent) order is reported as divergence instead of being folded to positive.
  const double p = apparent_order(g.ratio_21, g.ratio_32, std::log(std::abs(eps32 / eps21)), s, g.iterations);
  g.order = p;
  if (!(p > 0)) {
    g.kind = ConvergenceKind::divergent;
    return g;
  }
  g.kind = s > 0 ? ConvergenceKind::monotone : ConvergenceKind::oscillatory;
  g.order_used = p;
  g.safety_factor = o.safety_factor;
  if (o.formal_order > 0 && std::abs(p - o.formal_order) > o.order_band) {
    g.reverted = true;  // Roache 2011: not a reasonable order: p_th and FS = 3
    g.order_used = o.formal_order;
    g.safety_factor = o.reverted_safety_factor;
  }
  const double r21p = std::pow(g.ratio_21, g.order_used);
  g.extrapolated = (r21p * phi1 - phi2) / (r21p - 1);                     // Eq. 6
  g.relative_error = std::abs((phi1 - phi2) / phi1);                      // Eq. 7
  g.extrapolated_relative_error = std::abs((g.extrapolated - phi1) / g.extrapolated);  // Eq. 8
  g.gci_fine = g.safety_factor * g.relative_error / (r21p - 1);           // Eq. 9
  g.gci_fine_absolute = g.safety_factor * std::abs(eps21) / (r21p - 1);   // Eq. 9 before dividing by |φ1|
  return g;
}

}  // namespace stoneskip
