#include "model/water/stencil.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace stoneskip {

double Stencil::symbol(double a, double b) const {
  const double ca = std::cos(a), cb = std::cos(b);
  return centre + 2 * orth * (ca + cb) + 4 * diag * ca * cb;
}

double Stencil::min_symbol() const {
  double m = symbol(0, 0);
  for (double a : {0.0, M_PI})
    for (double b : {0.0, M_PI}) m = std::min(m, symbol(a, b));
  return m;
}

double Stencil::max_symbol() const {
  double m = symbol(0, 0);
  for (double a : {0.0, M_PI})
    for (double b : {0.0, M_PI}) m = std::max(m, symbol(a, b));
  return m;
}

double Stencil::symbol_roundoff() const {
  return 16 * std::numeric_limits<double>::epsilon() * (std::abs(centre) + 4 * std::abs(orth) + 4 * std::abs(diag));
}

double leapfrog_courant_limit(const Stencil& stencil) {
  const double tiny = stencil.symbol_roundoff();
  if (stencil.max_symbol() > tiny) return 0;  // a growing mode at every σ > 0
  const double smin = stencil.min_symbol();
  if (smin >= -tiny) return std::numeric_limits<double>::infinity();  // every symbol 0: no coupling
  return 2 / std::sqrt(-smin);  // Schur–Cohn/Jury on the amplification quadratic (stencil.hpp)
}

double leapfrog_courant_limit(const Stencil& stencil, double cx_min, double cx_max, double cy_min, double cy_max) {
  // symbol(a, b) = centre + 2 orth (cos a + cos b) + 4 diag cos a cos b, at the ends of the cosines' ranges.
  auto s = [&](double ca, double cb) { return stencil.centre + 2 * stencil.orth * (ca + cb) + 4 * stencil.diag * ca * cb; };
  double smin = s(cx_max, cy_max), smax = smin;
  for (double ca : {cx_min, cx_max})
    for (double cb : {cy_min, cy_max}) smin = std::min(smin, s(ca, cb)), smax = std::max(smax, s(ca, cb));
  const double tiny = stencil.symbol_roundoff();
  if (smax > tiny) return 0;
  if (smin >= -tiny) return std::numeric_limits<double>::infinity();
  return 2 / std::sqrt(-smin);
}

Stencil stencil_family(double gamma, std::string name) {
  // model/README.md §2.2: weights centre −4(1 − γ) − 2γ, orth 1 − γ, diag γ/2.
  return Stencil{std::move(name), -4 * (1 - gamma) - 2 * gamma, 1 - gamma, gamma / 2};
}

const std::vector<std::string>& stencil_names() {
  static const std::vector<std::string> names{"five_point", "nine_point_half", "nine_point_isotropic", "paper_eq11"};
  return names;
}

bool is_stencil_name(const std::string& name) {
  for (const auto& n : stencil_names())
    if (n == name) return true;
  return false;
}

Stencil named_stencil(const std::string& name) {
  if (name == "five_point") return stencil_family(0.0, name);                // Lee & Baek 2013, Fig. 4(a)
  if (name == "nine_point_half") return stencil_family(0.5, name);           // Eq. 10 divided by 2
  if (name == "nine_point_isotropic") return stencil_family(1.0 / 3, name);  // Patra & Karttunen 2006
  // Lee & Baek 2013, Eq. 11 exactly as printed: centre −10/3, edges 1/2, corners 1/4. Kept as
  // printed (not repaired): its weights sum to −1/3, which the consistency analysis reports.
  if (name == "paper_eq11") return Stencil{name, -10.0 / 3, 0.5, 0.25};
  throw std::invalid_argument("unknown stencil '" + name + "'");
}

}  // namespace stoneskip
