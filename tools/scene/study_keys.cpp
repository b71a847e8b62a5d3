#include "tools/scene/study_keys.hpp"

#include <sstream>

namespace stoneskip {

std::vector<double> positive_list(TomlTable& t, const std::string& key, const std::vector<double>& fallback) {
  std::vector<double> v = any_list(t, key, fallback);
  for (double x : v)
    if (!(x > 0)) t.fail(key, "every value must be > 0");
  return v;
}

std::vector<double> any_list(TomlTable& t, const std::string& key, const std::vector<double>& fallback) {
  auto v = t.maybe_numbers(key);
  if (!v) return fallback;
  if (v->empty()) t.fail(key, "must not be empty");
  return *v;
}

std::vector<double> refining_fractions(TomlTable& t, const std::string& key, const std::vector<double>& fallback, std::size_t least,
                                       const std::string& of_what) {
  std::vector<double> v = positive_list(t, key, fallback);
  if (v.size() < least) t.fail(key, "needs at least " + std::to_string(least) + " (each compared with the one before)");
  for (std::size_t i = 0; i < v.size(); ++i)
    if (v[i] > 1 || (i > 0 && !(v[i] < v[i - 1])))
      t.fail(key, "fractions of " + of_what + " in (0, 1], decreasing strictly (coarse to fine)");
  return v;
}

double positive(TomlTable& t, const std::string& key, double fallback) {
  const double v = t.number_or(key, fallback);
  t.require_positive(key, v);
  return v;
}

long long count_in(TomlTable& t, const std::string& key, long long fallback, long long lo, long long hi) {
  const long long v = t.integer_or(key, fallback);
  if (v < lo || v > hi) t.fail(key, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return v;
}

std::vector<double> from_to_step(TomlTable& t, const std::string& key, double from, double to, double step,
                                 double max_values) {
  if (!(step > 0)) t.fail(key, "the step must be > 0");
  if (!(to >= from)) t.fail(key, "to must be >= from");
  if ((to - from) / step > max_values - 1) t.fail(key, "more than " + std::to_string(static_cast<long long>(max_values)) + " values");
  std::vector<double> out;
  for (double x = from; x <= to + 1e-9 * step; x += step) {
    if (!(x + step > x)) {
      std::ostringstream m;
      m << "the step " << step << " is below the values' resolution (adding it leaves " << x << " unchanged)";
      t.fail(key, m.str());
    }
    out.push_back(x);
  }
  return out;
}

std::string study_preset(TomlTable& study, const std::string& kind) {
  const std::string k = study.string("kind");
  if (k != kind) study.fail("kind", "'" + k + "' is not a " + kind + " study (kind = \"" + kind + "\")");
  return study.string("preset");
}

}  // namespace stoneskip
