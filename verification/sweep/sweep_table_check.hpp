#pragma once
// A sweep result's /throws table read back against what a sweep writes (throw_record.hpp), so that
// a hand-edited or damaged table is refused before anything is drawn or counted from it: the
// columns are the record's for the file's axes and solvers, in order; row i is throw i; its varied
// values are the design's point i; each solver's outcome is a code of kOutcomeCodes; bounces and
// contacts are whole numbers, 0 ≤ bounces ≤ contacts (NaN where the throw did not run); and with
// both solvers the bounce and contact disagreements are real-time minus reference, NaN where either
// solve failed (or, in tables written before that rule, the difference); each solver's
// bounces_before_short_flight a count of at most its bounces, NaN exactly where
// shortest_resolved_flight_s is (tables written before those columns are read without them).
#include <string>

#include "tools/io/hdf5_file.hpp"
#include "verification/sweep/design.hpp"
#include "verification/sweep/throw_record.hpp"

namespace stoneskip {

// Throws InputError "FILE: throws.COLUMN: throw I: what is wrong" at the first problem found.
void check_sweep_table(const std::string& file, const SweepDesign& design, SweepSolvers solvers, const Table& throws);

}  // namespace stoneskip
