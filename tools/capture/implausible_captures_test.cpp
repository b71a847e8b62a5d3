// Recordings no human throw can have made are unusable, and the reason names the quantity.
// Oracle: the plausibility bounds of the verdict rules (verification/captures/capture_verdict.hpp:
// release speed 1–45 m/s, the hand within 3 m of the still part) and what each recording is by
// construction. The two recordings are third-party logs written here, as a user would bring them:
//  * a WiiYourself!-style log of a remote waved (rolled ±70° at 1.5 Hz for 5 s, the B button held)
//    by a logger whose rates have the other sign: integrated as recorded, the estimated attitude
//    turns the wrong way, gravity is removed along a wrong axis and the "hand" falls — after 5 s
//    at about g (1 − J0(2·70°)) ≈ g, tens of m/s and metres (the log: 47.5 m/s, 70 m);
//  * a flapping gesture (±10° at 2 Hz about the remote's X) with no button column: the release is
//    the file's end, where the stone moves at most 2.2 rad/s × 0.15 m ≈ 0.33 m/s.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "tools/capture/capture_format.hpp"
#include "verification/captures/capture_analysis.hpp"

using namespace stoneskip;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRate_hz = 100.0;

// One WiiYourself!-style row: integer-ms host time, Acc X/Y/Z in g (6 decimals, as the logger
// writes them), Speed Yaw/Pitch/Roll in deg/s (WiiYourself!'s sign: minus stoneskip's), and the
// button word when `buttons`.
std::string row(long sample, double t_s, double ax, double ay, double az, double wx, double wy, double wz, bool b_down,
                bool buttons) {
  char line[256];
  std::snprintf(line, sizeof line, "%ld,%ld,%.6f,%.6f,%.6f,%.3f,%.3f,%.3f", sample, 5246644L + std::lround(1000 * t_s), ax,
                ay, az, -wz, -wx, -wy);
  std::string s = line;
  if (buttons) s += b_down ? ",0400" : ",0000";
  return s + "\n";
}

std::string header(bool buttons) {
  return std::string("Sample,Time,Acc X #WM1,Acc Y #WM1,Acc Z #WM1,Speed Yaw #WM1,Speed Pitch #WM1,Speed Roll #WM1") +
         (buttons ? ",Buttons #WM1" : "") + "\n";
}

// Still for 1 s, then rolled about Y by 70° sin(2π 1.5 t) for 5 s with B held; the logger writes
// the roll rate with the wrong sign. 0.3 s after the release.
std::string waved_remote_with_the_other_rate_sign() {
  std::string csv = header(true);
  const double amplitude = 70.0 * kPi / 180.0, omega = 2 * kPi * 1.5, still_s = 1.0, wave_s = 5.0;
  long n = 0;
  for (double t = 0; t < still_s + wave_s + 0.3; t += 1 / kRate_hz, ++n) {
    const double s = std::max(0.0, t - still_s);
    const double phi = t > still_s && t < still_s + wave_s ? amplitude * std::sin(omega * s) : 0.0;
    const double rate_deg_s = t > still_s && t < still_s + wave_s ? amplitude * omega * std::cos(omega * s) * 180 / kPi : 0.0;
    csv += row(n, t, -std::sin(phi), 0.0, std::cos(phi), 0.0, -rate_deg_s, 0.0, t > 0.9 && t < still_s + wave_s, true);
  }
  return csv;
}

// Still for 1 s, then flapped about X by 10° sin(2π 2 t) until the file ends (no buttons).
std::string flapping_gesture_without_buttons() {
  std::string csv = header(false);
  const double amplitude = 10.0 * kPi / 180.0, omega = 2 * kPi * 2.0, still_s = 1.0;
  long n = 0;
  for (double t = 0; t < still_s + 3.1; t += 1 / kRate_hz, ++n) {
    const double s = std::max(0.0, t - still_s);
    const double th = t > still_s ? amplitude * std::sin(omega * s) : 0.0;
    const double rate_deg_s = t > still_s ? amplitude * omega * std::cos(omega * s) * 180 / kPi : 0.0;
    csv += row(n, t, 0.0, std::sin(th), std::cos(th), rate_deg_s, 0.0, 0.0, false, false);
  }
  return csv;
}

CaptureAnalysis analyse(const std::string& text, const std::string& name) {
  const Trace trace = parse_capture(text, name);
  CaptureOptions o;
  o.members = 8;  // the verdict is the nominal chain's; a few members keep the test short
  o.mounting = resolve_mounting(trace, {});
  o.thrower = resolve_thrower(trace, {});
  return analyse_capture(trace, o);
}

bool any_reason_has(const CaptureAnalysis& a, const std::string& words) {
  for (const auto& r : a.reasons)
    if (r.find(words) != std::string::npos) return true;
  return false;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(implausible_captures)

BOOST_AUTO_TEST_CASE(a_waved_remote_logged_with_the_other_rate_sign_is_unusable_naming_speed_and_travel) {
  const CaptureAnalysis a = analyse(waved_remote_with_the_other_rate_sign(), "waved_wiiyourself.csv");
  BOOST_TEST_MESSAGE("waved: " << a.measured_speed_m_s.nominal << " m/s; " << (a.reasons.empty() ? "" : a.reasons.front()));
  BOOST_TEST(a.format == std::string("csv"));
  BOOST_TEST(to_string(a.verdict) == std::string("unusable"));
  BOOST_TEST(a.measured_speed_m_s.nominal > 45.0, a.measured_speed_m_s.nominal);  // g × 5 s ≈ 49 m/s
  BOOST_TEST(any_reason_has(a, "release speed"));
  BOOST_TEST(any_reason_has(a, "hand displacement"));
}

BOOST_AUTO_TEST_CASE(a_flapping_gesture_without_a_button_column_is_unusable_naming_the_speed) {
  const CaptureAnalysis a = analyse(flapping_gesture_without_buttons(), "flapping.csv");
  BOOST_TEST_MESSAGE("flapping: " << a.measured_speed_m_s.nominal << " m/s; " << (a.reasons.empty() ? "" : a.reasons.front()));
  BOOST_TEST(to_string(a.verdict) == std::string("unusable"));
  BOOST_TEST(a.measured_speed_m_s.nominal < 1.0, a.measured_speed_m_s.nominal);  // at most ≈ 0.33 m/s
  BOOST_TEST(any_reason_has(a, "release speed"));
  BOOST_TEST((any_reason_has(a, "no button") || any_reason_has(a, "file's end")));  // the caveat says why the release is there
}

BOOST_AUTO_TEST_SUITE_END()
