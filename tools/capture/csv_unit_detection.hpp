#pragma once
// The unit of a CSV capture's accelerations or angular rates where its header gives none, read
// from the data, as the time column's is from its intervals (header_csv.hpp). A phone or IMU
// logger writes m/s² and rad/s as often as g and deg/s; read in the wrong unit, a capture at rest
// reads 9.8 g (clipped everywhere, no still part) or its swing 57 times too slow, with no word why.
#include <array>
#include <string>
#include <vector>

#include "tools/capture/csv_columns.hpp"

namespace stoneskip {

inline constexpr double kStandardGravity = 9.80665;  // m/s² in 1 g (CGPM 1901)

struct DetectedCsvUnit {
  CsvUnit unit = CsvUnit::none;
  std::string how;  // for the notes: what decided it
};

// Accelerations: a capture is at rest or near it most of the time (the analysis needs a still part
// before the swing), so the median of |a| over the rows is about gravity: 1 in g, 9.81 in m/s².
// Median |a| in [0.5, 2]: g; in [0.5, 2] × 9.80665: m/s²; otherwise g, the default, and the note
// says that neither fits. Rows with a non-finite value are left out.
DetectedCsvUnit detect_acceleration_unit(const std::vector<std::array<double, 3>>& accel);

// Angular rates (stoneskip-sign rate columns): the largest |component|. A throw's swing turns the
// wrist at 300–2000 deg/s (5–35 rad/s; the MotionPlus reads at most 2000 deg/s); a largest rate in
// [1, 40] is such a swing in rad/s (in deg/s the remote all but still: no throw to read); otherwise
// deg/s, the default. Rows with a non-finite value are left out.
DetectedCsvUnit detect_rate_unit(const std::vector<std::array<double, 3>>& rates);

}  // namespace stoneskip
