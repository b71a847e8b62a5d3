// The whole capture path (report bytes → trace → timing → orientation → release state) against
// synthetic captures whose truth is known exactly (synthetic_capture.hpp).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>

#include "verification/captures/capture_analysis.hpp"
#include "tools/capture/capture_format.hpp"
#include "tools/capture/synthetic_capture.hpp"
#include "tools/io/input_error.hpp"

using namespace stoneskip;

namespace {
// The acceptance tolerances for an unclipped capture.
constexpr double kSpeedRelTol = 0.05;   // 5 % on the release speed
constexpr double kAngleTol_deg = 3.0;   // 3° on attack and path angles

CaptureOptions quick_options() {
  CaptureOptions o;
  o.members = 16;  // enough for the intervals these tests look at; keeps each test well under a second
  return o;
}

// A throw hard enough to clip a real remote, recorded by a hypothetical ±16 g accelerometer (30
// counts per g, so that ±16 g fits the 10-bit reading).
SyntheticSensor wide_range_sensor() {
  SyntheticSensor s;
  s.clip_g = 16.0;
  for (int i = 0; i < 3; ++i) s.accel_one_g_counts[i] = s.accel_zero_counts[i] + 30;
  return s;
}

// A gentle throw (Ω = 7 rad/s ≈ 400 deg/s) that a real ±3.6 g remote records without clipping
// while its MotionPlus still switches to fast mode.
SyntheticThrow gentle_throw() {
  SyntheticThrow th;
  th.swing_rate_rad_s = 7.0;
  th.pivot_speed_m_s = 1.0;
  return th;
}

void check_unclipped(const CaptureAnalysis& a, const SyntheticTruth& truth) {
  BOOST_TEST_INFO("verdict: " << to_string(a.verdict) << (a.reasons.empty() ? "" : ": " + a.reasons.front()));
  BOOST_REQUIRE(a.can_throw());
  BOOST_TEST_MESSAGE(a.format << ": speed " << a.nominal.speed_m_s << " (truth " << truth.speed_m_s << "), attack "
                     << a.nominal.attack_angle_deg << " (" << truth.attack_angle_deg << "), path " << a.nominal.path_angle_deg
                     << " (" << truth.path_angle_deg << "), spin " << a.nominal.spin_rev_s << " (" << truth.spin_rev_s
                     << "), height " << a.nominal.height_m << " (" << truth.height_m << ")");
  BOOST_TEST(!a.clipped);
  BOOST_TEST(std::abs(a.nominal.speed_m_s - truth.speed_m_s) <= kSpeedRelTol * truth.speed_m_s,
             "speed " << a.nominal.speed_m_s << " vs truth " << truth.speed_m_s);
  BOOST_TEST(std::abs(a.nominal.attack_angle_deg - truth.attack_angle_deg) <= kAngleTol_deg,
             "attack " << a.nominal.attack_angle_deg << " vs truth " << truth.attack_angle_deg);
  BOOST_TEST(std::abs(a.nominal.path_angle_deg - truth.path_angle_deg) <= kAngleTol_deg,
             "path " << a.nominal.path_angle_deg << " vs truth " << truth.path_angle_deg);
}
}  // namespace

BOOST_AUTO_TEST_SUITE(capture_recovery)

BOOST_AUTO_TEST_CASE(an_unclipped_hard_throw_is_recovered_within_five_percent_and_three_degrees) {
  // Oracle: the generator's analytic release state (speed V + Ω|lever|, angles α and β).
  SyntheticTruth truth;
  const std::string log = synthetic_report_log(SyntheticThrow{}, wide_range_sensor(), truth);
  CaptureOptions o = quick_options();
  o.saturation_g = 15.9;  // this sensor clips at 16 g
  const CaptureAnalysis a = analyse_capture(parse_capture(log, "hard_wide.log"), o);
  check_unclipped(a, truth);
  BOOST_TEST(truth.range_switches > 0);
}

BOOST_AUTO_TEST_CASE(a_gentle_throw_on_a_real_remote_is_recovered_from_every_format) {
  // Oracle: the generator's analytic release state; the same motion written as a report log, an
  // evemu recording and a gesture file must each give it back within the acceptance tolerances.
  const SyntheticThrow th = gentle_throw();
  SyntheticTruth t_log, t_evemu, t_gesture;
  const SyntheticSensor sensor;
  const auto log = analyse_capture(parse_capture(synthetic_report_log(th, sensor, t_log), "gentle.log"), quick_options());
  check_unclipped(log, t_log);
  BOOST_TEST(t_log.clipped_samples == 0);
  BOOST_TEST(std::string(to_string(log.verdict)) == "usable", (log.reasons.empty() ? "" : log.reasons.front()));
  const auto ev = analyse_capture(parse_capture(synthetic_evemu(th, sensor, t_evemu), "gentle.evemu"), quick_options());
  BOOST_TEST(ev.format == "evemu");
  check_unclipped(ev, t_evemu);
  const auto ge = analyse_capture(parse_capture(synthetic_gesture(th, sensor, t_gesture), "gentle.txt"), quick_options());
  BOOST_TEST(ge.format == "gesture");
  check_unclipped(ge, t_gesture);
  // The range modes inferred from the jumps are the ones the generator's MotionPlus used.
  BOOST_REQUIRE(ge.trace.samples.size() == t_gesture.written_fast.size());
  int switches = 0, mismatches = 0;
  for (std::size_t k = 0; k < t_gesture.written_fast.size(); ++k) {
    mismatches += ge.trace.samples[k].gyro_fast != t_gesture.written_fast[k];
    if (k > 0) switches += t_gesture.written_fast[k] != t_gesture.written_fast[k - 1];
  }
  BOOST_TEST(switches > 0);
  BOOST_TEST(mismatches == 0);
}

BOOST_AUTO_TEST_CASE(a_clipped_throw_is_flagged_and_its_speed_interval_contains_the_truth) {
  // Oracle: the generator's analytic release speed, which the ±3.6 g clipping hides.
  SyntheticTruth truth;
  const std::string log = synthetic_report_log(SyntheticThrow{}, SyntheticSensor{}, truth);
  const CaptureAnalysis a = analyse_capture(parse_capture(log, "hard.log"), quick_options());
  BOOST_REQUIRE(truth.clipped_samples > 0);
  BOOST_TEST(a.clipped);
  BOOST_TEST(std::string(to_string(a.verdict)) == "usable with caveats");
  BOOST_REQUIRE(!a.reasons.empty());
  BOOST_TEST(a.reasons.front().find("clipped") != std::string::npos, a.reasons.front());
  BOOST_TEST_MESSAGE("clipped: speed " << a.nominal.speed_m_s << " [" << a.speed_m_s.low << ", " << a.speed_m_s.high
                     << "] truth " << truth.speed_m_s << "; accel lower bound " << a.accel_lower.accel_speed_m_s
                     << ", attack " << a.attack_angle_deg.nominal << " [" << a.attack_angle_deg.low << ", "
                     << a.attack_angle_deg.high << "] truth " << truth.attack_angle_deg << ", path "
                     << a.path_angle_deg.nominal << " truth " << truth.path_angle_deg);
  BOOST_TEST(a.speed_m_s.contains(truth.speed_m_s),
             "[" << a.speed_m_s.low << ", " << a.speed_m_s.high << "] vs truth " << truth.speed_m_s);
  // The clipped accelerometer alone underestimates the speed: its value is a lower bound.
  BOOST_TEST(a.accel_lower.accel_speed_m_s < truth.speed_m_s);
  // So the speed used is not below it (the lever arm, which misses the pivot's share, is: 8.38 of
  // the bound's 8.65 m/s here) and keeps the lever arm's direction (1e-12: a rescaled vector's
  // round-off); the interval's low end is a member's own bound, within the members' spread
  // (MotionPlus scale ±5 %) of the nominal one, never the lever arm's 20 % lower low end.
  BOOST_TEST(a.nominal.lever_speed_m_s < a.accel_lower.accel_speed_m_s);
  BOOST_TEST(a.nominal.speed_floored);
  BOOST_TEST(a.nominal.measured_speed_m_s == a.accel_lower.accel_speed_m_s, boost::test_tools::tolerance(1e-12));
  const Vec3 used = a.nominal.measured.velocity_m_s.normalized(), lever = a.nominal.lever_velocity_m_s.normalized();
  BOOST_TEST((used - lever).norm() <= 1e-12);
  BOOST_TEST(a.measured_speed_m_s.low > a.lever_speed_m_s.low);
  // Each member is raised to its own bound (its twin: the same draws, spans as recorded), not the
  // nominal one: the bounds differ between members (MotionPlus scale ±5 %, noise), and a member
  // raised is exactly at its own (1e-12: the rescaled vector's norm).
  double lowest = INFINITY, highest = 0;
  int raised = 0;
  for (const ReleaseKinematics& m : a.ensemble) {
    lowest = std::min(lowest, m.speed_floor_m_s);
    highest = std::max(highest, m.speed_floor_m_s);
    if (!m.speed_floored) continue;
    ++raised;
    BOOST_TEST(m.measured_speed_m_s == m.speed_floor_m_s, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(m.lever_speed_m_s < m.speed_floor_m_s);
  }
  BOOST_TEST(raised > 0);
  BOOST_TEST(lowest < a.accel_lower.accel_speed_m_s);
  BOOST_TEST(highest > a.accel_lower.accel_speed_m_s);
}

BOOST_AUTO_TEST_CASE(dropped_and_repeated_reports_and_jitter_are_counted_exactly) {
  // Oracle: the generator's own count of the reports it dropped and repeated, and the standard
  // deviation of the intervals between the stamps it kept, computed here independently.
  SyntheticSensor s;
  s.drop_probability = 0.05;
  s.repeat_probability = 0.05;
  SyntheticTruth truth;
  const std::string log = synthetic_report_log(gentle_throw(), s, truth);
  const TimedSamples t = analyse_timing(parse_capture(log, "lossy.log"));
  BOOST_REQUIRE(truth.dropped_reports > 0);
  BOOST_REQUIRE(truth.repeated_reports > 0);
  BOOST_TEST(t.stats.dropped_reports == truth.dropped_reports);
  BOOST_TEST(t.stats.repeated == std::size_t(truth.repeated_reports));
  BOOST_TEST(t.stats.used == truth.received_stamps_s.size());
  // Intervals that span no lost report are the jitter's sample.
  const double period = 1.0 / s.rate_hz;
  std::vector<double> dt;
  for (std::size_t k = 1; k < truth.received_stamps_s.size(); ++k) {
    const double d = truth.received_stamps_s[k] - truth.received_stamps_s[k - 1];
    if (d < 1.5 * period) dt.push_back(d);
  }
  double mean = 0, var = 0;
  for (double d : dt) mean += d / double(dt.size());
  for (double d : dt) var += (d - mean) * (d - mean) / double(dt.size() - 1);
  constexpr double kStampRoundoff_s = 2e-6;  // stamps are written with 1 µs resolution
  BOOST_TEST(std::abs(t.stats.jitter_s - std::sqrt(var)) < kStampRoundoff_s);
  BOOST_TEST(t.stats.gaps > 0);
}

BOOST_AUTO_TEST_CASE(a_remote_strapped_on_its_side_is_described_key_by_key_in_either_order) {
  // Oracle: the generator's analytic release state, for a remote whose X axis is the stone's
  // normal and whose Z axis points forward. Each key alone is parallel to the other's default
  // (normal +Z, forward −X), so the mounting is checked only once every setting is applied.
  SyntheticThrow th = gentle_throw();
  th.mounting.stone_normal = Vec3(1, 0, 0);
  th.mounting.stone_forward = Vec3(0, 0, 1);
  SyntheticTruth truth;
  const Trace trace = parse_capture(synthetic_report_log(th, SyntheticSensor{}, truth), "side.log");
  for (const auto& order : {std::vector<std::string>{"stone_normal=1,0,0", "stone_forward=0,0,1"},
                            std::vector<std::string>{"stone_forward=0,0,1", "stone_normal=1,0,0"}}) {
    CaptureOptions o = quick_options();
    o.mounting = resolve_mounting(trace, order);
    check_unclipped(analyse_capture(trace, o), truth);
  }
  // A combination that leaves forward along the normal is still refused, naming the key.
  try {
    resolve_mounting(trace, {"stone_normal=1,0,0", "stone_forward=2,0,0"});
    BOOST_FAIL("a forward direction along the normal was accepted");
  } catch (const InputError& e) {
    BOOST_TEST(std::string(e.what()).find("mounting.stone_forward") != std::string::npos, e.what());
  }
}

BOOST_AUTO_TEST_CASE(a_saturated_motionplus_widens_the_intervals_to_hold_the_truth) {
  // Oracle: the generator's analytic release state. A swing at 45 rad/s (2 580 deg/s) passes the
  // MotionPlus's fast range (about 1 860 deg/s): the recorded rate is cut at the end of its range,
  // so the spin and the lever-arm speed read low. The intervals must hold the truth (the
  // accelerometer is a ±16 g one here, so that only the gyro saturates).
  SyntheticThrow th;
  th.swing_rate_rad_s = 45.0;
  SyntheticTruth truth;
  const std::string log = synthetic_report_log(th, wide_range_sensor(), truth);
  CaptureOptions o = quick_options();
  o.members = 64;  // the bump heights are drawn per member: enough of them to reach the truth
  o.saturation_g = 15.9;
  const CaptureAnalysis a = analyse_capture(parse_capture(log, "fast.log"), o);
  BOOST_REQUIRE(a.gyro_saturated_in_swing);
  BOOST_REQUIRE(a.can_throw());
  BOOST_TEST_MESSAGE("saturated: spin " << a.measured_spin_rev_s.nominal << " [" << a.measured_spin_rev_s.low << ", "
                     << a.measured_spin_rev_s.high
                     << "] truth " << truth.spin_rev_s << "; speed " << a.measured_speed_m_s.nominal << " ["
                     << a.measured_speed_m_s.low << ", " << a.measured_speed_m_s.high << "] truth " << truth.speed_m_s
                     << "; attack " << a.attack_angle_deg.nominal << " [" << a.attack_angle_deg.low << ", "
                     << a.attack_angle_deg.high << "] truth " << truth.attack_angle_deg);
  BOOST_TEST(a.measured_spin_rev_s.nominal < truth.spin_rev_s);  // what the cut rate shows: a lower bound
  BOOST_TEST(a.measured_spin_rev_s.contains(truth.spin_rev_s));
  BOOST_TEST(a.measured_speed_m_s.contains(truth.speed_m_s));
  BOOST_TEST(a.attack_angle_deg.contains(truth.attack_angle_deg));
  BOOST_TEST(a.path_angle_deg.contains(truth.path_angle_deg));
}

BOOST_AUTO_TEST_CASE(a_mounting_that_turns_the_stone_upside_down_is_a_caveat_naming_the_tilt) {
  // Oracle: the generator's attack angle (15°, so the stone's normal is 15° from the vertical).
  // Read with the stone's normal reversed, the same capture releases the stone upside down
  // (165°): past the 60° a skipping throw allows, a caveat says to check the mounting.
  SyntheticTruth truth;
  const Trace trace = parse_capture(synthetic_report_log(gentle_throw(), SyntheticSensor{}, truth), "g.log");
  auto tilt_caveat = [](const CaptureAnalysis& a) {
    return std::count_if(a.reasons.begin(), a.reasons.end(),
                         [](const std::string& r) { return r.find("from the vertical at release") != std::string::npos; });
  };
  const CaptureAnalysis right = analyse_capture(trace, quick_options());
  BOOST_TEST(tilt_caveat(right) == 0);
  CaptureOptions o = quick_options();
  o.mounting = resolve_mounting(trace, {"stone_normal=0,0,-1"});
  const CaptureAnalysis flipped = analyse_capture(trace, o);
  BOOST_TEST(std::abs(flipped.attack_angle_deg.nominal) > 90);
  BOOST_TEST(tilt_caveat(flipped) == 1);
}

BOOST_AUTO_TEST_SUITE_END()
