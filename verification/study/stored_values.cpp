#include "verification/study/stored_values.hpp"

#include <cmath>
#include <sstream>

namespace stoneskip {

namespace {
[[noreturn]] void refuse(const Record& r, const std::string& key, double x, const std::string& what) {
  std::ostringstream m;
  m.precision(17);
  m << (r.path().empty() ? std::string("/") : r.path()) << ": '" << key << "' must be " << what << " (got " << x << ")";
  throw RecordError(m.str());
}
}  // namespace

std::size_t stored_count(const Record& r, const std::string& key, std::size_t most) {
  const double x = r.number(key);
  if (!(x >= 0 && x <= static_cast<double>(most) && x == std::floor(x)))
    refuse(r, key, x, "a whole number in [0, " + std::to_string(most) + "]");
  return static_cast<std::size_t>(x);
}

double stored_finite(const Record& r, const std::string& key) {
  const double x = r.number(key);
  if (!std::isfinite(x)) refuse(r, key, x, "a finite number");
  return x;
}

double stored_in(const Record& r, const std::string& key, double lo, double hi) {
  const double x = r.number(key);
  if (!(x >= lo && x <= hi)) {
    std::ostringstream w;
    w.precision(17);
    w << "a number in [" << lo << ", " << hi << "]";
    refuse(r, key, x, w.str());
  }
  return x;
}

}  // namespace stoneskip
