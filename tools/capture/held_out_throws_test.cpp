// The capture path on throws no shipped capture records: skipping throws drawn over the published
// envelope (synthetic_capture.hpp, SkippingThrowSpec), recorded by remotes strapped at drawn angles,
// with drawn report rates, jitter, losses and formats. Each is checked against the generator's
// analytic truth: the capture issue's 5 % on the speed and 3° on the angles where nothing clipped,
// and the intervals where something did.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <sstream>

#include "tools/capture/capture_format.hpp"
#include "tools/capture/synthetic_capture.hpp"
#include "verification/captures/capture_analysis.hpp"

using namespace stoneskip;

namespace {
constexpr double kSpeedRelTol = 0.05;  // 5 % on the release speed (the capture issue's acceptance)
constexpr double kAngleTol_deg = 3.0;  // 3° on attack and path angles (the same)
// The spin the remote sees (the arm's, about the stone's normal) to the MotionPlus scale's stated
// uncertainty, ±5 % (CaptureOptions::gyro_scale_rel_uncertainty): an error beyond it is the chain's.
constexpr double kSpinRelTol = 0.05;
constexpr int kDraws = 40;

struct Draw {
  SyntheticThrow th;
  SyntheticSensor sensor;
  int format = 0;  // 0 report log, 1 evemu, 2 gesture, 3 WiiYourself! CSV of two remotes
  std::string describe;
};

double uniform(std::mt19937_64& g, double a, double b) { return std::uniform_real_distribution<double>(a, b)(g); }

// Which throws and remotes a test draws.
enum class Kind {
  skipping_wide_range,  // a skipping throw on a hypothetical ±16 g accelerometer (nothing clips)
  skipping,             // a skipping throw on a real ±3.6 g remote (the accelerometer clips)
  gentle,               // a gentle throw a real remote records whole
};

// A throw over the published envelope (synthetic_capture.hpp's SkippingThrowSpec cites it): speed
// 8–15 m/s, spin 10–20 rev/s, attack 10–30°, path 0–15°, released 0.1–0.6 m above the water, the
// trunk's share of the speed 5–30 %, a 0.15–0.3 s swing; a gentle throw is 3–5.5 m/s over a
// 0.25–0.4 s swing. The remote: strapped rolled about the forearm by any angle, its lever arm
// 0.45–0.75 m; reports at 95–105 Hz, jitter to 3 ms, up to 3 % lost and 2 % repeated, either report
// kind, written in one of four formats (three for the hypothetical remote: WiiYourself! keeps an
// accelerometer's 8 high bits, 0.13 g a step at its 30 counts per g, too coarse to find the still part).
Draw draw(std::mt19937_64& g, Kind kind) {
  SkippingThrowSpec spec;
  spec.speed_m_s = kind == Kind::gentle ? uniform(g, 3, 5.5) : uniform(g, 8, 15);
  spec.spin_rev_s = uniform(g, 10, 20);
  spec.attack_angle_deg = uniform(g, 10, 30);
  spec.path_angle_deg = uniform(g, 0, 15);
  spec.release_height_m = uniform(g, 0.1, 0.6);
  spec.pivot_share = uniform(g, 0.05, 0.3);
  spec.swing_duration_s = kind == Kind::gentle ? uniform(g, 0.25, 0.4) : uniform(g, 0.15, 0.3);
  Draw d;
  const double roll = uniform(g, -180, 180) * std::numbers::pi / 180;
  const Mat3 about_forearm = Eigen::AngleAxisd(roll, Vec3::UnitY()).toRotationMatrix();
  Mounting m;
  m.stone_normal = about_forearm * m.stone_normal;
  m.stone_forward = about_forearm * m.stone_forward;
  m.stone_offset_m = about_forearm * m.stone_offset_m;
  m.lever_arm_m = Vec3(0, uniform(g, 0.45, 0.75), 0);
  spec.mounting = m;
  d.th = skipping_throw(spec);
  d.sensor.rate_hz = uniform(g, 95, 105);
  d.sensor.jitter_s = uniform(g, 0, 0.003);
  d.sensor.drop_probability = uniform(g, 0, 0.03);
  d.sensor.repeat_probability = uniform(g, 0, 0.02);
  d.sensor.report_id = uniform(g, 0, 1) < 0.5 ? 0x35 : 0x37;
  d.sensor.seed = g();
  const bool wide_range = kind == Kind::skipping_wide_range;
  if (wide_range) {  // a hypothetical ±16 g accelerometer, 30 counts per g, so ±16 g fits 10 bits
    d.sensor.clip_g = 16.0;
    for (int i = 0; i < 3; ++i) d.sensor.accel_one_g_counts[i] = d.sensor.accel_zero_counts[i] + 30;
  }
  d.format = static_cast<int>(uniform(g, 0, wide_range ? 3 : 4));
  std::ostringstream s;
  s << "speed " << spec.speed_m_s << " spin " << spec.spin_rev_s << " attack " << spec.attack_angle_deg << " path "
    << spec.path_angle_deg << " height " << spec.release_height_m << " share " << spec.pivot_share << " swing "
    << spec.swing_duration_s << " roll " << roll * 180 / std::numbers::pi << " lever " << m.lever_arm_m.y() << " rate "
    << d.sensor.rate_hz << " format " << d.format;
  d.describe = s.str();
  return d;
}

std::string record(const Draw& d, SyntheticTruth& truth) {
  if (d.format == 1) return synthetic_evemu(d.th, d.sensor, truth);
  if (d.format == 2) return synthetic_gesture(d.th, d.sensor, truth);
  if (d.format == 3) {  // the second remote lies on a table, its own stream
    SyntheticSensor idle;
    idle.seed = d.sensor.seed + 1;
    return synthetic_wiiyourself_csv(d.th, d.sensor, idle, truth);
  }
  return synthetic_report_log(d.th, d.sensor, truth);
}
const char* name(int format) {
  return format == 1 ? "held.evemu" : format == 2 ? "held.txt" : format == 3 ? "held.csv" : "held.log";
}

// The draw written in its format (into text, with its truth) and analysed as a user would, giving
// the mounting the remote was strapped with.
CaptureAnalysis recorded_and_analysed(const Draw& d, Kind kind, SyntheticTruth& truth, std::string& text) {
  text = record(d, truth);
  CaptureOptions o;
  o.members = 16;  // enough for the intervals these checks read; keeps a draw well under a second
  if (kind == Kind::skipping_wide_range) o.saturation_g = 15.9;  // that accelerometer clips at 16 g
  o.mounting = d.th.mounting;
  return analyse_capture(parse_capture(text, name(d.format)), o);
}

// A gesture file has no range flags: the modes inferred from the raw counts (gyro_range.hpp) must
// be the ones the generator's MotionPlus used, sample for sample.
void check_inferred_modes(const Draw& d, const std::string& text, const SyntheticTruth& truth) {
  if (d.format != 2) return;
  const Trace trace = parse_capture(text, name(d.format));
  BOOST_REQUIRE(trace.samples.size() == truth.written_fast.size());
  int mismatches = 0;
  for (std::size_t k = 0; k < trace.samples.size(); ++k) mismatches += trace.samples[k].gyro_fast != truth.written_fast[k];
  BOOST_TEST(mismatches == 0);
}

void check_recovered(const CaptureAnalysis& a, const SyntheticTruth& truth) {
  BOOST_TEST(a.can_throw());
  if (!a.can_throw()) return;
  BOOST_TEST(std::abs(a.nominal.speed_m_s - truth.speed_m_s) <= kSpeedRelTol * truth.speed_m_s);
  BOOST_TEST(std::abs(a.nominal.attack_angle_deg - truth.attack_angle_deg) <= kAngleTol_deg);
  BOOST_TEST(std::abs(a.nominal.path_angle_deg - truth.path_angle_deg) <= kAngleTol_deg);
  BOOST_TEST(std::abs(a.measured_spin_rev_s.nominal - truth.spin_rev_s) <= kSpinRelTol * truth.spin_rev_s);
}

// The draws of one kind that nothing clipped, each recovered within the tolerances; returns how many.
int check_unclipped_draws(std::uint64_t seed, Kind kind) {
  std::mt19937_64 g(seed);
  int checked = 0;
  for (int i = 0; i < kDraws; ++i) {
    const Draw d = draw(g, kind);
    SyntheticTruth truth;
    std::string text;
    const CaptureAnalysis a = recorded_and_analysed(d, kind, truth, text);
    BOOST_TEST_CONTEXT(d.describe) {
      BOOST_TEST_MESSAGE(d.describe << " | verdict " << to_string(a.verdict)
                         << (a.reasons.empty() ? "" : ": " + a.reasons.front())
                         << " | clipped " << truth.clipped_samples << " | speed " << a.nominal.speed_m_s << " ("
                         << truth.speed_m_s << ") attack " << a.nominal.attack_angle_deg << " ("
                         << truth.attack_angle_deg << ") path " << a.nominal.path_angle_deg << " ("
                         << truth.path_angle_deg << ") spin " << a.measured_spin_rev_s.nominal << " ("
                         << truth.spin_rev_s << ")");
      check_inferred_modes(d, text, truth);
      if (truth.clipped_samples > 0) continue;
      ++checked;
      check_recovered(a, truth);
    }
  }
  return checked;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(held_out_throws)

BOOST_AUTO_TEST_CASE(unclipped_throws_drawn_over_the_envelope_are_recovered_within_five_percent_and_three_degrees) {
  // Not vacuous: most draws stay inside the wide-range accelerometer.
  BOOST_TEST(check_unclipped_draws(20261207, Kind::skipping_wide_range) >= kDraws / 2);
}

BOOST_AUTO_TEST_CASE(gentle_throws_a_real_remote_records_whole_are_recovered_in_every_format) {
  BOOST_TEST(check_unclipped_draws(20261209, Kind::gentle) >= kDraws / 2);
}

BOOST_AUTO_TEST_CASE(clipped_throws_drawn_over_the_envelope_have_intervals_that_hold_the_truth) {
  std::mt19937_64 g(20261208);
  for (int i = 0; i < kDraws; ++i) {
    const Draw d = draw(g, Kind::skipping);
    SyntheticTruth truth;
    std::string text;
    const CaptureAnalysis a = recorded_and_analysed(d, Kind::skipping, truth, text);
    BOOST_TEST_CONTEXT(d.describe) {
      BOOST_TEST_MESSAGE(d.describe << " | verdict " << to_string(a.verdict)
                         << (a.reasons.empty() ? "" : ": " + a.reasons.front())
                         << " | clipped " << truth.clipped_samples << " | speed " << a.speed_m_s.nominal << " ["
                         << a.speed_m_s.low << ", " << a.speed_m_s.high << "] (" << truth.speed_m_s << ") attack "
                         << a.attack_angle_deg.nominal << " [" << a.attack_angle_deg.low << ", "
                         << a.attack_angle_deg.high << "] (" << truth.attack_angle_deg << ") path "
                         << a.path_angle_deg.nominal << " [" << a.path_angle_deg.low << ", " << a.path_angle_deg.high
                         << "] (" << truth.path_angle_deg << ")");
      check_inferred_modes(d, text, truth);
      BOOST_TEST(a.can_throw());
      if (!a.can_throw()) continue;
      BOOST_TEST(a.clipped == (truth.clipped_samples > 0));
      BOOST_TEST(a.speed_m_s.contains(truth.speed_m_s));
      BOOST_TEST(a.attack_angle_deg.contains(truth.attack_angle_deg));
      BOOST_TEST(a.path_angle_deg.contains(truth.path_angle_deg));
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
