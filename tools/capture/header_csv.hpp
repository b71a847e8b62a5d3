#pragma once
// The header-driven CSV reader (format "csv"; tools/capture/README.md, "Header-driven CSV"): any
// CSV file whose first line (after "# key: value" header comments, capture_header.hpp) names its
// columns. Columns are found by name (csv_columns.hpp: case, spaces, units and device suffixes
// tolerated), or mapped with --columns; unrecognised columns are ignored and listed in the notes.
//
//   * separator: ',' ';' or tab, whichever the column line has most of; a field may be quoted;
//   * times: the header's unit, else the median interval decides (below 0.5: seconds, 0.5–500:
//     milliseconds, above: microseconds); made relative to the first row. No time column: the
//     nominal rate (# nominal_rate_hz, default 100 Hz) and a caveat;
//   * several remotes: columns with a "#WM2"-style suffix belong to that remote, columns without a
//     suffix to every remote; --remote N picks one, the default is the lowest-numbered one with
//     data (a non-empty, non-zero acceleration or rate). Rows where the chosen remote's values are
//     empty, or unchanged from its previous row in a file with several remotes (a row written for
//     another remote), are skipped and counted in the notes;
//   * angular rate, first source present: MotionPlus raw words (hex unless [dec]; the range mode
//     from slow/fast columns, else from WiiYourself!'s Speed columns where they follow its
//     conversion, else inferred from jumps, gyro_range.hpp); stoneskip-sign rates (wx, wy, wz);
//     WiiYourself! Speed columns (negated: WiiYourself! reports −(raw − 0x1F7F)·scale);
//   * buttons: a WiiYourself! Button.Bits word (B 0x0400, A 0x0800; hex unless [dec]) or 0/1
//     columns per button; none: the release is the file's end (a caveat);
//   * accelerations in g (or m/s² by unit) are taken as calibrated by the logger.
// Strict: a field that does not parse, a row with the wrong number of fields, time going backwards,
// a unit a column does not allow, two columns for the same quantity, an incomplete axis set, are
// InputErrors naming the file, the line and the column.
#include <string>
#include <vector>

#include "verification/captures/capture_trace.hpp"

namespace stoneskip {

struct HeaderCsvOptions {
  int remote = 0;        // 0: the first with data; else the "#WMn" number
  std::string columns;   // "--columns": key[unit]=Header Name,… (csv_columns.hpp keys)
};

// True when the line looks like a column line this reader can use (at least two recognised
// columns, one of them an acceleration or an angular rate).
bool is_header_csv_column_line(const std::string& line);

Trace read_header_csv(const std::string& text, const std::string& file, const HeaderCsvOptions& options = {});

}  // namespace stoneskip
