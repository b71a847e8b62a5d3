#pragma once
// Limits decided before any work: each command estimates, from its validated inputs, the
// memory it will hold and the work it will do (steps, cell updates), and refuses — exit 2, the
// estimate in the message — when either exceeds the documented limit (cases/README.md, "Limits").
// The limits are deliberately generous for a 2-core laptop; `--max-memory-gb G` and
// `--allow-large` lift them for bigger machines and longer runs.
#include <string>
#include <vector>

namespace stoneskip {

constexpr double kDefaultMaxMemoryBytes = 8e9;  // 8 GB

struct ResourceLimits {
  double max_memory_bytes = kDefaultMaxMemoryBytes;  // --max-memory-gb
  bool allow_large = false;                          // --allow-large: lifts the work limits
};

// One kind of work: e.g. "stone steps × triangles" counted against its limit.
struct WorkEstimate {
  std::string what;     // "triangle-steps (t_max_s / contact_dt_s = 1e+06 steps × 44 triangles)"
  double count = 0;
  double limit = 0;
};

struct ResourceEstimate {
  double memory_bytes = 0;
  std::string memory_detail;  // what the memory holds, in words
  std::vector<WorkEstimate> work;
  void add_memory(double bytes, const std::string& what);
  void add_work(double count, double limit, const std::string& what);
};

// Throws InputError ("WHERE: needs about 22.5 GB of memory (...), above the limit of 8 GB; ...")
// naming the first estimate above its limit. NaN or infinite estimates count as above.
void enforce_limits(const ResourceEstimate& estimate, const ResourceLimits& limits, const std::string& where);

// "22.5 GB", "512 MB", "3 kB" (decimal units, three significant figures).
std::string human_bytes(double bytes);

}  // namespace stoneskip
