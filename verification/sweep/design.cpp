#include "verification/sweep/design.hpp"

#include <cmath>
#include <limits>
#include <set>
#include <sstream>

namespace stoneskip {

const char* to_string(AxisScale s) { return s == AxisScale::log ? "log" : "linear"; }

bool parse_axis_scale(const std::string& s, AxisScale& out) {
  if (s == "linear") out = AxisScale::linear;
  else if (s == "log") out = AxisScale::log;
  else return false;
  return true;
}

const char* to_string(DesignKind k) {
  switch (k) {
    case DesignKind::grid: return "grid";
    case DesignKind::random: return "random";
    case DesignKind::latin_hypercube: return "latin_hypercube";
  }
  return "?";
}

bool parse_design_kind(const std::string& s, DesignKind& out) {
  if (s == "grid") out = DesignKind::grid;
  else if (s == "random") out = DesignKind::random;
  else if (s == "latin_hypercube") out = DesignKind::latin_hypercube;
  else return false;
  return true;
}

namespace {

// SplitMix64's output function (Steele, Lea & Flood 2014): a bijective 64-bit mixer.
std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::uint64_t hash4(std::uint64_t a, std::uint64_t b, std::uint64_t c, std::uint64_t d) {
  return mix(mix(mix(mix(a) ^ b) ^ c) ^ d);
}

// A keyed pseudo-random permutation of {0, …, n−1}: a 6-round balanced Feistel network on the
// smallest even-width binary domain 2^(2h) ≥ n, walked until it lands inside [0, n) (cycle
// walking, Black & Rogaway 2002). A bijection, computed per element without storing the
// permutation.
std::uint64_t permute(std::uint64_t x, std::uint64_t n, std::uint64_t key) {
  int h = 1;
  while ((std::uint64_t{1} << (2 * h)) < n) ++h;
  const std::uint64_t mask = (std::uint64_t{1} << h) - 1;
  do {
    std::uint64_t left = x >> h, right = x & mask;
    for (std::uint64_t round = 0; round < 6; ++round) {
      const std::uint64_t f = hash4(key, round, right, 0x5eed) & mask;
      const std::uint64_t next = left ^ f;
      left = right;
      right = next;
    }
    x = (left << h) | right;
  } while (x >= n);
  return x;
}

// u ∈ [0, 1] → [from, to], uniformly in x (linear) or in ln x (log).
double map_unit(const SweepAxis& a, double u) {
  if (a.from == a.to) return a.from;
  if (a.scale == AxisScale::log) return std::exp(std::log(a.from) + u * (std::log(a.to) - std::log(a.from)));
  return a.from + u * (a.to - a.from);
}

// Grid value i of count: endpoints exact, linear in x or in ln x between them.
double grid_value(const SweepAxis& a, long long i) {
  if (a.count <= 1 || i == 0) return a.from;
  if (i == a.count - 1) return a.to;
  const double t = static_cast<double>(i) / static_cast<double>(a.count - 1);
  if (a.scale == AxisScale::log) {
    // A value within round-off of a whole number is that number (1, 10, 100, 1000 come out as
    // 9.999999999999998 …): an integer key must get whole values. 8 ulps: pow's error, a few ulps.
    const double v = a.from * std::pow(a.to / a.from, t);
    const double whole = std::round(v);
    return std::abs(v - whole) <= 8 * std::numeric_limits<double>::epsilon() * std::abs(v) ? whole : v;
  }
  // from + i·(to − from)/(count − 1): whole when the exact value is (i·(to − from) and its quotient
  // are exact), where from·(1 − t) + to·t gave 14.999999999999998 for 3…30 in 28 points; the
  // old form only where the span overflows (±1e308).
  const double span = a.to - a.from;
  const double v = a.from + static_cast<double>(i) * span / static_cast<double>(a.count - 1);
  return std::isfinite(v) ? v : a.from * (1 - t) + a.to * t;
}

}  // namespace

double unit_draw(std::uint64_t seed, std::uint64_t index, std::uint64_t axis, std::uint64_t stream) {
  const std::uint64_t bits = hash4(seed, index, axis, stream) >> 11;  // 53 bits
  return (static_cast<double>(bits) + 0.5) * 0x1.0p-53;              // never 0, never 1
}

bool SweepDesign::is_valid(DesignProblem* problem) const {
  auto fail = [&](int axis, const std::string& key, const std::string& what) {
    if (problem) *problem = DesignProblem{axis, key, what};
    return false;
  };
  if (axes.empty()) return fail(-1, "vary", "no parameter to vary (give at least one [[vary]] table)");
  std::set<std::string> keys;
  double throws = 1;
  for (std::size_t k = 0; k < axes.size(); ++k) {
    const SweepAxis& a = axes[k];
    const int i = static_cast<int>(k);
    if (a.key.empty()) return fail(i, "key", "must name a case key, e.g. \"throw.speed_m_s\"");
    if (!keys.insert(a.key).second) return fail(i, "key", "\"" + a.key + "\" is varied twice");
    if (!std::isfinite(a.from)) return fail(i, "from", "must be a finite number");
    if (!std::isfinite(a.to)) return fail(i, "to", "must be a finite number");
    if (a.from > a.to) {
      std::ostringstream s;
      s << "from (" << a.from << ") must not exceed to (" << a.to << ")";
      return fail(i, "to", s.str());
    }
    if (a.scale == AxisScale::log && !(a.from > 0)) {
      std::ostringstream s;
      s << "a log axis needs from > 0 (got " << a.from << ")";
      return fail(i, "from", s.str());
    }
    if (kind == DesignKind::grid) {
      if (a.count <= 0) return fail(i, "count", "must be >= 1 (got " + std::to_string(a.count) + ")");
      if (a.count == 1 && a.from != a.to) return fail(i, "count", "a single grid point needs from = to");
      if (a.count > 1 && a.from == a.to)
        return fail(i, "to", "must exceed from for " + std::to_string(a.count) +
                                 " grid points (from = to gives identical throws; give count = 1 for one)");
      throws *= static_cast<double>(a.count);
    }
  }
  if (kind != DesignKind::grid) {
    if (samples <= 0) return fail(-1, "samples", "must be >= 1 (got " + std::to_string(samples) + ")");
    throws = static_cast<double>(samples);
  }
  if (throws > static_cast<double>(kMaxSweepThrows)) {
    std::ostringstream s;
    s << "the design has " << throws << " throws, more than the " << kMaxSweepThrows << " a sweep file may hold";
    return fail(kind == DesignKind::grid ? 0 : -1, kind == DesignKind::grid ? "count" : "samples", s.str());
  }
  return true;
}

std::size_t SweepDesign::size() const {
  if (kind != DesignKind::grid) return static_cast<std::size_t>(samples);
  std::size_t n = 1;
  for (const auto& a : axes) n *= static_cast<std::size_t>(a.count);
  return axes.empty() ? 0 : n;
}

std::vector<double> SweepDesign::point(std::size_t index) const {
  std::vector<double> p(axes.size());
  switch (kind) {
    case DesignKind::grid: {
      std::size_t rest = index;  // row-major: the last axis varies fastest
      for (std::size_t k = axes.size(); k-- > 0;) {
        const auto n = static_cast<std::size_t>(axes[k].count);
        p[k] = grid_value(axes[k], static_cast<long long>(rest % n));
        rest /= n;
      }
      break;
    }
    case DesignKind::random:
      for (std::size_t k = 0; k < axes.size(); ++k) p[k] = map_unit(axes[k], unit_draw(seed, index, k, 0));
      break;
    case DesignKind::latin_hypercube: {
      const auto n = static_cast<std::uint64_t>(samples);
      for (std::size_t k = 0; k < axes.size(); ++k) {
        const std::uint64_t stratum = permute(index, n, hash4(seed, k, 0x1a7, 0));
        p[k] = map_unit(axes[k], (static_cast<double>(stratum) + unit_draw(seed, index, k, 1)) / static_cast<double>(n));
      }
      break;
    }
  }
  return p;
}

std::vector<double> SweepDesign::grid_values(std::size_t axis) const {
  std::vector<double> v;
  const SweepAxis& a = axes.at(axis);
  for (long long i = 0; i < a.count; ++i) v.push_back(grid_value(a, i));
  return v;
}

}  // namespace stoneskip
