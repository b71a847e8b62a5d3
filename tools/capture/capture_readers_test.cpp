// Readers on good and bad input: the oracle is the input itself (what was written must be read
// back; a defect planted on a known line must be reported with that file and line).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>

#include "verification/captures/capture_analysis.hpp"
#include "verification/captures/capture_timing.hpp"
#include "tools/capture/capture_format.hpp"
#include "tools/capture/synthetic_capture.hpp"
#include "tools/capture/trace_csv.hpp"
#include "tools/capture/wiimote_report.hpp"
#include "tools/io/input_error.hpp"

using namespace stoneskip;

namespace {
// The error message of parsing `text`, or "" if it parsed.
std::string error_of(const std::string& text, const std::string& format = "") {
  try {
    parse_capture(text, "bad.cap", format);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

std::string gentle_log() {
  SyntheticThrow th;
  th.swing_rate_rad_s = 7.0;
  SyntheticTruth truth;
  return synthetic_report_log(th, SyntheticSensor{}, truth);
}

// A calibration block's ten bytes as a log or header writes them: "7e 80 81 ...".
std::string block_hex(const std::array<int, 3>& zero_counts, const std::array<int, 3>& one_g_counts) {
  std::string hex;
  for (auto b : encode_calibration_block(zero_counts, one_g_counts)) {
    char h[4];
    std::snprintf(h, sizeof h, "%02x", unsigned(b));
    hex += (hex.empty() ? "" : " ") + std::string(h);
  }
  return hex;
}

const std::string kCsvHead = std::string(kTraceCsvMagic) + "\n" + kTraceCsvColumns + "\n";
}  // namespace

BOOST_AUTO_TEST_SUITE(capture_readers)

BOOST_AUTO_TEST_CASE(each_format_is_recognised_from_its_content) {
  SyntheticThrow th;
  SyntheticTruth t;
  BOOST_TEST(detect_capture_format(synthetic_report_log(th, {}, t)) == "report_log");
  BOOST_TEST(detect_capture_format(synthetic_evemu(th, {}, t)) == "evemu");
  BOOST_TEST(detect_capture_format(synthetic_gesture(th, {}, t)) == "gesture");
  BOOST_TEST(detect_capture_format(kCsvHead + "0,0,0,1,0,0,0,0,0,0,0,-\n") == "trace_csv");
  BOOST_TEST(contains(error_of("hello world\n"), "--format"));
}

BOOST_AUTO_TEST_CASE(a_trace_written_as_csv_reads_back_sample_for_sample) {
  // Oracle: the trace the report-log reader produced, written with 9 significant digits.
  const Trace t = parse_capture(gentle_log(), "gentle.log");
  const Trace back = parse_capture(trace_csv_text(t), "gentle.csv");
  BOOST_TEST(back.format == "trace_csv");
  BOOST_REQUIRE(back.samples.size() == t.samples.size());
  constexpr double kPrintRel = 1e-8;  // %.9g
  for (std::size_t k = 0; k < t.samples.size(); ++k) {
    BOOST_TEST(std::abs(back.samples[k].t_s - t.samples[k].t_s) < 1e-9);
    BOOST_TEST((back.samples[k].accel_g - t.samples[k].accel_g).norm() <= kPrintRel * (1 + t.samples[k].accel_g.norm()));
    BOOST_TEST((back.samples[k].rate_deg_s - t.samples[k].rate_deg_s).norm() <= kPrintRel * (1 + t.samples[k].rate_deg_s.norm()));
    BOOST_TEST(back.samples[k].buttons == t.samples[k].buttons);
    BOOST_TEST(back.samples[k].flags == t.samples[k].flags);
    BOOST_TEST(back.samples[k].gyro_fast == t.samples[k].gyro_fast);
  }
  BOOST_TEST(back.calibration.accel_one_g_counts == t.calibration.accel_one_g_counts);
  BOOST_TEST(back.has_gyro);
}

BOOST_AUTO_TEST_CASE(binary_data_is_refused_with_the_file_name) {
  const std::string e = error_of(std::string("12.0 31 00\0\x01\x02", 13));
  BOOST_TEST(contains(e, "bad.cap:1"));
  BOOST_TEST(contains(e, "binary"));
}

BOOST_AUTO_TEST_CASE(wrong_column_counts_and_non_numeric_fields_name_their_line) {
  BOOST_TEST(contains(error_of(kCsvHead + "0,0,0,1,0,0,0,0,0,0,0,-\n0,0,1\n"), "bad.cap:4"));
  BOOST_TEST(contains(error_of(kCsvHead + "0,0,zero,1,0,0,0,0,0,0,0,-\n"), "bad.cap:3"));
  BOOST_TEST(contains(error_of("0.1 0.2 0.3 8192 8192\n0.1 0.2 0.3 8192 8192 8192\n", "gesture"), "bad.cap:1"));
  BOOST_TEST(contains(error_of("1.0 0.0 1.0 8192 8192 99999\n", "gesture"), "14-bit"));
  BOOST_TEST(contains(error_of("10.0 31 00 00 80 80 9a\n10.1 31 0g 00 80 80 9a\n", "report_log"), "bad.cap:2"));
}

BOOST_AUTO_TEST_CASE(a_cut_short_last_line_is_a_warning_not_an_error) {
  const Trace t = parse_capture(kCsvHead + "0,0,0,1,0,0,0,0,0,0,0,-\n0.01,0,0,1,0,0,0,0,0,0,0,-\n0.02,0,0", "cut.csv");
  BOOST_TEST(t.samples.size() == 2u);
  BOOST_REQUIRE(t.warnings.size() == 1u);
  BOOST_TEST(contains(t.warnings[0], "cut.csv:5"));
}

BOOST_AUTO_TEST_CASE(time_going_backwards_names_the_line) {
  // Both lines are named: an absurd time on the earlier line shows as the later one's fault.
  BOOST_TEST(contains(error_of("10.0 31 00 00 80 80 9a\n9.9 31 00 00 80 80 9a\n"),
                      "bad.cap:2: time goes backwards (9.9 s after 10 s on line 1)"));
  BOOST_TEST(contains(error_of(kCsvHead + "1,0,0,1,0,0,0,0,0,0,0,-\n0.5,0,0,1,0,0,0,0,0,0,0,-\n"), "(0.5 s after 1 s on line 3)"));
  // An absurd first time is the one named, with its value as written (the check is against the
  // samples' median, not the first sample).
  BOOST_TEST(contains(error_of("-1e300 31 00 00 80 80 9a\n10.0 31 00 00 80 80 9a\n10.01 31 00 00 80 80 9b\n"),
                      "bad.cap:1: time -1e+300 s is not within"),
             error_of("-1e300 31 00 00 80 80 9a\n10.0 31 00 00 80 80 9a\n10.01 31 00 00 80 80 9b\n"));
  BOOST_TEST(contains(error_of("N: Nintendo Wii Remote Accelerometer\nE: -5e7 0003 0003 1\nE: -5e7 0000 0000 0\n"
                               "E: 13.0 0003 0003 2\nE: 13.0 0000 0000 0\nE: 13.01 0003 0003 3\nE: 13.01 0000 0000 0\n"),
                      "bad.cap:3: time -50000000 s is not within"),
             "evemu, as written");
  // A file whose later part is shifted by 2e6 s: the median lies there, and the first sample, a
  // good one, was named. The jump between neighbours is named, with both lines.
  const std::string shifted = "10.00 31 00 00 80 80 9a\n10.01 31 00 00 80 80 9a\n10.02 31 00 00 80 80 9b\n"
                              "2000010.03 31 00 00 80 80 9a\n2000010.04 31 00 00 80 80 9a\n2000010.05 31 00 00 80 80 9b\n";
  BOOST_TEST(contains(error_of(shifted), "bad.cap:3: time 10.02 s is not within 1e+06 s of the neighbouring sample's time "
                                         "(2000010.03 s, line 4)"),
             error_of(shifted));
  BOOST_TEST(contains(error_of(kCsvHead + "1,0,0,1,0,0,0,0,0,0,0,-\n0.5,0,0,1,0,0,0,0,0,0,0,-\n"), "backwards"));
  BOOST_TEST(contains(error_of("N: Nintendo Wii Remote Accelerometer\nE: 1.0 0003 0003 1\nE: 0.5 0003 0003 2\n"), "bad.cap:3"));
  // A device's second block goes on from its first (main: each block started a clock of its own,
  // so the accelerometer recorded twice was read as one capture with time running back 1.5 s);
  // another device's block has its own order, and a block that goes on is one recording split.
  const std::string accel_at = "N: Nintendo Wii Remote Accelerometer\nE: 1.0 0003 0003 1\nE: 1.0 0000 0000 0\n";
  BOOST_TEST(contains(error_of(accel_at + "N: Nintendo Wii Remote Motion Plus\nE: 0.5 0003 0003 9\n" + accel_at.substr(0, 37) +
                               "E: 0.9 0003 0003 2\n"),
                      "bad.cap:7: time goes backwards (0.9 s after 1 s on line 3, the last event of this device's earlier block)"));
  const Trace split = parse_capture(accel_at + "N: Nintendo Wii Remote Motion Plus\nE: 0.5 0003 0003 9\nE: 0.5 0000 0000 0\n" +
                                        "E: 1.0 0003 0003 18\nE: 1.0 0000 0000 0\nE: 1.5 0003 0003 9\nE: 1.5 0000 0000 0\n" +
                                        accel_at.substr(0, 37) + "E: 1.5 0003 0003 2\nE: 1.5 0000 0000 0\n",
                                    "split.evemu");
  BOOST_TEST(split.samples.size() == 2u);
}

BOOST_AUTO_TEST_CASE(a_trace_marked_nominal_over_other_times_is_refused) {
  // "# timestamps: nominal" over host stamps: the stamps were analysed (98.8 Hz, 1.7 ms of jitter,
  // a gap) while the verdict said the nominal rate was assumed. Oracle: the mark's meaning, times
  // k / nominal_rate_hz from the first: the gesture recorder's trace (nominal, as convert writes it)
  // reads back, the same with one row 1 ms late is refused naming that row, and a host-stamped
  // trace marked nominal is refused.
  SyntheticThrow th;
  th.swing_rate_rad_s = 7.0;
  SyntheticTruth truth;
  const Trace gesture = parse_capture(synthetic_gesture(th, SyntheticSensor{}, truth), "g.txt");
  BOOST_REQUIRE(gesture.nominal_timestamps);
  const std::string text = trace_csv_text(gesture);
  BOOST_TEST(parse_capture(text, "g.csv").samples.size() == gesture.samples.size());
  std::string late = text;
  const std::size_t row = late.find("\n0.050000000,");  // the sixth sample at 100 Hz
  BOOST_REQUIRE(row != std::string::npos);
  late.replace(row + 1, 11, "0.051000000");
  BOOST_TEST(contains(error_of(late), "'# timestamps: nominal' says the times are k / nominal_rate_hz (100 Hz)"), error_of(late));
  BOOST_TEST(contains(error_of(late), "this row's is 0.051000000 s, not 0.050000000 s"));
  std::string host = trace_csv_text(parse_capture(gentle_log(), "gentle.log"));
  host.replace(host.find("# timestamps: host"), 18, "# timestamps: nominal");
  BOOST_TEST(contains(error_of(host), "'# timestamps: nominal' says"), error_of(host));
}

BOOST_AUTO_TEST_CASE(a_misspelt_header_key_or_another_trace_version_is_refused_a_note_is_not) {
  // main: "# has_gyroo: false" was ignored (and the MotionPlus taken as present: another verdict),
  // "# nominal_rate_Hz: 100" too, and "# stoneskip trace v2" read as v1. Oracle: the keys of
  // capture_header.hpp and trace_csv.hpp; a key within two edits of one is its misspelling, a
  // comment further from every key ("# note: …") stays a comment.
  const std::string row = "0,0,0,1,0,0,0,0,0,0,0,-\n0.01,0,0,1,0,0,0,0,0,0,0,-\n";
  const std::string trace = std::string(kTraceCsvMagic) + "\n# has_gyroo: false\n" + kTraceCsvColumns + "\n" + row;
  BOOST_TEST(contains(error_of(trace), "bad.cap:2: has_gyroo: not a header key: a misspelling of 'has_gyro'?"), error_of(trace));
  // The trace's own keys given twice are refused as the shared ones are: "has_gyro: true" then
  // "false" silently made a capture unusable for want of a MotionPlus.
  const std::string twice = std::string(kTraceCsvMagic) + "\n# has_gyro: true\n# has_gyro: false\n" + kTraceCsvColumns + "\n" + row;
  BOOST_TEST(contains(error_of(twice), "bad.cap:3: has_gyro: given twice (first on line 2): keep one"), error_of(twice));
  const std::string v2 = "# stoneskip trace v2\n" + std::string(kTraceCsvColumns) + "\n" + row;
  BOOST_TEST(contains(error_of(v2), "bad.cap:1: '# stoneskip trace v2' is not a trace version this build reads"), error_of(v2));
  const std::string log = "10.00 31 00 00 80 80 9a\n10.01 31 00 00 80 80 9a\n";
  BOOST_TEST(contains(error_of("# nominal_rate_Hz: 100\n" + log), "bad.cap:1: nominal_rate_Hz: not a header key: a misspelling of 'nominal_rate_hz'?"));
  BOOST_TEST(contains(error_of("# calibraton.block: 80 80 80 00 9a 9a 9a 00 00 c5\n" + log),
                      "a misspelling of 'calibration.block'?"));
  // A rate out of range is said to be so (main: "expected a positive number, got '1e7'").
  BOOST_TEST(contains(error_of("# nominal_rate_hz: 1e7\n" + log), "bad.cap:1: nominal_rate_hz: must be in [1, 1000] (got 1e7)"));
  // Device settings no remote has: each bound with its reason (capture_header.cpp). Oracle: the
  // input rules; 1e6 counts per deg/s made every rate about 0 and the capture merely "usable with
  // caveats", a fast factor of 1e-9 made fast mode finer than slow.
  BOOST_TEST(contains(error_of("# nominal_rate_hz: 1e-300\n" + log), "nominal_rate_hz: must be in [1, 1000]"));
  BOOST_TEST(contains(error_of("# calibration.gyro_slow_counts_per_deg_s: 1e6\n" + log),
                      "bad.cap:1: calibration.gyro_slow_counts_per_deg_s: must be in [2, 200] (got 1e6)"));
  BOOST_TEST(contains(error_of("# calibration.gyro_fast_factor: 1e-9\n" + log),
                      "calibration.gyro_fast_factor: must be in [1, 50] (got 1e-9): fast mode is coarser than slow"));
  BOOST_TEST(parse_capture("# calibration.gyro_slow_counts_per_deg_s: 13.7\n# calibration.gyro_fast_factor: 4\n# nominal_rate_hz: 200\n" + log,
                           "ok.log")
                 .calibration.gyro_slow_counts_per_deg_s == 13.7);
  const Trace noted = parse_capture("# note: thrown at the lake\n# rate: fast\n" + log, "noted.log");
  BOOST_TEST(noted.samples.size() == 2u);
}

BOOST_AUTO_TEST_CASE(unknown_and_truncated_reports_are_skipped_with_a_warning_naming_the_line) {
  const Trace t = parse_capture("10.00 31 00 00 80 80 9a\n10.01 99 00 00\n10.02 35 00 00 80\n10.03 31 00 00 80 80 9a\n",
                                "odd.log");
  BOOST_TEST(t.samples.size() == 2u);
  BOOST_REQUIRE(t.warnings.size() >= 2u);
  BOOST_TEST(contains(t.warnings[0], "odd.log:2: unknown report type 0x99"));
  BOOST_TEST(contains(t.warnings[1], "odd.log:3: truncated report 0x35"));
}

BOOST_AUTO_TEST_CASE(a_report_longer_than_any_the_remote_sends_is_warned_of) {
  // Oracle: the Wii Remote's input reports are at most 22 bytes with the id (0x35: id, 2 button,
  // 3 accelerometer, 16 extension bytes; WiiBrew, "Wiimote", Data Reporting). A logger may pad a
  // shorter report up to that (accepted in silence) or prefix the HID header 0xa1; a 23rd byte is
  // no part of any report (main read it in silence).
  const std::string r35 = " 35 00 00 80 80 9a 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00";
  const Trace ok = parse_capture("10.00" + r35 + "\n10.01 a1" + r35 + "\n10.02 31 00 00 80 80 9a 00 00\n", "ok.log");
  BOOST_TEST(ok.samples.size() == 3u);
  for (const auto& w : ok.warnings) BOOST_TEST(!contains(w, "longer than"), w);
  const Trace t = parse_capture("10.00" + r35 + "\n10.01" + r35 + " 7f\n10.02" + r35 + " 7f 7f\n", "long.log");
  BOOST_TEST(t.samples.size() == 3u);
  BOOST_TEST(std::count_if(t.warnings.begin(), t.warnings.end(), [](const std::string& w) {
               return contains(w, "long.log:2: 2 reports are longer than 22 bytes");
             }) == 1);
}

BOOST_AUTO_TEST_CASE(a_capture_without_a_button_press_or_still_part_is_unusable_with_the_reason) {
  // Oracle: a log whose button bits were all cleared has no press; a throw that starts 0.1 s
  // into the recording has no still part.
  std::string log = gentle_log();
  for (std::size_t p = log.find('\n'); p != std::string::npos && p + 1 < log.size(); p = log.find('\n', p + 1)) {
    const std::size_t bytes = log.find(' ', p + 1) + 1;  // "35 00 b1 ..." → clear B (0x04) in b1
    const int b1 = std::stoi(log.substr(bytes + 6, 2), nullptr, 16) & ~0x04;
    const char* hex = "0123456789abcdef";
    log[bytes + 6] = hex[b1 >> 4];
    log[bytes + 7] = hex[b1 & 15];
  }
  CaptureOptions o;
  o.members = 0;
  const CaptureAnalysis a = analyse_capture(parse_capture(log, "nopress.log"), o);
  BOOST_TEST(std::string(to_string(a.verdict)) == "unusable");
  BOOST_REQUIRE(!a.reasons.empty());
  BOOST_TEST(contains(a.reasons.front(), "no press"), a.reasons.front());

  SyntheticThrow th;
  th.swing_rate_rad_s = 7.0;
  th.still_s = 0.1;
  th.press_at_s = 0.0;
  SyntheticTruth truth;
  const CaptureAnalysis b = analyse_capture(parse_capture(synthetic_report_log(th, {}, truth), "nostill.log"), o);
  BOOST_TEST(std::string(to_string(b.verdict)) == "unusable");
  BOOST_REQUIRE(!b.reasons.empty());
  BOOST_TEST(contains(b.reasons.front(), "no still part"), b.reasons.front());
}

BOOST_AUTO_TEST_CASE(an_evemu_report_whose_accelerometer_values_repeat_is_held_not_lost) {
  // evdev drops an ABS value equal to the last and a SYN_REPORT with nothing before it, so a report
  // whose three accelerometer values repeat leaves only its MotionPlus frame; such reports were
  // read as lost (the shipped gentle_sidearm.evemu: "about 7 reports lost", its truth 1). Oracle:
  // the synthetic recording's own counts, one sample for every report the remote sent that was
  // neither lost nor a repeat (the input core emits nothing for those), and the report log of the
  // same recording, whose reports all arrive as lines.
  SyntheticThrow th;
  th.swing_rate_rad_s = 7.0;
  SyntheticTruth truth;
  const Trace ev = parse_capture(synthetic_evemu(th, {}, truth), "held.evemu");
  BOOST_TEST(ev.samples.size() == std::size_t(truth.reports_sent - truth.dropped_reports - truth.repeated_reports));
  const TimedSamples from_evemu = analyse_timing(ev), from_log = analyse_timing(parse_capture(gentle_log(), "same.log"));
  BOOST_TEST(from_evemu.stats.dropped_reports == from_log.stats.dropped_reports);
  BOOST_TEST(from_evemu.stats.gaps == from_log.stats.gaps);
}

BOOST_AUTO_TEST_CASE(an_evemu_accelerometer_that_stops_or_pauses_in_a_swing_is_not_held) {
  // A report without an accelerometer frame is held only where the reading can have repeated:
  // inside the accelerometer's recording, with the remote turned under 1° since (gravity moves
  // under 2 counts). Oracle: the synthetic throw's own motion (a 7 rad/s swing turns about 4° a
  // report near the release); the accelerometer device's events are cut from the text, so no
  // sample may stand where it has none: after its recording stops, or inside a pause in the swing.
  SyntheticThrow th;
  th.swing_rate_rad_s = 7.0;
  SyntheticTruth truth;
  const std::string text = synthetic_evemu(th, {}, truth);
  // The text with the accelerometer device's events at host times in [from, to) removed, and the
  // host time of its first event (a trace's times count from it).
  double first_accel_s = -1;
  auto without_accel = [&](double from, double to) {
    std::string out;
    bool accel = false;
    for (std::size_t at = 0; at < text.size();) {
      const std::size_t end = text.find('\n', at);
      const std::string line = text.substr(at, end - at + 1);
      at = end + 1;
      if (line.rfind("N: ", 0) == 0) accel = line.find("Accelerometer") != std::string::npos;
      if (accel && line.rfind("E: ", 0) == 0) {
        const double t = std::stod(line.substr(3));
        if (first_accel_s < 0) first_accel_s = t;
        if (t >= from && t < to) continue;
      }
      out += line;
    }
    return out;
  };
  const Trace full = parse_capture(without_accel(0, 0), "full.evemu");
  // The generator's host clock: 12.5 s + the remote's time + latency (SyntheticSensor).
  const double release_s = 12.5 + synthetic_release_time_s(th) + SyntheticSensor{}.latency_s;
  const Trace stopped = parse_capture(without_accel(release_s - 0.1, 1e9), "stopped.evemu");
  BOOST_TEST(first_accel_s + stopped.samples.back().t_s < release_s - 0.1 + 0.003,
             "a sample at " << first_accel_s + stopped.samples.back().t_s << " s, the recording stopped at "
                            << release_s - 0.1 << " s");
  BOOST_TEST(full.samples.back().t_s > stopped.samples.back().t_s + 0.3);
  const double from = release_s - 0.09, to = release_s - 0.03;
  const Trace paused = parse_capture(without_accel(from, to), "paused.evemu");
  int inside = 0;
  for (const TraceSample& x : paused.samples)
    if (first_accel_s + x.t_s > from + 0.003 && first_accel_s + x.t_s < to - 0.003) ++inside;
  BOOST_TEST(inside == 0);
  BOOST_TEST(analyse_timing(paused).stats.dropped_reports >= 4);  // the 60 ms pause: about 6 reports
}

BOOST_AUTO_TEST_CASE(an_evemu_motionplus_stream_that_starts_late_or_ends_early_invents_no_rate) {
  // A MotionPlus changes some count every report (noise), so 0.1 s without one of its frames is a
  // stream that is not there; the reader gave the accelerometer frames before its first frame a
  // rate of exactly 0 and those after its last that frame's rate, for the rest of the throw (the
  // capture then judged "usable with caveats", blaming the lever arm). Oracle: the synthetic
  // recording's own MotionPlus event times, cut from the text: no sample may lie more than 0.1 s
  // (plus the 2 ms that pairs the two devices' events of one report) outside them, and a reader
  // warning names where the stream starts or ends; a silence inside the recording is warned of.
  SyntheticThrow th;
  th.swing_rate_rad_s = 7.0;
  SyntheticTruth truth;
  const std::string text = synthetic_evemu(th, {}, truth);
  double first_event_s = -1;  // the first accelerometer event's host time: the trace's zero
  auto without_gyro = [&](double from, double to) {
    std::string out;
    bool gyro = false, accel = false;
    for (std::size_t at = 0; at < text.size();) {
      const std::size_t end = text.find('\n', at);
      const std::string line = text.substr(at, end - at + 1);
      at = end + 1;
      if (line.rfind("N: ", 0) == 0) {
        gyro = line.find("Motion Plus") != std::string::npos;
        accel = line.find("Accelerometer") != std::string::npos;
      }
      if ((gyro || accel) && line.rfind("E: ", 0) == 0) {
        const double t = std::stod(line.substr(3));
        if (accel && first_event_s < 0) first_event_s = t;
        if (gyro && t >= from && t < to) continue;
      }
      out += line;
    }
    return out;
  };
  const Trace full = parse_capture(without_gyro(0, 0), "full.evemu");
  BOOST_TEST(full.warnings.empty());
  const double t0 = first_event_s + full.samples.front().t_s, t1 = first_event_s + full.samples.back().t_s;
  const double mid = 0.5 * (t0 + t1);
  // A trace's times count from its first kept sample: the full trace's times say where each is.
  const auto full_samples = [&](double from, double to) {
    return std::count_if(full.samples.begin(), full.samples.end(), [&](const TraceSample& x) {
      return first_event_s + x.t_s >= from && first_event_s + x.t_s < to;
    });
  };
  const Trace late = parse_capture(without_gyro(0, mid), "late.evemu");
  BOOST_TEST(static_cast<long>(late.samples.size()) == full_samples(mid - 0.002, 1e9));
  BOOST_REQUIRE(!late.warnings.empty());
  BOOST_TEST(contains(late.warnings.front(), "late.evemu:"), late.warnings.front());
  BOOST_TEST(contains(late.warnings.front(), "the MotionPlus stream starts here"), late.warnings.front());
  const Trace early = parse_capture(without_gyro(mid, 1e9), "early.evemu");
  // The last MotionPlus frame lies within 20 ms before mid (a frame every report, ≈ 10 ms).
  BOOST_TEST(static_cast<long>(early.samples.size()) <= full_samples(0, mid + 0.1 + 0.002));
  BOOST_TEST(static_cast<long>(early.samples.size()) >= full_samples(0, mid - 0.02 + 0.1));
  BOOST_REQUIRE(!early.warnings.empty());
  BOOST_TEST(contains(early.warnings.front(), "the MotionPlus stream ends here"), early.warnings.front());
  const Trace gap = parse_capture(without_gyro(mid, mid + 0.3), "gap.evemu");
  BOOST_TEST(gap.samples.size() == full.samples.size());
  BOOST_REQUIRE(gap.warnings.size() == 1u);
  BOOST_TEST(contains(gap.warnings.front(), "no MotionPlus frame from here"), gap.warnings.front());
  // Every sample in the silence, from its last frame on (≈ 10 ms before the cut) to the next, holds
  // that frame's rate and is flagged: at least the samples inside the cut, none outside it.
  long held = 0, held_outside = 0;
  for (const TraceSample& x : gap.samples)
    if (x.flags & kGyroHeld) {
      ++held;
      const double at = first_event_s + x.t_s;
      held_outside += at < mid - 0.02 || at > mid + 0.3 + 0.002;
    }
  BOOST_TEST(held >= full_samples(mid + 0.002, mid + 0.3 - 0.002));
  BOOST_TEST(held_outside == 0);
  // A silence inside the swing: the rate there is not measured, and the capture is unusable (cut
  // 0.16 s before the release, the speed read 5.54 m/s for the truth's 5.2, "usable with caveats").
  const double release_s = 12.5 + synthetic_release_time_s(th) + SyntheticSensor{}.latency_s;
  CaptureOptions o;
  o.members = 0;
  const CaptureAnalysis swing = analyse_capture(parse_capture(without_gyro(release_s - 0.17, release_s - 0.01), "swing.evemu"), o);
  BOOST_TEST(std::string(to_string(swing.verdict)) == "unusable");
  BOOST_REQUIRE(!swing.reasons.empty());
  BOOST_TEST(contains(swing.reasons.front(), "the MotionPlus sent no frame for 0.1 s or more during the swing"),
             swing.reasons.front());
}

BOOST_AUTO_TEST_CASE(identical_reports_of_a_still_remote_at_200_hz_are_not_repeats_but_repeats_are) {
  // A report log's repeat (the same report logged twice, flag R, dropped) was the same bytes less
  // than half the nominal 100 Hz period later: a noiseless still remote at 200 Hz lost 149 of its
  // reports as "repeats". Oracle: the recording's own counts; the synthetic sensor at 200 Hz without
  // noise sends identical reports 5 ± 2 ms apart (jitter ±1 ms) and repeats 5 % of its reports
  // 0.2–1.0 ms later.
  SyntheticThrow th;
  th.swing_rate_rad_s = 7.0;
  SyntheticSensor sensor;
  sensor.rate_hz = 200.0;
  sensor.jitter_s = 0.001;
  sensor.accel_noise_g = 0.0;
  sensor.gyro_noise_deg_s = 0.0;
  sensor.repeat_probability = 0.05;
  SyntheticTruth truth;
  const Trace t = parse_capture(synthetic_report_log(th, sensor, truth), "still200.log");
  const TimedSamples timed = analyse_timing(t);
  BOOST_TEST(truth.repeated_reports > 0);
  BOOST_TEST(timed.stats.repeated == std::size_t(truth.repeated_reports));
  BOOST_TEST(std::abs(timed.stats.clock_rate_hz - 200.0) < 1.0, timed.stats.clock_rate_hz);
}

BOOST_AUTO_TEST_CASE(a_byte_order_mark_and_lone_cr_line_ends_read_as_the_plain_file) {
  // Oracle: the plain file's own trace; a UTF-8 BOM before the first line and classic Mac line
  // ends (CR alone) must change nothing, in every format that has lines.
  SyntheticThrow th;
  th.swing_rate_rad_s = 7.0;
  SyntheticTruth truth;
  const std::string csv = synthetic_wiiyourself_csv(th, {}, {}, truth);
  const std::string trace = trace_csv_text(parse_capture(gentle_log(), "gentle.log"));
  for (const std::string& text :
       {gentle_log(), synthetic_evemu(th, {}, truth), synthetic_gesture(th, {}, truth), csv, trace}) {
    const Trace plain = parse_capture(text, "plain.cap");
    std::string cr = text;
    for (char& c : cr)
      if (c == '\n') c = '\r';
    for (const std::string& variant : {"\xEF\xBB\xBF" + text, cr}) {
      const Trace t = parse_capture(variant, "variant.cap");
      BOOST_TEST(t.format == plain.format);
      BOOST_TEST(detect_capture_format(variant) == plain.format);
      BOOST_REQUIRE(t.samples.size() == plain.samples.size());
      bool same = true;
      for (std::size_t k = 0; k < t.samples.size(); ++k)
        same = same && t.samples[k].t_s == plain.samples[k].t_s && t.samples[k].accel_g == plain.samples[k].accel_g &&
               t.samples[k].rate_deg_s == plain.samples[k].rate_deg_s && t.samples[k].line == plain.samples[k].line;
      BOOST_TEST(same, plain.format << ": a sample differs");
    }
  }
}

BOOST_AUTO_TEST_CASE(readings_beyond_the_sensor_or_out_of_bounds_name_their_line) {
  // The driver writes the accelerometer's 10-bit reading − 0x200 (−512..511): 5000 is no reading.
  const std::string ev = "N: Nintendo Wii Remote Accelerometer\nE: 1.0 0003 0003 5\nE: 1.0 0000 0000 0\n"
                         "E: 1.01 0003 0003 5000\n";
  BOOST_TEST(contains(error_of(ev), "bad.cap:4"));
  BOOST_TEST(contains(error_of(ev), "-512..511"));
  // A number no sensor reads (1e308 g) on line 4 is named by that line, not by its sample index.
  const std::string e = error_of(kCsvHead + "0,0,0,1,0,0,0,0,0,0,0,-\n0.01,1e308,0,1,0,0,0,0,0,0,0,-\n");
  BOOST_TEST(contains(e, "bad.cap:4"), e);
  BOOST_TEST(contains(e, "acceleration"), e);
}

BOOST_AUTO_TEST_CASE(times_stamped_in_unix_time_are_read_relative_to_the_first) {
  // Oracle: the same trace stamped from 0; 1.7e9 s (a Unix time) is far beyond the 1e6 s a
  // capture may last, but that bound is on time since the first sample.
  const Trace t = parse_capture(gentle_log(), "gentle.log");
  Trace shifted = t;
  for (TraceSample& x : shifted.samples) x.t_s += 1.7e9;
  const Trace back = parse_capture(trace_csv_text(shifted), "epoch.csv");
  BOOST_REQUIRE(back.samples.size() == t.samples.size());
  BOOST_TEST(back.samples.back().t_s - back.samples.front().t_s ==
                 t.samples.back().t_s - t.samples.front().t_s,
             boost::test_tools::tolerance(1e-6));  // %.17g of 1.7e9 s keeps 0.2 µs
}

BOOST_AUTO_TEST_CASE(a_header_calibration_wins_over_the_recorded_block_and_a_disagreement_is_a_warning) {
  // Oracle: the header's own numbers. The synthetic log records the remote's calibration block
  // (zero-g 506,513,518, one-g 610,617,621, SyntheticSensor's defaults).
  auto with_header = [](const std::string& zero, const std::string& one_g) {
    return parse_capture("# calibration.accel_zero_counts: " + zero + "\n# calibration.accel_one_g_counts: " + one_g +
                             "\n" + gentle_log(),
                         "cal.log");
  };
  auto disagreement = [](const Trace& t) {
    return std::count_if(t.warnings.begin(), t.warnings.end(),
                         [](const std::string& w) { return contains(w, "differs from the header's calibration"); });
  };
  const Trace other = with_header("500,500,500", "600,600,600");
  BOOST_TEST(other.calibration.accel_zero_counts == (std::array<double, 3>{500, 500, 500}));
  BOOST_TEST(other.calibration.accel_one_g_counts == (std::array<double, 3>{600, 600, 600}));
  BOOST_TEST(disagreement(other) >= 1);
  const Trace same = with_header("506,513,518", "610,617,621");
  BOOST_TEST(disagreement(same) == 0);
}

BOOST_AUTO_TEST_CASE(a_header_key_given_twice_is_refused_naming_both_lines) {
  // A second "# calibration.accel_one_g_counts" silently won (the last one), and turned a
  // capture's verdict from usable to unusable; which was meant cannot be known. Oracle: the input
  // rules, an error naming the file, the second line, the key, and the first line.
  const std::string twice = "# calibration.accel_one_g_counts: 610,617,621\n# calibration.accel_one_g_counts: 1000,1000,1000\n" + gentle_log();
  try {
    parse_capture(twice, "twice.log");
    BOOST_ERROR("a key given twice was taken");
  } catch (const InputError& e) {
    const std::string m = e.what();
    BOOST_TEST(contains(m, "twice.log:2: calibration.accel_one_g_counts: given twice (first on line 1)"), m);
  }
}

BOOST_AUTO_TEST_CASE(a_calibration_block_beside_count_lines_or_counts_no_remote_reports_are_refused) {
  // The block (EEPROM 0x16-0x1f) and the two count lines say the same thing: the later one silently
  // won. A count outside the device's reading (10 bits for the accelerometer, 14 for MotionPlus,
  // spec "Facts for the ingestion path") came from no remote. Oracle: the input rules, an error
  // naming the file, the line and the key.
  const std::string block = block_hex({506, 513, 518}, {610, 617, 621});
  BOOST_TEST(parse_capture("# calibration.block: " + block + "\n" + gentle_log(), "b.log").calibration.accel_one_g_counts ==
             (std::array<double, 3>{610, 617, 621}));  // the block alone reads
  const std::string both = "# calibration.block: " + block + "\n# calibration.accel_zero_counts: 500,500,500\n";
  BOOST_TEST(contains(error_of(both + gentle_log()), ":2: calibration.accel_zero_counts: conflicts with calibration.block on line 1"),
             error_of(both + gentle_log()));
  const std::string reversed = "# calibration.accel_one_g_counts: 600,600,600\n# calibration.block: " + block + "\n";
  BOOST_TEST(contains(error_of(reversed + gentle_log()), ":2: calibration.block: conflicts with calibration.accel_one_g_counts on line 1"),
             error_of(reversed + gentle_log()));
  BOOST_TEST(contains(error_of("# calibration.accel_zero_counts: 5e6,512,512\n" + gentle_log()), "0..1023"));
  BOOST_TEST(contains(error_of("# calibration.accel_one_g_counts: 610,-3,621\n" + gentle_log()), "0..1023"));
  BOOST_TEST(contains(error_of("# calibration.gyro_zero_counts: 8192,8192,16384\n" + gentle_log()), "0..16383"));
  BOOST_TEST(parse_capture("# calibration.gyro_zero_counts: 0,8100,16383\n" + gentle_log(), "g.log").calibration.gyro_zero_counts ==
             (std::array<double, 3>{0, 8100, 16383}));  // the ends of the range read
}

BOOST_AUTO_TEST_CASE(half_a_calibration_is_refused_and_the_two_count_lines_are_checked_in_either_order) {
  // One count line without the other took the nominal calibration's other half in silence (a
  // capture's path angle 12.75° against 10°, verdict "usable"). Oracle: the input rules, an error
  // naming the line given and the line missing; and the pair zero 616 / one-g 720, valid, must
  // read whichever line comes first (616 is the nominal one-g, which the first line alone met).
  BOOST_TEST(contains(error_of("# calibration.accel_zero_counts: 500,500,500\n" + gentle_log()),
                      "bad.cap:1: calibration.accel_zero_counts: is given without calibration.accel_one_g_counts"),
             error_of("# calibration.accel_zero_counts: 500,500,500\n" + gentle_log()));
  BOOST_TEST(contains(error_of("# note\n# calibration.accel_one_g_counts: 600,600,600\n" + gentle_log()),
                      "bad.cap:2: calibration.accel_one_g_counts: is given without calibration.accel_zero_counts"));
  for (const bool zero_first : {true, false}) {
    const std::string zero = "# calibration.accel_zero_counts: 616,616,616\n", one = "# calibration.accel_one_g_counts: 720,720,720\n";
    const Trace t = parse_capture((zero_first ? zero + one : one + zero) + gentle_log(), "pair.log");
    BOOST_TEST(t.calibration.accel_zero_counts == (std::array<double, 3>{616, 616, 616}));
    BOOST_TEST(t.calibration.accel_one_g_counts == (std::array<double, 3>{720, 720, 720}));
  }
  BOOST_TEST(contains(error_of("# calibration.accel_zero_counts: 600,600,600\n# calibration.accel_one_g_counts: 600,700,700\n" +
                               gentle_log()),
                      ":2: calibration.accel_one_g_counts: one-g and zero-g counts are 0 apart on X"));
  // In range but no remote's: 1 g of 2 counts would make the axis span ±256 g. Oracle: the
  // ADXL330's range (spec §4, ±3.5–4.6 g at clipping over ±512 counts: 110–150 counts per g), with
  // the bounds 26..400 of wiimote_report.hpp; the shipped captures' 104 passes.
  BOOST_TEST(contains(error_of("# calibration.accel_zero_counts: 512,512,512\n# calibration.accel_one_g_counts: 616,514,616\n" +
                               gentle_log()),
                      ":2: calibration.accel_one_g_counts: one-g and zero-g counts are 2 apart on Y"));
  const std::string tiny = block_hex({512, 512, 512}, {616, 616, 1000});
  BOOST_TEST(contains(error_of("# calibration.block: " + tiny + "\n" + gentle_log()), "are 488 apart on Z"));
  // A one-g point below zero-g, 104 counts away (the spacing of a real remote): the axis would read
  // every acceleration with its sign flipped (+0.317 g for −0.317 g on gentle_sidearm's X, judged
  // "usable" with an attack angle of 27.6° for the truth's 15°). Oracle: the +1 g reading lies
  // above the zero-g one (wiibrew.org, Wiimote, Accelerometer calibration).
  const std::string flipped = block_hex({512, 512, 512}, {408, 616, 616});
  BOOST_TEST(contains(error_of("# calibration.block: " + flipped + "\n" + gentle_log()),
                      "the one-g count 408 on X is below its zero-g count 512"), error_of("# calibration.block: " + flipped + "\n" + gentle_log()));
  BOOST_TEST(contains(error_of("# calibration.accel_zero_counts: 512,512,512\n# calibration.accel_one_g_counts: 616,408,616\n" +
                               gentle_log()),
                      ":2: calibration.accel_one_g_counts: the one-g count 408 on Y is below its zero-g count 512"));
}

BOOST_AUTO_TEST_CASE(a_second_calibration_block_that_differs_is_refused_and_a_late_header_still_wins_with_a_warning) {
  // A second 0x21 calibration reply replaced the first for every sample, the ones before it too,
  // and header count lines at the end of a log won over the block without the warning they get
  // at its top. Oracle: the input rules; the synthetic log's block is on line 2 (zero-g
  // 506,513,518, one-g 610,617,621).
  const std::string log = gentle_log();
  const auto block_at = log.find(" 21 00 00 f0 00 16 ");
  BOOST_REQUIRE(block_at != std::string::npos);
  const std::string block_line = log.substr(log.rfind('\n', block_at) + 1, log.find('\n', block_at) - log.rfind('\n', block_at));
  const std::string payload = block_line.substr(block_line.find(" 21 "));  // " 21 ... 00\n"
  const std::string other_hex = " " + block_hex({496, 496, 496}, {608, 608, 608});
  // The same reply with the other block's ten bytes (after " 21 bb bb se aa aa": 18 characters).
  const std::string other_payload = payload.substr(0, 18) + other_hex + payload.substr(18 + other_hex.size());
  const long lines = std::count(log.begin(), log.end(), '\n');
  const std::string second = log + "99.0" + other_payload;
  BOOST_TEST(contains(error_of(second), "bad.cap:" + std::to_string(lines + 1) +
                                            ": a second calibration block differs from the one on line 2"),
             error_of(second));
  BOOST_TEST(parse_capture(log + "99.0" + payload, "again.log").calibration.accel_one_g_counts ==
             (std::array<double, 3>{610, 617, 621}));  // the same block read again
  // Where the header states the calibration, neither block is used: each that differs is a warning.
  const Trace stated = parse_capture("# calibration.accel_zero_counts: 500,500,500\n# calibration.accel_one_g_counts: 600,600,600\n" +
                                         second,
                                     "stated.log");
  BOOST_TEST(stated.calibration.accel_one_g_counts == (std::array<double, 3>{600, 600, 600}));
  BOOST_TEST(std::count_if(stated.warnings.begin(), stated.warnings.end(), [&](const std::string& w) {
               return contains(w, "stated.log:" + std::to_string(lines + 3) + ": the remote's calibration block");
             }) == 1);
  // A block whose one-g lies 2 counts from its zero-g (no remote's): refused where it is the
  // calibration, not used (a warning) where the header states one.
  const std::string odd_hex = " " + block_hex({512, 512, 512}, {616, 514, 616});
  std::string odd = log;
  odd.replace(block_at + 18, odd_hex.size(), odd_hex);
  BOOST_TEST(contains(error_of(odd), "bad.cap:2: calibration block: one-g and zero-g counts are 2 apart on Y"), error_of(odd));
  BOOST_TEST(parse_capture("# calibration.accel_zero_counts: 506,513,518\n# calibration.accel_one_g_counts: 610,617,621\n" + odd,
                           "odd.log")
                 .calibration.accel_one_g_counts == (std::array<double, 3>{610, 617, 621}));
  const Trace late = parse_capture(log + "# calibration.accel_zero_counts: 500,500,500\n# calibration.accel_one_g_counts: 600,600,600\n",
                                   "late.log");
  BOOST_TEST(late.calibration.accel_one_g_counts == (std::array<double, 3>{600, 600, 600}));
  BOOST_TEST(std::count_if(late.warnings.begin(), late.warnings.end(), [](const std::string& w) {
               return contains(w, "late.log:2: the remote's calibration block") && contains(w, "differs from the header's");
             }) == 1);
}

BOOST_AUTO_TEST_CASE(a_trace_without_a_has_gyro_line_keeps_its_rates) {
  // Oracle: the rows themselves. Rates in the wx..wz columns are a MotionPlus's, stated or not;
  // an explicit `has_gyro: false` still wins.
  const std::string rows = "0,0,0,1,5,0,0,0,0,0,0,-\n0.01,0,0,1,6,0,0,0,0,0,0,-\n";
  BOOST_TEST(parse_capture(kCsvHead + rows, "t.csv").has_gyro);
  BOOST_TEST(!parse_capture(kCsvHead + "0,0,0,1,0,0,0,0,0,0,0,-\n", "t.csv").has_gyro);
  const std::string stated = std::string(kTraceCsvMagic) + "\n# has_gyro: false\n" + kTraceCsvColumns + "\n" + rows;
  BOOST_TEST(!parse_capture(stated, "t.csv").has_gyro);
}

BOOST_AUTO_TEST_SUITE_END()
