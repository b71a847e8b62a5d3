// Decoding of Wii Remote input reports against values computed by hand from the byte layouts of
// model/README.md §4 (WiiBrew): every field is exact integer arithmetic, so the comparisons are exact.
#include <boost/test/unit_test.hpp>

#include <vector>

#include "tools/capture/wiimote_report.hpp"

using namespace stoneskip;

namespace {
DecodedReport decode(const std::vector<std::uint8_t>& b) { return decode_report(b.data(), b.size()); }

// MotionPlus bytes for yaw 8000 (0x1f40, slow), roll 8192 (0x2000, slow), pitch 8500 (0x2134, fast):
//   e0 = 0x40, e1 = 0x00, e2 = 0x34, e3 = 0x1f<<2 | yaw slow 0x02 = 0x7e,
//   e4 = 0x20<<2 | roll slow 0x02 = 0x82, e5 = 0x21<<2 | MotionPlus marker 0x02 = 0x86.
const std::vector<std::uint8_t> kMotionPlus{0x40, 0x00, 0x34, 0x7e, 0x82, 0x86};

void check_motionplus(const DecodedReport& r) {
  BOOST_TEST(r.has_motionplus);
  BOOST_TEST(r.gyro_raw[0] == 8500);  // pitch (X)
  BOOST_TEST(r.gyro_raw[1] == 8192);  // roll (Y)
  BOOST_TEST(r.gyro_raw[2] == 8000);  // yaw (Z)
  BOOST_TEST(!r.gyro_slow[0]);
  BOOST_TEST(r.gyro_slow[1]);
  BOOST_TEST(r.gyro_slow[2]);
}
}  // namespace

BOOST_AUTO_TEST_SUITE(wiimote_report)

BOOST_AUTO_TEST_CASE(report_0x31_gives_buttons_and_ten_bit_acceleration) {
  // Hand computation: b0 = 0x60 → X low bits 3; b1 = 0x64 → Y bit1 = (0x64>>4)&2 = 2, Z bit1 =
  // (0x64>>5)&2 = 2, button B (0x04); X = 0x80<<2|3 = 515, Y = 0x90<<2|2 = 578, Z = 0xa0<<2|2 = 642.
  const DecodedReport r = decode({0x31, 0x60, 0x64, 0x80, 0x90, 0xa0});
  BOOST_TEST(r.length_ok);
  BOOST_TEST(r.has_accel);
  BOOST_TEST(r.accel_raw[0] == 515);
  BOOST_TEST(r.accel_raw[1] == 578);
  BOOST_TEST(r.accel_raw[2] == 642);
  BOOST_TEST(r.buttons == kButtonB);
  BOOST_TEST(!r.has_motionplus);
}

BOOST_AUTO_TEST_CASE(report_0x33_skips_the_twelve_ir_bytes) {
  // Hand computation: X = 0x7f<<2 = 508, Y = 0x81<<2 = 516, Z = 0x99<<2 = 612, button A (0x08).
  std::vector<std::uint8_t> b{0x33, 0x00, 0x08, 0x7f, 0x81, 0x99};
  b.insert(b.end(), 12, 0xff);
  const DecodedReport r = decode(b);
  BOOST_TEST(r.accel_raw[0] == 508);
  BOOST_TEST(r.accel_raw[1] == 516);
  BOOST_TEST(r.accel_raw[2] == 612);
  BOOST_TEST(r.buttons == kButtonA);
  BOOST_TEST(!r.has_motionplus);
}

BOOST_AUTO_TEST_CASE(report_0x35_carries_motionplus_in_the_first_six_extension_bytes) {
  std::vector<std::uint8_t> b{0x35, 0x00, 0x00, 0x80, 0x80, 0x80};
  b.insert(b.end(), kMotionPlus.begin(), kMotionPlus.end());
  b.insert(b.end(), 10, 0x00);
  const DecodedReport r = decode(b);
  BOOST_TEST(r.accel_raw[0] == 512);
  check_motionplus(r);
}

BOOST_AUTO_TEST_CASE(report_0x37_carries_motionplus_after_ten_ir_bytes) {
  std::vector<std::uint8_t> b{0xa1, 0x37, 0x00, 0x00, 0x80, 0x80, 0x80};  // with the HID header a1
  b.insert(b.end(), 10, 0xff);
  b.insert(b.end(), kMotionPlus.begin(), kMotionPlus.end());
  const DecodedReport r = decode(b);
  BOOST_TEST(r.id == 0x37);
  check_motionplus(r);
}

BOOST_AUTO_TEST_CASE(a_pass_through_extension_is_not_read_as_motionplus) {
  // Byte 5 bit 1 clear: extension data, not MotionPlus.
  std::vector<std::uint8_t> b{0x35, 0x00, 0x00, 0x80, 0x80, 0x80, 0x40, 0x00, 0x34, 0x7e, 0x82, 0x84};
  b.insert(b.end(), 10, 0x00);
  BOOST_TEST(!decode(b).has_motionplus);
}

BOOST_AUTO_TEST_CASE(truncated_and_unknown_reports_are_recognised_as_such) {
  // Oracle: the layout table (0x35 needs 22 bytes with the id); 0x99 is no Wii Remote report.
  const DecodedReport t = decode({0x35, 0x00, 0x00, 0x80});
  BOOST_TEST(!t.length_ok);
  BOOST_TEST(t.needed_bytes == 22u);
  BOOST_TEST(int(decode({0x99, 0x00}).kind) == int(ReportKind::unknown));
}

BOOST_AUTO_TEST_CASE(encoding_then_decoding_gives_back_every_field) {
  // Oracle: the encoder is the decoder's inverse for every value the report can carry (Y and Z
  // even: their lowest bit is not sent).
  for (std::uint8_t id : {0x31, 0x33, 0x35, 0x37}) {
    const std::array<int, 3> a{1023, 2, 514};
    const std::array<int, 3> g{16383, 0, 8191};
    const std::array<bool, 3> slow{true, false, true};
    const auto bytes = encode_report(id, kButtonB | kButtonA, a, g, slow);
    const DecodedReport r = decode(bytes);
    BOOST_TEST(r.accel_raw == a);
    BOOST_TEST(r.buttons == (kButtonA | kButtonB));
    if (id == 0x35 || id == 0x37) {
      BOOST_TEST(r.gyro_raw == g);
      BOOST_TEST(r.gyro_slow == slow);
    }
  }
}

BOOST_AUTO_TEST_CASE(the_calibration_block_decodes_with_its_checksum) {
  // Hand computation: zero-g bytes 0x80 → 512, one-g 0x9a → 616; checksum
  // (3·0x80 + 3·0x9a + 0x55) mod 256 = 931 mod 256 = 0xa3.
  const std::uint8_t b[10] = {0x80, 0x80, 0x80, 0x00, 0x9a, 0x9a, 0x9a, 0x00, 0x00, 0xa3};
  const auto c = decode_calibration_block(b, 10);
  BOOST_REQUIRE(c.has_value());
  BOOST_TEST(c->zero_counts[0] == 512);
  BOOST_TEST(c->one_g_counts[2] == 616);
  BOOST_TEST(c->checksum_ok);
  const auto e = encode_calibration_block({512, 512, 512}, {616, 616, 616});
  BOOST_TEST(e[9] == 0xa3);
}

BOOST_AUTO_TEST_SUITE_END()
