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
  char buf[200];
  if (kind == ConvergenceKind::divergent || kind == ConvergenceKind::converged_to_roundoff) {
    std::snprintf(buf, sizeof buf, "%s (no GCI)", to_string(kind));
  } else {
    std::snprintf(buf, sizeof buf, "%s, p = %.3g, phi_ext = %.6g, GCI_fine = %.3g %%", to_string(kind), order,
                  extrapolated, 100 * gci_fine);
  }
  return buf;
}

GciResult grid_convergence_index(double phi1, double phi2, double phi3, double h1, double h2, double h3,
                                 double safety_factor) {
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
  if (eps21 == 0 || eps32 == 0 || !(g.ratio_21 > 1) || !(g.ratio_32 > 1)) {
    g.kind = ConvergenceKind::divergent;  // no order can be inferred
    return g;
  }
  const double s = (eps32 / eps21) > 0 ? 1.0 : -1.0;  // Celik Eq. 5: s = sign(ε32/ε21)
  const double l21 = std::log(g.ratio_21);
  const double lratio = std::log(std::abs(eps32 / eps21));
  // Celik Eq. 3–4: p = [ln|ε32/ε21| + q(p)] / ln r21, q(p) = ln((r21^p − s)/(r32^p − s)),
  // solved by fixed-point iteration. Celik takes |·| of the bracket; we keep its sign so that a
  // negative (divergent) order is reported as divergence instead of being folded to positive.
  auto q = [&](double p) {
    double a = std::pow(g.ratio_21, p) - s, b = std::pow(g.ratio_32, p) - s;
    if (a <= 0 || b <= 0) return std::numeric_limits<double>::quiet_NaN();
    return std::log(a / b);
  };
  double p = lratio / l21;
  bool converged = false;
  for (g.iterations = 1; g.iterations <= 200; ++g.iterations) {
    if (!(p > 0) || !std::isfinite(p) || p > 50) break;
    double next = (lratio + q(p)) / l21;
    if (!std::isfinite(next)) break;
    if (std::abs(next - p) <= 1e-12 * std::max(1.0, std::abs(next))) {
      p = next;
      converged = true;
      break;
    }
    p = next;
  }
  if (!converged || !(p > 0)) {
    g.kind = ConvergenceKind::divergent;
    g.order = p;
    return g;
  }
  g.kind = s > 0 ? ConvergenceKind::monotone : ConvergenceKind::oscillatory;
  g.order = p;
  const double r21p = std::pow(g.ratio_21, p);
  g.extrapolated = (r21p * phi1 - phi2) / (r21p - 1);                     // Eq. 6
  g.relative_error = std::abs((phi1 - phi2) / phi1);                      // Eq. 7
  g.extrapolated_relative_error = std::abs((g.extrapolated - phi1) / g.extrapolated);  // Eq. 8
  g.gci_fine = safety_factor * g.relative_error / (r21p - 1);             // Eq. 9
  return g;
}

}  // namespace stoneskip
