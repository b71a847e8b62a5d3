#include "tools/io/number_text.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace stoneskip {

namespace {
std::string g(double v, int digits) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*g", digits, v);
  return b;
}
}  // namespace

std::pair<std::string, std::string> numbers_apart(double a, double b, int digits) {
  int d = digits;
  // %.17g tells any two different doubles apart (IEEE 754 binary64: 17 significant digits round-trip).
  if (a != b)
    while (d < 17 && g(a, d) == g(b, d)) ++d;
  return {g(a, d), g(b, d)};
}

std::string at_most(double x, int digits) {
  if (!(x > 0) || !std::isfinite(x)) return g(x, digits);
  std::string text = g(x, digits);
  // Printed to the nearest: where that is above x, one unit in x's own last digit less. The unit
  // comes from x's decimal exponent (%e at 17 digits), not the printed value's: 0.09999 at 3 digits
  // prints 0.1, and a unit read from 0.1 would give 0.099, a digit short of 0.0999.
  char e[64];
  std::snprintf(e, sizeof e, "%.16e", x);
  const int exponent = std::atoi(std::strchr(e, 'e') + 1);
  const double unit = std::pow(10.0, exponent - (digits - 1));
  for (int i = 0; i < 4; ++i) {
    const double shown = std::strtod(text.c_str(), nullptr);
    if (shown <= x) break;
    text = g(shown - unit, digits);
  }
  return text;
}

}  // namespace stoneskip
