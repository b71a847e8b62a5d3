#pragma once
// A sweep's result file (HDF5), written whole by rank 0 at the end, and read back by
// `stoneskip sweep-plot` and the reports.
//
//   /             attributes: code_version, created_utc, title, sweep_file, sweep_text,
//                 base_case_file, base_case_text, base_overrides (the sweep's `set`, one per
//                 line), resolved_settings (the base case after `set`), solvers, throws,
//                 outcome_codes
//   /throws       table (attribute columns): one row per throw, in throw-index order
//                 (verification/sweep/throw_record.hpp lists the columns)
//   /design       attributes kind, samples, seed, axes; /design/axis_<k>: attributes key, from,
//                 to, count, scale, and for a grid the dataset `values` (its grid values)
//   /notes        datasets throw (ints), solver, detail (strings): failed solves, throws whose
//                 case could not be built, contacts begun off a walled pond
//   /run          attributes of the run that finished the file (not part of the result proper):
//                 ranks, master_threads, wall_s, throws_computed, throws_remote (by other
//                 ranks), throws_recovered (from the journal of an interrupted run),
//                 throws_per_s, chunks, max_chunk, master_cpu_s (rank 0's scheduling thread,
//                 idle polling included), master_busy_cpu_s (of which handling messages and
//                 rows), master_busy_cpu_per_throw_s, journal_wall_s
#include <filesystem>
#include <string>
#include <vector>

#include "tools/io/hdf5_file.hpp"
#include "verification/sweep/design.hpp"
#include "verification/sweep/scheduler.hpp"
#include "verification/sweep/throw_record.hpp"

namespace stoneskip {

struct SweepProvenance {
  std::string title;
  std::string sweep_file, sweep_text;
  std::string base_case_file, base_case_text;
  std::vector<std::string> base_overrides;
  std::string resolved_settings;
  // Files the rows depend on beyond the texts above, by content: "mesh PATH fnv1a64 HEX" lines.
  std::string input_files;
  std::string build;  // version and executable fingerprint of the build that computed the rows
  std::string code_version, created_utc;  // set when the file is written (read back only)
};

struct SweepRunInfo {
  ScheduleStats schedule;
  std::size_t throws_recovered = 0;
  double journal_wall_s = 0;
  std::size_t max_chunk = 0;
  std::string journal_damage;  // a damaged record mid-journal and the records dropped after it
};

struct SweepData {
  SweepDesign design;
  SweepSolvers solvers = SweepSolvers::realtime;
  SweepProvenance provenance;
  Table throws;
  std::vector<ThrowNote> notes;
  SweepRunInfo run;
};

void write_sweep_file(const std::filesystem::path& path, const SweepData& data);
// InputError naming the file when it is not a sweep result file, or one so damaged that reading
// it crashes or hangs the HDF5 library (read in a child first: tools/io/isolated_read.hpp).
SweepData read_sweep_file(const std::filesystem::path& path);

}  // namespace stoneskip
