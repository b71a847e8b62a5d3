#include "tools/io/input_error.hpp"

namespace stoneskip {

std::string input_location(const std::string& file, long line, const std::string& key) {
  std::string s = file;
  if (line > 0) {
    s.push_back(':');
    s.append(std::to_string(line));
  }
  if (!key.empty()) {
    if (!s.empty()) s.append(": ");
    s.append(key);
  }
  return s;
}

void throw_input_error(const std::string& file, long line, const std::string& key,
                       const std::string& what) {
  std::string where = input_location(file, line, key);
  // One line, always: fold any newline a library put into `what`.
  std::string msg = where.empty() ? what : where + ": " + what;
  for (char& c : msg) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  throw InputError(msg);
}

}  // namespace stoneskip
