#pragma once
// What every text capture reader shares: splitting into numbered lines, refusing binary data,
// parsing numbers strictly, and the truncation rule: a malformed LAST line without a final newline
// is taken as a recording cut short (a warning, the line dropped); anywhere else a malformed line
// is an InputError naming the file and the line.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "verification/captures/strict_numbers.hpp"  // trim, split_fields, parse_real, parse_integer

namespace stoneskip {

// A capture's times lie within this of their median (a file may stamp them in Unix time; a time
// beyond is refused, naming its line: tools/capture/capture_format.cpp).
constexpr double kMaxCaptureTimeSpread_s = 1e6;

struct TextLine {
  long number = 0;         // 1-based
  std::string_view text;   // without the newline and a trailing '\r'
  bool last_unterminated = false;  // the file's last line, with no newline after it
};

// Splits text into lines. Throws InputError "FILE: binary data (byte 0x.. at line N)" when the text
// holds a NUL or other control byte (tab, CR, LF excepted).
std::vector<TextLine> split_capture_lines(const std::string& text, const std::string& file);

// Reports a malformed line: a warning (recorded in warnings) when it is the unterminated last line,
// an InputError otherwise.
void malformed_line(const std::string& file, const TextLine& line, const std::string& what,
                    std::vector<std::string>& warnings);

// "# key: value" header comments: returns key and value (trimmed) when the line has that form.
bool header_comment(std::string_view line, std::string& key, std::string& value);

}  // namespace stoneskip
