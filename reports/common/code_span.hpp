#pragma once
// A Markdown code span, as the reports write it and as the pages' reader and the tables' escaping
// read it (CommonMark 0.30 §6.1): one reading, shared, so that the two cannot drift apart.
#include <cstddef>
#include <string>

namespace stoneskip {

// A code span opening at s[open] (a run of n backticks) ends at the next run of exactly n
// backticks. Returns the index after that run, or npos when there is none (the opening run is then
// text). When `content` is given it receives the span's content, with one space stripped from each
// end when both ends have one and it is not all spaces (reports/common/section.cpp pads a content
// that starts or ends with a backtick).
std::size_t code_span(const std::string& s, std::size_t open, std::string* content = nullptr);

}  // namespace stoneskip
