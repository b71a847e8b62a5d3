// The units of a CSV capture's accelerations and rates where the header gives none. Oracles: the
// documented rules (csv_unit_detection.hpp: gravity's size at rest; the largest rate a rad/s swing
// can have), and the same readings written with their units.
#include "tools/capture/csv_unit_detection.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "tools/capture/capture_format.hpp"
#include "tools/capture/synthetic_capture.hpp"

using namespace stoneskip;

namespace {
constexpr double kG = 9.80665;  // m/s² in 1 g
const double kNaN = std::numeric_limits<double>::quiet_NaN();

// n rows at rest (gravity along z, in `unit_g` per g) and a swing of m rows of 3 g.
std::vector<std::array<double, 3>> at_rest_then_swing(int n, int m, double unit_g) {
  std::vector<std::array<double, 3>> a(n, {0.01 * unit_g, -0.02 * unit_g, 1.0 * unit_g});
  for (int i = 0; i < m; ++i) a.push_back({3 * unit_g, 0, 0.5 * unit_g});
  return a;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(csv_unit_detection)

BOOST_AUTO_TEST_CASE(accelerations_at_rest_tell_g_from_metres_per_second_squared) {
  BOOST_TEST(to_string(detect_acceleration_unit(at_rest_then_swing(80, 20, 1)).unit) == std::string("g"));
  BOOST_TEST(to_string(detect_acceleration_unit(at_rest_then_swing(80, 20, kG)).unit) == std::string("m/s2"));
  // The band's edges (median |a| within a factor of 2 of gravity): 0.5 and 2 g, 4.9 and 19.6 m/s².
  BOOST_TEST(to_string(detect_acceleration_unit({{0, 0, 0.5}}).unit) == std::string("g"));
  BOOST_TEST(to_string(detect_acceleration_unit({{0, 0, 2.0}}).unit) == std::string("g"));
  BOOST_TEST(to_string(detect_acceleration_unit({{0, 0, kG / 2}}).unit) == std::string("m/s2"));
  BOOST_TEST(to_string(detect_acceleration_unit({{0, 0, 2 * kG}}).unit) == std::string("m/s2"));
  // Gravity removed (a "linear acceleration"), or mg: neither; g stands, and the note says so.
  const DetectedCsvUnit none = detect_acceleration_unit({{0.01, 0.02, 0.0}, {0.0, 0.03, 0.01}, {0.02, 0.0, 0.0}});
  BOOST_TEST(to_string(none.unit) == std::string("g"));
  BOOST_TEST(none.how.find("neither") != std::string::npos, none.how);
  BOOST_TEST(none.how.find("gravity removed") != std::string::npos, none.how);
  const DetectedCsvUnit milli = detect_acceleration_unit({{0, 0, 1000}});
  BOOST_TEST(milli.how.find("neither") != std::string::npos, milli.how);
  BOOST_TEST(milli.how.find("gravity removed") == std::string::npos, milli.how);
  // Rows with a missing value are left out; no rows at all: the default.
  BOOST_TEST(to_string(detect_acceleration_unit({{kNaN, 0, 50}, {0, 0, kG}, {0, 0.1, kG}}).unit) == std::string("m/s2"));
  BOOST_TEST(to_string(detect_acceleration_unit({}).unit) == std::string("g"));
}

BOOST_AUTO_TEST_CASE(a_swing_in_radians_per_second_is_told_from_one_in_degrees) {
  auto unit = [](double largest) {
    return std::string(to_string(detect_rate_unit({{0.01, -0.02, 0.0}, {0.5, largest, -0.3}}).unit));
  };
  BOOST_TEST(unit(14.6) == "rad/s");   // a 14 rad/s swing
  BOOST_TEST(unit(-14.6) == "rad/s");  // whatever its sign
  BOOST_TEST(unit(838) == "deg/s");    // the same swing in deg/s
  BOOST_TEST(unit(40) == "rad/s");     // the edges: 1 and 40
  BOOST_TEST(unit(40.5) == "deg/s");
  BOOST_TEST(unit(1) == "rad/s");
  BOOST_TEST(unit(0.9) == "deg/s");    // all but still in either unit: the default
  BOOST_TEST(std::string(to_string(detect_rate_unit({{kNaN, 500, 0}, {0, 14, 0}}).unit)) == "rad/s");
  BOOST_TEST(std::string(to_string(detect_rate_unit({}).unit)) == "deg/s");
}

BOOST_AUTO_TEST_CASE(a_capture_written_in_si_units_without_them_reads_as_the_same_capture_with_them) {
  // Oracle: the same synthetic readings written with their units (g, deg/s) in the header. Without
  // units, in m/s² and rad/s (a phone or IMU logger's), main read them as g and deg/s: at rest 9.8
  // "g", clipped throughout, no still part, the capture unusable with no word of the unit.
  SyntheticTruth truth;
  const Trace log = parse_capture(synthetic_report_log(SyntheticThrow{}, SyntheticSensor{}, truth), "throw.log");
  std::string with = "time (s),ax (g),ay (g),az (g),wx (deg/s),wy (deg/s),wz (deg/s),btn_b\n";
  std::string without = "timestamp,accelerometerX,accelerometerY,accelerometerZ,gyroscopeX,gyroscopeY,gyroscopeZ,buttonB\n";
  constexpr double kDeg = 180 / 3.14159265358979323846;
  for (const TraceSample& x : log.samples) {
    char row[320];
    const int b = (x.buttons & kButtonB) ? 1 : 0;
    std::snprintf(row, sizeof row, "%.9f,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%d\n", x.t_s, x.accel_g.x(), x.accel_g.y(),
                  x.accel_g.z(), x.rate_deg_s.x(), x.rate_deg_s.y(), x.rate_deg_s.z(), b);
    with += row;
    std::snprintf(row, sizeof row, "%.9f,%.12g,%.12g,%.12g,%.12g,%.12g,%.12g,%d\n", x.t_s, kG * x.accel_g.x(),
                  kG * x.accel_g.y(), kG * x.accel_g.z(), x.rate_deg_s.x() / kDeg, x.rate_deg_s.y() / kDeg,
                  x.rate_deg_s.z() / kDeg, b);
    without += row;
  }
  const Trace a = parse_capture(with, "with.csv"), b = parse_capture(without, "without.csv");
  BOOST_REQUIRE(a.samples.size() == b.samples.size());
  // Twelve significant digits written, and one conversion each way: agreement to 1e-10 relative.
  constexpr double kWritten = 1e-10;
  double accel = 0, rate = 0;
  for (std::size_t k = 0; k < a.samples.size(); ++k) {
    accel = std::max(accel, (a.samples[k].accel_g - b.samples[k].accel_g).norm() / (1 + a.samples[k].accel_g.norm()));
    rate = std::max(rate, (a.samples[k].rate_deg_s - b.samples[k].rate_deg_s).norm() / (1 + a.samples[k].rate_deg_s.norm()));
    BOOST_TEST(a.samples[k].gyro_fast == b.samples[k].gyro_fast);
  }
  BOOST_TEST(accel <= kWritten);
  BOOST_TEST(rate <= kWritten);
  auto note = [](const Trace& t, const std::string& part) {
    for (const std::string& n : t.notes)
      if (n.find(part) != std::string::npos) return n;
    return std::string();
  };
  BOOST_TEST(note(b, "accelerations in m/s2 (no unit in the header: detected from the median |a|") != "");
  BOOST_TEST(note(b, "angular rates in rad/s (no unit in the header: detected from the largest rate") != "");
  BOOST_TEST(note(a, "accelerations in").empty());  // the header's units: nothing detected
  BOOST_TEST(note(a, "angular rates in").empty());
}

BOOST_AUTO_TEST_SUITE_END()
