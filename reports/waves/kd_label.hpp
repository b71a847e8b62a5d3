#pragma once
// A wavenumber kd written in units of π for the waves report's prose, tables and figures: "π/8"
// where kd is π over a whole number (to 1e-9), otherwise its decimal multiple ("0.3π"). Rounding
// to π/n wrote kd = 0.3π as "π/3" and 0.7π as "π".
#include <cmath>
#include <cstdio>
#include <string>

namespace stoneskip {

inline std::string pi_fraction(double kd) {
  const double over_pi = kd / M_PI;
  if (over_pi > 0) {
    const long denom = std::lround(1 / over_pi);
    if (denom >= 1 && std::abs(over_pi * static_cast<double>(denom) - 1) <= 1e-9)
      return denom == 1 ? "π" : "π/" + std::to_string(denom);
  }
  char b[32];
  std::snprintf(b, sizeof b, "%.4gπ", over_pi);
  return b;
}

}  // namespace stoneskip
