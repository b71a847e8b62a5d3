// The header-driven CSV reader. Oracles: the documented table of names (what a spelling must be
// recognised as), the same synthetic readings written as a raw report log (what the CSV's rows must
// read back as), and defects planted on known lines and columns (what the error must name).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cctype>

#include <cmath>
#include <fstream>
#include <numbers>
#include <regex>
#include <string>

#include "tools/capture/capture_format.hpp"
#include "tools/capture/capture_text.hpp"
#include "tools/capture/csv_columns.hpp"
#include "tools/capture/header_csv.hpp"
#include "tools/capture/synthetic_capture.hpp"
#include "tools/io/input_error.hpp"

using namespace stoneskip;

namespace {

std::string error_of(const std::string& text, const HeaderCsvOptions& o = {}) {
  try {
    CaptureReadOptions r;
    r.csv = o;
    parse_capture(text, "bad.csv", r);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// The skipping throw the shipped WiiYourself-style capture records.
SyntheticThrow throw_10ms() {
  SkippingThrowSpec spec;
  spec.speed_m_s = 10.0;
  return skipping_throw(spec);
}

SyntheticSensor idle_remote() {
  SyntheticSensor idle;
  idle.rate_hz = 99.6;
  idle.seed = 19;
  return idle;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(header_csv)

BOOST_AUTO_TEST_CASE(column_names_are_recognised_whatever_their_case_units_and_device_suffix) {
  // Oracle: the table in tools/capture/README.md ("Header-driven CSV").
  struct Case {
    const char* header;
    CsvField field;
    int remote;
    CsvUnit unit;
  };
  const Case cases[] = {
      {"Acc X", CsvField::ax, 0, CsvUnit::none},
      {"acc_x [g]", CsvField::ax, 0, CsvUnit::g},
      {"Acc X #WM1", CsvField::ax, 1, CsvUnit::none},
      {"AccelerationY (m/s^2)", CsvField::ay, 0, CsvUnit::m_s2},
      {"accZ", CsvField::az, 0, CsvUnit::none},
      {"Speed Yaw #WM2", CsvField::speed_yaw, 2, CsvUnit::none},
      {"MotionPlus.Speed.Pitch", CsvField::speed_pitch, 0, CsvUnit::none},
      {"Raw Roll #wm 3", CsvField::raw_roll, 3, CsvUnit::none},
      {"MotionPlus.Raw.Yaw [dec]", CsvField::raw_yaw, 0, CsvUnit::dec},
      {"Time", CsvField::time, 0, CsvUnit::none},
      {"time_ms", CsvField::time, 0, CsvUnit::ms},
      {"t_s", CsvField::time, 0, CsvUnit::s},
      {"\"Timestamp (us)\"", CsvField::time, 0, CsvUnit::us},
      {"wx_deg_s", CsvField::wx, 0, CsvUnit::deg_s},
      {"gyro z [rad/s]", CsvField::wz, 0, CsvUnit::rad_s},
      {"Yaw rate", CsvField::wz, 0, CsvUnit::none},
      {"Pitch #WM1", CsvField::orientation_pitch, 1, CsvUnit::none},
      {"Buttons #WM2", CsvField::buttons, 2, CsvUnit::none},
      {"Button B", CsvField::button_b, 0, CsvUnit::none},
      {"slow_yaw", CsvField::slow_yaw, 0, CsvUnit::none},
  };
  for (const auto& c : cases) {
    BOOST_TEST_CONTEXT(c.header) {
      const auto r = recognise_column(c.header);
      BOOST_REQUIRE(r.has_value());
      BOOST_TEST(int(r->field) == int(c.field));
      BOOST_TEST(r->remote == c.remote);
      BOOST_TEST(int(r->unit) == int(c.unit));
    }
  }
  for (const char* unknown : {"Temperature", "Yaw", "Acc W", "acc x [furlong]", "Battery #WM1"})
    BOOST_TEST(!recognise_column(unknown).has_value(), unknown);
}

BOOST_AUTO_TEST_CASE(the_table_in_the_readme_is_what_the_reader_recognises) {
  // Oracle: tools/capture/README.md's table of recognised names: every name in a row must be
  // recognised as one of that row's keys, and the row's units must be the field's.
  std::ifstream in("tools/capture/README.md");
  BOOST_REQUIRE(in.good());
  const std::regex ticked("`([^`]+)`");
  std::string line;
  int rows = 0;
  while (std::getline(in, line)) {
    if (line.rfind("| `", 0) != 0) continue;
    std::vector<std::string> cells;
    for (std::size_t b = 1, e; (e = line.find('|', b)) != std::string::npos; b = e + 1) cells.push_back(line.substr(b, e - b));
    if (cells.size() != 4) continue;  // the other tables of the README
    std::vector<CsvField> keys;
    for (std::sregex_iterator it(cells[0].begin(), cells[0].end(), ticked), end; it != end; ++it) {
      const std::string key = (*it)[1];
      if (key.back() == '*') {  // slow_*, fast_*
        for (const char* axis : {"pitch", "roll", "yaw"}) keys.push_back(*csv_field_from_key(key.substr(0, key.size() - 1) + axis));
      } else {
        const auto f = csv_field_from_key(key);
        BOOST_REQUIRE_MESSAGE(f.has_value(), "README key " << key);
        keys.push_back(*f);
      }
    }
    if (keys.empty()) continue;
    ++rows;
    for (std::sregex_iterator it(cells[2].begin(), cells[2].end(), ticked), end; it != end; ++it) {
      const std::string name = (*it)[1];
      const auto r = recognise_column(name);
      BOOST_TEST_CONTEXT("README name '" << name << "'") {
        BOOST_REQUIRE(r.has_value());
        BOOST_TEST((std::find(keys.begin(), keys.end(), r->field) != keys.end()));
      }
    }
    const auto& units = csv_field_info(keys.front()).units;
    const std::string cell(trim(cells[3]));
    BOOST_TEST(cell.rfind(units.front() == CsvUnit::none ? "none" : to_string(units.front()), 0) == 0u,
               "default unit of " << cells[0] << ": README '" << cell << "'");
    for (CsvUnit u : units)
      if (u != CsvUnit::none) BOOST_TEST(cell.find(to_string(u)) != std::string::npos, cells[0] << " lacks " << to_string(u));
  }
  BOOST_TEST(rows == 10);
}

BOOST_AUTO_TEST_CASE(a_wiiyourself_log_reads_back_the_readings_the_report_log_of_the_same_throw_holds) {
  // Oracle: the generator draws the same readings for the same throw and sensor; written as a raw
  // report log and as a two-remote WiiYourself!-style CSV they must give the same samples: the
  // same MotionPlus rates and range modes (raw words and WiiYourself!'s Speed), the accelerations
  // to within WiiYourself!'s 8-bit step, the button, and times to within the CSV's 1 ms rounding.
  const SyntheticThrow th = throw_10ms();
  SyntheticSensor s;
  s.repeat_probability = 0;  // a repeat makes no CSV row; keep the streams comparable
  SyntheticTruth t_log, t_csv;
  const std::string csv = synthetic_wiiyourself_csv(th, s, idle_remote(), t_csv);
  BOOST_TEST(detect_capture_format(csv) == "csv");
  const Trace wm = parse_capture(csv, "two.csv");
  const Trace log = parse_capture(synthetic_report_log(th, s, t_log), "same.log");
  BOOST_TEST(wm.format == "csv");
  BOOST_TEST(wm.has_gyro);
  BOOST_TEST(!wm.gyro_mode_inferred);  // the modes come from the Speed columns
  // The CSV starts once both remotes have reported (its first row, written for #WM2, carries #WM1's
  // first report at #WM2's time), and rows the thrower's remote did not change are not in it:
  // align on the second CSV sample's words, then match samples by time.
  constexpr double kRounding_s = 0.0011;        // two stamps rounded to 1 ms, against 1 µs stamps
  constexpr double kEightBit_g = 1.0 / 25.0;    // one 8-bit step (one-g minus zero-g ≈ 26 counts)
  constexpr double kRate_deg_s = 1e-9;          // the same words through the same calibration
  std::size_t j = 0, matched = 0;
  while (j < log.samples.size() && log.samples[j].rate_deg_s != wm.samples[1].rate_deg_s) ++j;
  BOOST_REQUIRE(j < log.samples.size());
  const double t0_log = log.samples[j].t_s, t0_wm = wm.samples[1].t_s;
  for (std::size_t k = 1; k < wm.samples.size(); ++k) {
    const TraceSample& x = wm.samples[k];
    while (j < log.samples.size() && log.samples[j].t_s - t0_log < x.t_s - t0_wm - kRounding_s) ++j;
    BOOST_REQUIRE(j < log.samples.size());
    const TraceSample& y = log.samples[j];
    BOOST_TEST(std::abs((y.t_s - t0_log) - (x.t_s - t0_wm)) <= kRounding_s);
    BOOST_TEST((x.accel_g - y.accel_g).cwiseAbs().maxCoeff() <= kEightBit_g);
    BOOST_TEST((x.rate_deg_s - y.rate_deg_s).cwiseAbs().maxCoeff() <= kRate_deg_s);
    BOOST_TEST(x.gyro_fast == y.gyro_fast);
    BOOST_TEST((x.buttons & kButtonB) == (y.buttons & kButtonB));
    ++matched;
  }
  BOOST_TEST(matched + 5 >= log.samples.size());  // the first few reports and unchanged ones left no row
  // The second remote is there, lying still on the table: --remote 2 reads it.
  CaptureReadOptions two;
  two.csv.remote = 2;
  const Trace table = parse_capture(csv, "two.csv", two);
  BOOST_TEST(std::abs(table.samples[table.samples.size() / 2].accel_g.z() - 1.0) <= kEightBit_g);
  for (const auto& x : table.samples) BOOST_TEST(x.buttons == 0u);
}

BOOST_AUTO_TEST_CASE(any_csv_can_be_mapped_with_columns_and_units) {
  // Oracle: the values written (a German-language CSV with ';' separators, seconds, m/s² and rad/s).
  const std::string text =
      "Zeit;Beschl X;Beschl Y;Beschl Z;Dreh X;Dreh Y;Dreh Z;Taste\n"
      "0.000;0;0;9.80665;0;0;0.5;0\n"
      "0.010;1.0;0;9.80665;0;0;0.5;1\n"
      "0.021;2.0;0;9.80665;0;0;0.5;1\n";
  BOOST_TEST(detect_capture_format(text).empty());  // nothing recognisable without a map
  CaptureReadOptions o;
  o.csv.columns =
      "t[s]=Zeit,ax[m/s2]=Beschl X,ay[m/s2]=Beschl Y,az[m/s2]=Beschl Z,wx[rad/s]=Dreh X,wy[rad/s]=Dreh Y,"
      "wz[rad/s]=Dreh Z,button_b=Taste";
  const Trace t = parse_capture(text, "de.csv", o);
  BOOST_REQUIRE(t.samples.size() == 3u);
  constexpr double kExact = 1e-12;
  BOOST_TEST(std::abs(t.samples[2].t_s - 0.021) < kExact);
  BOOST_TEST(std::abs(t.samples[1].accel_g.x() - 1.0 / 9.80665) < kExact);
  BOOST_TEST(std::abs(t.samples[0].accel_g.z() - 1.0) < kExact);
  BOOST_TEST(std::abs(t.samples[0].rate_deg_s.z() - 0.5 * 180.0 / std::numbers::pi) < kExact);
  BOOST_TEST(t.samples[0].buttons == 0u);
  BOOST_TEST(t.samples[1].buttons == kButtonB);
}

BOOST_AUTO_TEST_CASE(a_linear_acceleration_beside_the_accelerometer_is_left_unused_and_alone_is_refused) {
  // main read a phone's "linear acceleration" (gravity removed) as the accelerometer: beside the
  // accelerometer's own columns the file was refused (two columns for ax), alone it was read as a
  // specific force it is not. Oracle: the values written; the bad-input rule (one line, the file).
  const std::string both =
      "timestamp,accelerometerX,accelerometerY,accelerometerZ,linear acceleration x,linear acceleration y,"
      "linear acceleration z\n0,0.1,0.2,9.80665,0.1,0.2,0\n10,0.1,0.2,9.80665,0.1,0.2,0\n";
  const Trace t = parse_capture(both, "phone.csv");
  BOOST_REQUIRE(t.samples.size() == 2u);
  BOOST_TEST(std::abs(t.samples[1].accel_g.z() - 1.0) < 1e-12);  // the accelerometer's, in m/s² (detected)
  BOOST_TEST(std::any_of(t.notes.begin(), t.notes.end(),
                         [](const std::string& n) { return contains(n, "not recognised") && contains(n, "'linear acceleration x'"); }));
  const std::string alone =
      "timestamp,linear acceleration x,linear acceleration y,linear acceleration z,gyroscopeX,gyroscopeY,gyroscopeZ\n"
      "0,0.1,0.2,0,0.5,0,0\n10,0.1,0.2,0,0.5,0,0\n";
  const std::string e = error_of(alone);
  BOOST_TEST(contains(e, "bad.csv:1: no acceleration columns"), e);
}

BOOST_AUTO_TEST_CASE(time_units_come_from_the_header_or_from_the_median_interval) {
  // Oracle: the documented rule (below 0.5: s; 0.5–500: ms; above: µs) on 10 ms intervals.
  auto second_sample = [](const std::string& time_header, const char* t1) {
    const std::string text = time_header + ",ax,ay,az\n0,0,0,1\n" + t1 + ",0,0,1\n";
    return parse_capture(text, "t.csv").samples[1].t_s;
  };
  BOOST_TEST(second_sample("Time", "0.01") == 0.01);
  BOOST_TEST(std::abs(second_sample("Time", "10") - 0.01) < 1e-15);
  BOOST_TEST(std::abs(second_sample("Time", "10000") - 0.01) < 1e-15);
  BOOST_TEST(std::abs(second_sample("Time [ms]", "0.25") - 0.00025) < 1e-15);  // the header wins
}

BOOST_AUTO_TEST_CASE(a_wrapping_32_bit_millisecond_counter_is_unwrapped_and_a_real_step_back_is_refused) {
  // Oracle: the stamps themselves. timeGetTime wraps at 2^32 ms; a log that runs across the wrap
  // keeps its steps (9, 5 and 11 ms). A step back that is no wrap (from 5000 to 4990) still names its line.
  const std::string wrap = "Time,ax,ay,az\n4294967286,0,0,1\n4294967295,0,0,1\n4,0,0,1\n15,0,0,1\n";
  const Trace t = parse_capture(wrap, "wrap.csv");
  BOOST_REQUIRE(t.samples.size() == 4u);
  BOOST_TEST(std::abs(t.samples[2].t_s - 0.014) < 1e-12);
  BOOST_TEST(std::abs(t.samples[3].t_s - 0.025) < 1e-12);
  BOOST_TEST(std::any_of(t.notes.begin(), t.notes.end(), [](const std::string& n) { return contains(n, "wrap.csv:4"); }));
  const std::string e = error_of("Time,ax,ay,az\n5000,0,0,1\n4990,0,0,1\n");
  BOOST_TEST(contains(e, "bad.csv:3"), e);
  BOOST_TEST(contains(e, "4990 after 5000"), e);
}

BOOST_AUTO_TEST_CASE(a_quoted_field_may_hold_the_separator_and_an_open_quote_names_its_line) {
  // Oracle: RFC 4180. A note column whose quoted text holds commas and a doubled quote is one
  // field; the samples are the rows' numbers. A quote left open on a row names that row.
  const std::string text = "Time,ax,ay,az,note\n0,0,0,1,\"x, y\"\n10,0.5,0,1,\"say \"\"hi\"\", then go\"\n";
  const Trace t = parse_capture(text, "q.csv");
  BOOST_REQUIRE(t.samples.size() == 2u);
  BOOST_TEST(t.samples[1].accel_g.x() == 0.5);
  // A quote inside a field (not opening it) is an ordinary character: a header `Size (")`.
  const Trace inch = parse_capture("Time,ax,ay,az,Size (\")\n0,0,0,1,5\n10,0,0,1,5\n", "inch.csv");
  BOOST_TEST(inch.samples.size() == 2u);
  const std::string e = error_of("Time,ax,ay,az,note\n0,0,0,1,\"open\n10,0,0,1,ok\n");
  BOOST_TEST(contains(e, "bad.csv:2"), e);
  BOOST_TEST(contains(e, "quoted field"), e);
}

BOOST_AUTO_TEST_CASE(rate_columns_take_their_range_modes_from_fast_columns_or_else_from_their_size) {
  // Oracle: the report log's own range modes (the MotionPlus flags in each report). The same
  // samples written as a CSV of rates in deg/s with fast-mode columns must keep them; without
  // the columns a rate beyond the slow range (8192 counts / 20 per deg/s) must read as fast.
  SyntheticThrow th;
  th.swing_rate_rad_s = 10.0;  // about 570 deg/s: past the slow range, the MotionPlus switches
  SyntheticTruth truth;
  const Trace log = parse_capture(synthetic_report_log(th, SyntheticSensor{}, truth), "gentle.log");
  std::string with = "time (s),ax (g),ay (g),az (g),wx (deg/s),wy (deg/s),wz (deg/s),btn_b,fast pitch,fast roll,fast yaw\n";
  std::string without = "time (s),ax (g),ay (g),az (g),wx (deg/s),wy (deg/s),wz (deg/s),btn_b\n";
  for (const TraceSample& x : log.samples) {
    char row[320];
    std::snprintf(row, sizeof row, "%.9f,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%d", x.t_s, x.accel_g.x(), x.accel_g.y(),
                  x.accel_g.z(), x.rate_deg_s.x(), x.rate_deg_s.y(), x.rate_deg_s.z(), (x.buttons & kButtonB) ? 1 : 0);
    without += std::string(row) + "\n";
    with += std::string(row) + "," + (x.gyro_fast[0] ? "1" : "0") + "," + (x.gyro_fast[1] ? "1" : "0") + "," +
            (x.gyro_fast[2] ? "1" : "0") + "\n";
  }
  const Trace a = parse_capture(with, "with.csv"), b = parse_capture(without, "without.csv");
  BOOST_REQUIRE(a.samples.size() == log.samples.size());
  BOOST_REQUIRE(b.samples.size() == log.samples.size());
  int fast = 0, mismatches = 0, size_rule = 0, beyond = 0;
  const double slow_range = log.calibration.gyro_range_deg_s(false);
  for (std::size_t k = 0; k < log.samples.size(); ++k)
    for (int i = 0; i < 3; ++i) {
      fast += log.samples[k].gyro_fast[i];
      mismatches += a.samples[k].gyro_fast[i] != log.samples[k].gyro_fast[i];
      // Beyond the slow range the MotionPlus was in fast mode (the log's own flag says so): the
      // reader without mode columns must say fast there.
      if (std::abs(b.samples[k].rate_deg_s[i]) > slow_range) {
        ++beyond;
        size_rule += !b.samples[k].gyro_fast[i] || !log.samples[k].gyro_fast[i];
      }
    }
  BOOST_TEST(fast > 0);
  BOOST_TEST(mismatches == 0);
  BOOST_TEST(!a.gyro_mode_inferred);
  BOOST_TEST(beyond > 0);
  BOOST_TEST(size_rule == 0);
  BOOST_TEST(b.gyro_mode_inferred);
}

BOOST_AUTO_TEST_CASE(wiiyourself_speed_columns_alone_give_the_rate_with_its_sign_reversed) {
  // Oracle: WiiYourself! reports −(raw − 0x1F7F)·scale; stoneskip's rate is +(raw − zero)/scale.
  const std::string text = "Time,Acc X,Acc Y,Acc Z,Speed Pitch,Speed Roll,Speed Yaw,Buttons\n"
                           "100,0,0,1,1.5,-2.0,500.0,0400\n";
  const Trace t = parse_capture(text, "speed.csv");
  BOOST_TEST(t.samples[0].rate_deg_s.x() == -1.5);
  BOOST_TEST(t.samples[0].rate_deg_s.y() == 2.0);
  BOOST_TEST(t.samples[0].rate_deg_s.z() == -500.0);
  BOOST_TEST(t.samples[0].gyro_fast[2]);   // beyond the slow range (±409.6 deg/s)
  BOOST_TEST(!t.samples[0].gyro_fast[0]);
  BOOST_TEST(t.samples[0].buttons == kButtonB);  // Button.Bits 0x0400 is B
}

BOOST_AUTO_TEST_CASE(bad_input_names_the_file_the_line_and_the_column) {
  const std::string head = "Time,Acc X,Acc Y,Acc Z,Raw Yaw,Raw Pitch,Raw Roll\n";
  BOOST_TEST(contains(error_of(head + "0,0,0,1,1f7f,1f7f,1f7f\n10,0,0,1,1f7f,zz,1f7f\n"), "bad.csv:3: Raw Pitch:"));
  BOOST_TEST(contains(error_of(head + "0,0,0,1,1f7f,1f7f,4000\n"), "14-bit"));
  BOOST_TEST(contains(error_of(head + "0,0,0,1,1f7f,1f7f\n20,0,0,1,1f7f,1f7f,1f7f\n"), "bad.csv:2"));
  BOOST_TEST(contains(error_of(head + "10,0,0,1,1f7f,1f7f,1f7f\n5,0,0,1,1f7f,1f7f,1f7f\n"), "bad.csv:3: Time: time goes backwards"));
  BOOST_TEST(contains(error_of(head + "0,0,nan,1,1f7f,1f7f,1f7f\n"), "bad.csv:2: Acc Y: not a number"));
  BOOST_TEST(contains(error_of("Time,Acc X [ms],Acc Y,Acc Z\n0,0,0,1\n"), "bad.csv:1: Acc X [ms]: unit 'ms'"));
  BOOST_TEST(contains(error_of("Time,Acc X,acc_x,Acc Y,Acc Z\n0,0,0,0,1\n"), "both give ax"));
  BOOST_TEST(contains(error_of("Time,Acc X,Acc Y,Gyro X\n0,0,0,1\n"), "needs all three"));
  BOOST_TEST(contains(error_of(head + "0,0,0,1,1f7f,1f7f,1f7f\n", {2, ""}), "--remote: no remote #WM2"));
  BOOST_TEST(contains(error_of(head + "0,0,0,1,1f7f,1f7f,1f7f\n", {0, "ax=Acc Q"}), "no column 'Acc Q'"));
  BOOST_TEST(contains(error_of(head + "0,0,0,1,1f7f,1f7f,1f7f\n", {0, "accel=Acc X"}), "unknown key"));
  // A cut-short last line is a warning, as for every reader.
  const Trace t = parse_capture(head + "0,0,0,1,1f7f,1f7f,1f7f\n10,0,0,1,1f7f,1f7f,1f7f\n20,0,0", "cut.csv");
  BOOST_TEST(t.samples.size() == 2u);
  BOOST_TEST(t.warnings.size() == 1u);
}

BOOST_AUTO_TEST_CASE(a_column_mapped_to_several_keys_or_with_an_unknown_unit_is_refused_by_name) {
  // Oracle: a column holds one quantity, so "Acc X" given as ax, ay and az is an error naming the
  // column and its first key; a known name with a unit stoneskip cannot read names that unit.
  const std::string head = "Time,Acc X,Acc Y,Acc Z\n0,0,0,1\n10,0,0,1\n";
  const std::string twice = error_of(head, {0, "ax=Acc X,ay=Acc X,az=Acc X"});
  BOOST_TEST(contains(twice, "--columns: ay: column 'Acc X' is already mapped to ax"), twice);
  BOOST_TEST(twice.find('\n') == std::string::npos);
  const std::string mg = error_of("Time,Acc X [mg],Acc Y [mg],Acc Z [mg],Gyro X,Gyro Y,Gyro Z\n0,0,0,1000,0,0,0\n");
  BOOST_TEST(contains(mg, "bad.csv:1: Acc X [mg]: unit 'mg' is not supported"), mg);
}

BOOST_AUTO_TEST_CASE(cr_only_line_endings_read_as_lf_line_endings) {
  // Oracle: the same file with LF endings; CR-only (classic Mac OS) must give the same samples.
  const std::string lf = "Time,Acc X,Acc Y,Acc Z\n0,0,0,1\n10,0.5,0,1\n20,1,0,1\n";
  std::string cr = lf;
  std::replace(cr.begin(), cr.end(), '\n', '\r');
  const Trace a = parse_capture(lf, "lf.csv"), b = parse_capture(cr, "cr.csv");
  BOOST_REQUIRE(b.samples.size() == 3u);
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    BOOST_TEST(a.samples[i].t_s == b.samples[i].t_s);
    BOOST_TEST(a.samples[i].accel_g.x() == b.samples[i].accel_g.x());
  }
}

BOOST_AUTO_TEST_CASE(the_first_remote_with_data_is_read_by_default) {
  // Oracle: remote #WM1 is all zeros (not connected); #WM2 has data.
  const std::string text = "Time,Acc X #WM1,Acc Y #WM1,Acc Z #WM1,Acc X #WM2,Acc Y #WM2,Acc Z #WM2\n"
                           "0,0,0,0,0.1,0,1\n10,0,0,0,0.2,0,1\n";
  const Trace t = parse_capture(text, "two.csv");
  BOOST_TEST(t.samples[1].accel_g.x() == 0.2);
  BOOST_TEST(contains(error_of(text, {1, ""}), "has no data"));
}

BOOST_AUTO_TEST_CASE(time_going_backwards_on_a_row_skipped_for_this_remote_is_refused) {
  // A row whose thrower's data repeat the previous row's is skipped (#WM2's idle remote wrote it),
  // and its time went unchecked: 100 ms taken off it passed, while the same on a kept row was an
  // error. Oracle: one logger's clock runs forward over every row. The shipped two-remote CSV's
  // first row whose #WM1 fields (3rd to 14th) repeat the row before gets its time cut by 100 ms.
  std::ifstream f("cases/captures/skip_two_remotes_wiiyourself.csv");
  std::vector<std::string> lines;
  for (std::string l; std::getline(f, l);) lines.push_back(l);
  BOOST_REQUIRE(lines.size() > 50u);
  const auto fields = [](const std::string& l) {
    std::vector<std::string> out;
    std::size_t a = 0;
    for (std::size_t b; (b = l.find(',', a)) != std::string::npos; a = b + 1) out.push_back(l.substr(a, b - a));
    out.push_back(l.substr(a));
    return out;
  };
  std::size_t at = 0;
  for (std::size_t i = 1; i < lines.size() && at == 0; ++i) {
    const auto p = fields(lines[i - 1]), q = fields(lines[i]);
    if (p.size() > 14 && q.size() == p.size() && !q[0].empty() && std::isdigit(static_cast<unsigned char>(q[0][0])) &&
        std::equal(p.begin() + 2, p.begin() + 14, q.begin() + 2))
      at = i;
  }
  BOOST_REQUIRE(at > 0);
  auto q = fields(lines[at]);
  q[1] = std::to_string(std::stol(q[1]) - 100);
  std::string edited;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::string l = lines[i];
    if (i == at) {
      l = q[0];
      for (std::size_t k = 1; k < q.size(); ++k) l += "," + q[k];
    }
    edited += l + "\n";
  }
  const std::string e = error_of(edited);
  BOOST_TEST(e.find("bad.csv:" + std::to_string(at + 1) + ":") != std::string::npos, e);
  BOOST_TEST(e.find("time goes backwards") != std::string::npos, e);
}

BOOST_AUTO_TEST_SUITE_END()
