// A clipped capture's direction is as uncertain as its speed. When the accelerometer clips, the
// throw takes the lever arm's velocity R (ω × lever arm), which misses the pivot's own motion: its
// size (the speed interval already runs to the accelerometer's bounds) and, where the pivot does
// not move along the arm's velocity, its direction. Oracle: the synthetic generator's closed-form
// motion (tools/capture/synthetic_capture.hpp), whose truth file gives the release's path and
// attack angles; the pivot's path raised 30° above the release direction (the trunk rising into
// the throw) tilts the true velocity away from the lever arm's. (A test of verification/captures
// that lives here because the synthetic generator is in tools/capture, above it.)
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tools/capture/capture_format.hpp"
#include "tools/capture/synthetic_capture.hpp"
#include "verification/captures/capture_analysis.hpp"

using namespace stoneskip;

BOOST_AUTO_TEST_SUITE(clipped_direction)

BOOST_AUTO_TEST_CASE(the_angle_intervals_of_a_clipped_capture_hold_a_pivot_that_rises) {
  SyntheticThrow th;  // a hard side-arm swing: 14 rad/s at 0.6 m clips the accelerometer
  th.pivot_speed_m_s = 4.0;
  th.pivot_elevation_deg = 30.0;
  SyntheticTruth truth;
  const Trace trace = parse_capture(synthetic_report_log(th, SyntheticSensor{}, truth), "rising_pivot.log");
  CaptureOptions o;
  o.members = 64;  // the members fill the clipped spans; the bounds join them
  const CaptureAnalysis a = analyse_capture(trace, o);
  BOOST_REQUIRE(a.nominal_computed);
  BOOST_REQUIRE(a.clipped);
  // The case is a hard one: the lever arm's own direction is off the truth by more than a degree.
  BOOST_TEST(std::abs(a.nominal.path_angle_deg - truth.path_angle_deg) > 1.0, a.nominal.path_angle_deg);
  BOOST_TEST(a.path_angle_deg.low <= truth.path_angle_deg,
             "[" << a.path_angle_deg.low << ", " << a.path_angle_deg.high << "] against " << truth.path_angle_deg);
  BOOST_TEST(a.path_angle_deg.high >= truth.path_angle_deg);
  BOOST_TEST(a.attack_angle_deg.low <= truth.attack_angle_deg,
             "[" << a.attack_angle_deg.low << ", " << a.attack_angle_deg.high << "] against " << truth.attack_angle_deg);
  BOOST_TEST(a.attack_angle_deg.high >= truth.attack_angle_deg);
  BOOST_TEST(a.speed_m_s.low <= truth.speed_m_s);
  BOOST_TEST(a.speed_m_s.high >= truth.speed_m_s);
}

BOOST_AUTO_TEST_SUITE_END()
