#include "tools/io/toml_prescan.hpp"

#include "tools/io/input_error.hpp"

namespace stoneskip {

std::uint32_t PrescannedToml::line_of(std::uint32_t parsed_line) const {
  if (parsed_line == 0 || source_line.empty()) return parsed_line;
  if (parsed_line >= source_line.size()) return source_line.back();
  return source_line[parsed_line];
}

namespace {

enum class State { normal, header, comment, basic, literal, ml_basic, ml_literal };

bool starts_with(const std::string& s, std::size_t i, const char* p) { return s.compare(i, 3, p) == 0; }

}  // namespace

PrescannedToml prescan_toml(const std::string& text, const std::string& name, bool name_lines) {
  PrescannedToml out;
  out.text.reserve(text.size() + text.size() / 8);
  out.source_line.reserve(64);
  out.source_line.push_back(0);
  out.source_line.push_back(1);

  // Which original lines are long (those get their arrays broken after each comma).
  std::vector<bool> long_line(1, false);
  {
    std::size_t start = 0;
    for (std::size_t i = 0; i <= text.size(); ++i)
      if (i == text.size() || text[i] == '\n') {
        long_line.push_back(i - start > kLongTomlLineBytes);
        start = i + 1;
      }
  }

  std::uint32_t line = 1;          // original line
  std::size_t out_line_bytes = 0;  // length of the current output line
  std::vector<char> brackets;      // open value brackets: '[' array, '{' inline table
  int inline_tables = 0;
  bool only_blanks = true;         // only blanks since the line began (a '[' then opens a header)
  State state = State::normal;
  State string_return = State::normal;  // where a string inside a header returns to

  auto emit_newline = [&](bool inserted) {
    out.text.push_back('\n');
    if (!inserted) ++line;
    out.source_line.push_back(line);
    out_line_bytes = 0;
  };
  auto emit = [&](char c) {
    out.text.push_back(c);
    if (++out_line_bytes > kMaxTomlLineBytes)
      throw_input_error(name, name_lines ? line : 0, "",
                        "line longer than " + std::to_string(kMaxTomlLineBytes) +
                            " characters (a limit: split long inline tables over [tables])");
  };

  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n') {
      emit_newline(false);
      only_blanks = true;
      if (state == State::comment || state == State::basic || state == State::literal) state = State::normal;
      if (state == State::header) state = State::normal;  // an unclosed header: toml11 reports it
      continue;
    }
    switch (state) {
      case State::comment:
        emit(c);
        continue;
      case State::basic:
        emit(c);
        if (c == '\\' && i + 1 < text.size() && text[i + 1] != '\n') emit(text[++i]);
        else if (c == '"') state = string_return;
        continue;
      case State::literal:
        emit(c);
        if (c == '\'') state = string_return;
        continue;
      case State::ml_basic:
        if (c == '\\' && i + 1 < text.size() && text[i + 1] != '\n') {
          emit(c);
          emit(text[++i]);
        } else if (starts_with(text, i, "\"\"\"")) {
          emit(c), emit(c), emit(c);
          i += 2;
          state = State::normal;
        } else {
          emit(c);
        }
        continue;
      case State::ml_literal:
        if (starts_with(text, i, "'''")) {
          emit(c), emit(c), emit(c);
          i += 2;
          state = State::normal;
        } else {
          emit(c);
        }
        continue;
      case State::header:
        emit(c);
        if (c == '"' || c == '\'') {
          string_return = State::header;
          state = c == '"' ? State::basic : State::literal;
        } else if (c == ']' && !(i + 1 < text.size() && text[i + 1] == ']')) {
          state = State::normal;
        }
        continue;
      case State::normal:
        break;
    }
    const bool blank = c == ' ' || c == '\t' || c == '\r';
    if (c == '#') {
      state = State::comment;
      emit(c);
    } else if (c == '"' || c == '\'') {
      string_return = State::normal;
      if (starts_with(text, i, c == '"' ? "\"\"\"" : "'''")) {
        emit(c), emit(c), emit(c);
        i += 2;
        state = c == '"' ? State::ml_basic : State::ml_literal;
      } else {
        emit(c);
        state = c == '"' ? State::basic : State::literal;
      }
    } else if (c == '[' && brackets.empty() && only_blanks) {
      emit(c);
      state = State::header;
    } else if (c == '[' || c == '{') {
      brackets.push_back(c);
      if (c == '{') ++inline_tables;
      if (static_cast<int>(brackets.size()) > kMaxTomlNesting)
        throw_input_error(name, name_lines ? line : 0, "",
                          "arrays or inline tables nested more than " + std::to_string(kMaxTomlNesting) + " deep");
      emit(c);
    } else if (c == ']' || c == '}') {
      if (!brackets.empty()) {
        if (brackets.back() == '{') --inline_tables;
        brackets.pop_back();
      }
      emit(c);
    } else if (c == ',' && !brackets.empty() && brackets.back() == '[' && inline_tables == 0 && long_line[line]) {
      emit(c);
      emit_newline(true);
    } else {
      emit(c);
    }
    if (!blank) only_blanks = false;
  }
  return out;
}

}  // namespace stoneskip
