#pragma once
// The work-precision grid's record (work_precision_grid_findings), read back from data.h5, is
// checked before the stones report prints it: every value its prose, table and findings line print
// that follows from other stored values is derived again from them and compared.
//   * the summary table: whole counts, 0 ≤ agreeing + failed ≤ n = the kept throws, timed ≤ n, the
//     agreement agreeing/n and its Wilson interval (work_precision_grid_stats.hpp), a median
//     contact-time error between 0 and the largest (NaN when no contact list matched), finite
//     non-negative work, a forced-step share in [0, 1];
//   * the throws: their count, the kept and set-aside ones against the stored tallies and lists;
//   * the failures and the adaptive family's disagreements listed, against the counts;
//   * the default tolerance and the real-time budget chosen again by their rules
//     (choose_grid_default, choose_grid_budget) from the stored summary table and the stored rule:
//     every number, phrase and the reason text they print, and the per-budget CPU bounds.
// Equal means to 1e-12 relative (the same code on the same doubles gives the same bits; the margin
// only keeps a check from depending on that). A hand-edited record, or parts of two runs, is
// refused instead of printed: `report render` says so in one line (tools/cli/report_render.cpp).
#include "verification/study/record.hpp"

namespace stoneskip {

// Throws RecordError "<record path>: <what> is <stored> but <expected> follows from the stored
// data" (or names the missing or malformed value) at the first inconsistency.
void check_work_precision_grid_record(const Record& grid);

}  // namespace stoneskip
