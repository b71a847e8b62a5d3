#include "tools/io/number_text.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

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
  // Printed to the nearest: where that is above x, one unit in the last printed digit less (log10
  // of the printed value, so that a power of ten read as just below it cannot skew the unit).
  for (int i = 0; i < 4; ++i) {
    const double shown = std::strtod(text.c_str(), nullptr);
    if (shown <= x) break;
    const double unit = std::pow(10.0, std::floor(std::log10(shown)) - (digits - 1));
    text = g(shown - unit, digits);
  }
  return text;
}

}  // namespace stoneskip
