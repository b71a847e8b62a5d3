#pragma once
// What is checked in a TOML text before toml11 (3.7) parses it, because toml11 itself would crash or
// crawl:
//  * nesting: toml11's parser recurses once per nested array or inline table, and ~8 000 levels
//    overflow the 8 MB stack (SIGSEGV). Deeper than kMaxTomlNesting levels is refused.
//  * long lines: toml11 builds an error message holding the whole current line each time it tries
//    a value type that does not match (an integer before a float, ...), so each array element costs
//    the length of its line: 100 000 numbers on one line took 28 s of CPU, on 100 000 lines 0.36 s.
//    The scan therefore breaks every long line after each comma of an array (outside strings,
//    comments and inline tables, where TOML allows a newline), and keeps the map from the new
//    lines to the file's, so messages still name the line as written. A line that is still longer
//    than kMaxTomlLineBytes (a long inline table) is refused.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace stoneskip {

constexpr int kMaxTomlNesting = 64;                    // arrays and inline tables inside each other
constexpr std::size_t kMaxTomlLineBytes = 64 * 1024;   // after long arrays are broken over lines
constexpr std::size_t kLongTomlLineBytes = 1024;       // lines longer than this are broken
constexpr std::size_t kMaxTomlFileBytes = 64u << 20;   // 64 MiB: a case or study file

struct PrescannedToml {
  std::string text;                      // what toml11 parses
  std::vector<std::uint32_t> source_line;  // [k] = the original line of line k (1-based; [0] unused)
  std::uint32_t line_of(std::uint32_t parsed_line) const;
};

// Throws InputError ("NAME:LINE: ...", without the line when name_lines is false: an override)
// on nesting deeper than kMaxTomlNesting or a line longer than kMaxTomlLineBytes after the split.
PrescannedToml prescan_toml(const std::string& text, const std::string& name, bool name_lines = true);

}  // namespace stoneskip
