#pragma once
// The design of a sweep: which values each varied parameter takes, throw by throw.
//
//   grid             the full tensor product of per-axis grids; axis k has count_k points from
//                    `from` to `to`, equally spaced (linear) or in constant ratio (log:
//                    x_i = from · (to/from)^(i/(count−1))). Throw index = row-major position,
//                    the first axis varying slowest (nested loops in the order the axes are given).
//   random           `samples` independent points, each coordinate uniform on [from, to) (log:
//                    uniform in ln x).
//   latin_hypercube  `samples` points such that each axis, cut into `samples` equal strata
//                    (equal in ln x on a log axis), has exactly one point in every stratum
//                    (McKay, Beckman & Conover 1979): a random permutation of the strata per
//                    axis, a uniform position inside each stratum.
//
// Every value is a pure function of (seed, throw index, axis): no generator state is carried from
// one throw to the next, so any process can compute any throw's point, in any order, and get the
// same bits (the counter-based hash is SplitMix64's finaliser, Steele, Lea & Flood 2014).
#include <cstdint>
#include <string>
#include <vector>

namespace stoneskip {

enum class AxisScale { linear, log };
const char* to_string(AxisScale s);
bool parse_axis_scale(const std::string& s, AxisScale& out);

enum class DesignKind { grid, random, latin_hypercube };
const char* to_string(DesignKind k);
bool parse_design_kind(const std::string& s, DesignKind& out);

struct SweepAxis {
  std::string key;        // the case key it varies, e.g. "throw.speed_m_s"
  double from = 0, to = 0;
  long long count = 0;    // grid points (grid designs only)
  AxisScale scale = AxisScale::linear;
};

// What is wrong with a design, and where: axis −1 is the [design] table itself.
struct DesignProblem {
  int axis = -1;
  std::string key;        // the offending key of that table ("count", "from", "samples", ...)
  std::string what;
};

struct SweepDesign {
  DesignKind kind = DesignKind::grid;
  std::vector<SweepAxis> axes;
  long long samples = 0;  // random designs
  std::uint64_t seed = 0; // random designs

  // Ceres-style self check: false with the first problem found.
  bool is_valid(DesignProblem* problem) const;
  // Number of throws: Π count (grid) or samples.
  std::size_t size() const;
  // The varied values of throw `index` (0 ≤ index < size()), one per axis.
  std::vector<double> point(std::size_t index) const;
  // The distinct values of one axis of a grid, ascending (grid designs only).
  std::vector<double> grid_values(std::size_t axis) const;
};

// Largest number of throws a design may have (the result table is held in memory by rank 0).
constexpr std::size_t kMaxSweepThrows = std::size_t{1} << 32;

// The unit value u ∈ (0, 1) that the random designs draw for (seed, throw, axis): 53 random bits.
double unit_draw(std::uint64_t seed, std::uint64_t index, std::uint64_t axis, std::uint64_t stream);

}  // namespace stoneskip
