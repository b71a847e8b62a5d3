#pragma once
// A sweep file (TOML, documented in cases/README.md, "Sweep files") resolved into the sweep's
// design and solvers, and the cases of its throws.
//
//   base = "../paper_8ms_spin.toml"   # the base stone case, relative to the sweep file
//   set = ["environment.convention=paper"]   # optional: fixed overrides of the base (as --set)
//   solvers = ["realtime"]            # "realtime" and/or "reference" (default: realtime)
//   title = "..."                     # optional (default: the file's stem); description optional
//   [design]
//   kind = "grid"                     # "grid" | "random" | "latin_hypercube"
//   samples = 1000                    # random designs only: number of throws
//   seed = 2024                       # random designs only: an integer >= 0
//   [[vary]]                          # one table per varied parameter
//   key = "throw.speed_m_s"           # any numeric key of the stone case
//   from = 4.0
//   to = 12.0
//   count = 41                        # grids only: points on this axis
//   scale = "linear"                  # or "log" (from > 0)
//
// Every error is one line naming the sweep file, the line and the key; nothing is computed before
// the whole file, the base case and the design's extreme points have been checked.
#include <string>
#include <vector>

#include "tools/io/resource_limits.hpp"
#include "tools/scene/stone_case.hpp"
#include "verification/sweep/design.hpp"
#include "verification/sweep/throw_record.hpp"

namespace stoneskip {

struct SweepFile {
  std::string file;                    // path as given
  std::string text;                    // the sweep file's text, attached to the result
  std::string title;
  std::string base_file;               // resolved against the sweep file's folder
  long base_line = 0;
  std::vector<std::string> base_sets;  // `set`: fixed overrides applied to the base case
  long set_line = 0;
  std::vector<long> set_lines;         // the line of each `set` entry (an array may span lines)
  SweepSolvers solvers = SweepSolvers::realtime;
  long solvers_line = 0;
  SweepDesign design;
  std::vector<long> axis_lines;        // the line of each [[vary]] table's key
};

SweepFile load_sweep_file(const std::string& path);
SweepFile sweep_file_from_text(const std::string& text, const std::string& name);

// The value of a varied key as a `--set` assignment: "key=<TOML number>" that reads back as the
// same double (an integer literal for whole values, so integer keys such as stone.segments work).
std::string sweep_override(const std::string& key, double value);

// The cases of a sweep's throws. The base case is parsed once, with the sweep's `set`; a throw's
// case is a copy of that document with the throw's values set where --set would put them
// (set_value, as integers when whole) and read by the case reader, so a throw is exactly
// `stoneskip run BASE --set ... --set key=value ...` (sweep_override gives those assignments).
class SweepCases {
 public:
  // Loads the base case and builds the cases at the design's extreme points (every corner of the
  // box, up to 10 varied keys; each key's extremes beyond) and at its first throws: a key that is
  // not numeric, a value the case refuses, or a reference solver on live water fails here, with
  // the sweep file's line.
  explicit SweepCases(const SweepFile& sweep);
  const StoneCase& base() const { return base_; }
  StoneCase at(const std::vector<double>& point) const;
  // The largest one-throw estimate (tools/scene/resource_estimate.hpp) over the cases built above,
  // item by item: what the limits of a whole sweep are computed from.
  const ResourceEstimate& heaviest_throw() const { return heaviest_throw_; }

 private:
  ResourceEstimate heaviest_throw_;
  SweepFile sweep_;
  TomlDocument base_doc_;
  StoneCase base_;
};

}  // namespace stoneskip
