// Messages quote what users' files hold. Oracle: the well-formed UTF-8 byte sequences of RFC 3629
// §4 (the Unicode Standard's Table 3-7): those are kept unless they are control characters; every
// other byte is written as \xNN, so that no Latin-1 byte, escape sequence or line break reaches
// the terminal raw.
#include <boost/test/unit_test.hpp>

#include <string>

#include "tools/io/input_error.hpp"
#include "tools/io/printable_text.hpp"

using stoneskip::printable_text;

BOOST_AUTO_TEST_SUITE(printable_text_suite)

BOOST_AUTO_TEST_CASE(valid_utf8_and_tabs_are_kept) {
  const std::string s = "a\tb: 10 °, x → y, \xE6\x96\x87 \xF0\x9F\x98\x80 U+10FFFF=\xF4\x8F\xBF\xBF";
  BOOST_TEST(printable_text(s) == s);
}

BOOST_AUTO_TEST_CASE(line_breaks_and_controls_are_escaped) {
  BOOST_TEST(printable_text("a\nb\rc") == "a\\nb\\rc");
  BOOST_TEST(printable_text("\x1B[31mred\x7F") == "\\x1B[31mred\\x7F");
  BOOST_TEST(printable_text(std::string("nul\0x", 5)) == "nul\\x00x");
  // The C1 controls (U+0080..U+009F: CSI is U+009B), though well-formed UTF-8.
  BOOST_TEST(printable_text("\xC2\x9B" "2J") == "\\xC2\\x9B2J");
  BOOST_TEST(printable_text("\xC2\xA0") == "\xC2\xA0");  // U+00A0, the first code point past C1
}

BOOST_AUTO_TEST_CASE(bytes_outside_utf8_are_escaped_one_by_one) {
  BOOST_TEST(printable_text("caf\xE9 ok") == "caf\\xE9 ok");           // Latin-1
  BOOST_TEST(printable_text("\xC0\xAF") == "\\xC0\\xAF");              // overlong '/'
  BOOST_TEST(printable_text("\xE0\x80\xAF") == "\\xE0\\x80\\xAF");     // overlong, three bytes
  BOOST_TEST(printable_text("\xED\xA0\x80") == "\\xED\\xA0\\x80");     // a surrogate, U+D800
  BOOST_TEST(printable_text("\xF4\x90\x80\x80") == "\\xF4\\x90\\x80\\x80");  // past U+10FFFF
  BOOST_TEST(printable_text("\xF5\x80") == "\\xF5\\x80");
  BOOST_TEST(printable_text("end \xE2\x82") == "end \\xE2\\x82");     // cut short at the end
  // A lead byte followed by a valid sequence: only the lead is escaped, the rest is kept.
  BOOST_TEST(printable_text("\xE2\xC3\xA9") == "\\xE2\xC3\xA9");
  BOOST_TEST(printable_text("\xFF\xFE") == "\\xFF\\xFE");
}

BOOST_AUTO_TEST_CASE(an_input_error_keeps_what_follows_a_nul) {
  // Oracle: the message as written, with the NUL spelt \x00. what() is a C string, so a key
  // "spin_rev_s\0x" from a TOML file once printed "throw.spin_rev_s" and nothing after it: a
  // valid key's name, and not what was wrong.
  const stoneskip::InputError e(std::string("f.toml:20: throw.spin_rev_s\0x: unknown key", 42));
  BOOST_TEST(std::string(e.what()) == "f.toml:20: throw.spin_rev_s\\x00x: unknown key");
}

BOOST_AUTO_TEST_SUITE_END()
