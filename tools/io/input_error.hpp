#pragma once
// The one exception type of the I/O edge: bad input (a case file, a capture, a command-line value,
// an output path). Its message is a single line that names the file and the line or key, and what
// is wrong. The command catches it, prints it, and exits with status 2.
#include <stdexcept>
#include <string>

namespace stoneskip {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& one_line_message) : std::runtime_error(without_nul(one_line_message)) {}

 private:
  // what() is a C string: a NUL quoted from the input (a TOML key "a\u0000b") would end the message
  // there, so it is written \x00, as printable_text writes the other control characters.
  static std::string without_nul(const std::string& s) {
    std::string out;
    out.reserve(s.size());
    for (char c : s) {
      if (c == '\0') out += "\\x00";
      else out += c;
    }
    return out;
  }
};

// "FILE:LINE: KEY: WHAT" with the empty parts left out.
std::string input_location(const std::string& file, long line, const std::string& key);

[[noreturn]] void throw_input_error(const std::string& file, long line, const std::string& key,
                                    const std::string& what);

}  // namespace stoneskip
