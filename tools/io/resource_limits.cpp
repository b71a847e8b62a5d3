#include "tools/io/resource_limits.hpp"

#include <cmath>
#include <cstdio>

#include "tools/io/input_error.hpp"

namespace stoneskip {

namespace {
std::string sci(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}
}  // namespace

void ResourceEstimate::add_memory(double bytes, const std::string& what) {
  memory_bytes += bytes;
  if (!what.empty()) memory_detail += (memory_detail.empty() ? "" : ", ") + what;
}

void ResourceEstimate::add_work(double count, double limit, const std::string& what) { work.push_back({what, count, limit}); }

namespace {
std::string bytes_to(double bytes, int digits) {
  const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  int u = 0;
  while (std::isfinite(bytes) && bytes >= 1000 && u < 6) {
    bytes /= 1000;
    ++u;
  }
  char b[48];
  std::snprintf(b, sizeof b, "%.*g %s", digits, bytes, units[u]);
  return b;
}
}  // namespace

std::string human_bytes(double bytes) { return bytes_to(bytes, 3); }

void enforce_limits(const ResourceEstimate& e, const ResourceLimits& limits, const std::string& where) {
  if (!(e.memory_bytes <= limits.max_memory_bytes)) {
    // As many digits as it takes to tell the need from the limit ("8 GB, above the limit of 8 GB").
    int digits = 3;
    while (digits < 12 && bytes_to(e.memory_bytes, digits) == bytes_to(limits.max_memory_bytes, digits)) ++digits;
    throw_input_error(where, 0, "",
                      "needs about " + bytes_to(e.memory_bytes, digits) + " of memory (" + e.memory_detail +
                          "), above the limit of " + bytes_to(limits.max_memory_bytes, digits) +
                          " (cases/README.md, Limits); --max-memory-gb raises it");
  }
  if (limits.allow_large) {
    // Still refuse what cannot be counted: a NaN or infinite estimate is a broken input.
    for (const auto& w : e.work)
      if (!std::isfinite(w.count)) throw_input_error(where, 0, "", "the work cannot be estimated: " + w.what);
    return;
  }
  for (const auto& w : e.work)
    if (!(w.count <= w.limit))
      throw_input_error(where, 0, "",
                        "about " + sci(w.count) + " " + w.what + ", above the limit of " + sci(w.limit) +
                            " (cases/README.md, Limits); --allow-large lifts it");
}

}  // namespace stoneskip
