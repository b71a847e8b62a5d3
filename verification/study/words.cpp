#include "verification/study/words.hpp"

#include <cmath>
#include <cstdio>

namespace stoneskip {

std::string num(double value, int significant) {
  if (std::isnan(value)) return "–";
  if (std::isinf(value)) return value > 0 ? "∞" : "−∞";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", significant, value);
  return buf;
}

}  // namespace stoneskip
