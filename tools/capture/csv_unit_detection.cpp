#include "tools/capture/csv_unit_detection.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace stoneskip {

namespace {
// |a| at rest within a factor of 2 of gravity: a median outside it is no capture at rest in that unit.
constexpr double kGravityBand = 2.0;
// The largest rate a MotionPlus reads, 2000 deg/s, is 34.9 rad/s; a rad/s swing stays below 40.
constexpr double kLargestRadPerS = 40.0;
// Below 1 the largest rate is the remote all but still in either unit: the default stands.
constexpr double kSmallestSwingRadPerS = 1.0;

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

bool finite(const std::array<double, 3>& v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }
}  // namespace

DetectedCsvUnit detect_acceleration_unit(const std::vector<std::array<double, 3>>& accel) {
  std::vector<double> size;
  size.reserve(accel.size());
  for (const auto& a : accel)
    if (finite(a)) size.push_back(std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]));
  if (size.empty()) return {CsvUnit::g, "no unit in the header and no values: read as g"};
  std::nth_element(size.begin(), size.begin() + std::ptrdiff_t(size.size() / 2), size.end());
  const double median = size[size.size() / 2];
  const std::string m = "the median |a| " + num(median);
  if (median >= 1 / kGravityBand && median <= kGravityBand)
    return {CsvUnit::g, "no unit in the header: detected from " + m + ", gravity in g"};
  if (median >= kStandardGravity / kGravityBand && median <= kStandardGravity * kGravityBand)
    return {CsvUnit::m_s2, "no unit in the header: detected from " + m + ", gravity in m/s2"};
  // Near 0: gravity removed (a phone's "linear acceleration"), which no unit puts back.
  const std::string removed = median < 1 / kGravityBand
                                  ? "; near 0 it looks like gravity removed (a \"linear acceleration\"), which the "
                                    "analysis cannot use: it needs the accelerometer's reading, gravity included"
                                  : "";
  return {CsvUnit::g, "no unit in the header, and " + m +
                          " is gravity in neither g (about 1) nor m/s2 (about 9.8): read as g; give the unit "
                          "in the header or with --columns" + removed};
}

DetectedCsvUnit detect_rate_unit(const std::vector<std::array<double, 3>>& rates) {
  double largest = 0;
  bool any = false;
  for (const auto& w : rates)
    if (finite(w)) {
      any = true;
      largest = std::max({largest, std::abs(w[0]), std::abs(w[1]), std::abs(w[2])});
    }
  if (!any) return {CsvUnit::deg_s, "no unit in the header and no values: read as deg/s"};
  const std::string m = "the largest rate " + num(largest);
  if (largest >= kSmallestSwingRadPerS && largest <= kLargestRadPerS)
    return {CsvUnit::rad_s, "no unit in the header: detected from " + m +
                                ": a swing in rad/s, where a throw's is 5–35; in deg/s the remote would be all but still"};
  return {CsvUnit::deg_s, "no unit in the header: detected from " + m +
                              (largest > kLargestRadPerS ? ", beyond any swing in rad/s" : ", the remote all but still in either unit: read as deg/s")};
}

}  // namespace stoneskip
