#include "reports/common/code_span.hpp"

namespace stoneskip {

std::size_t code_span(const std::string& s, std::size_t open, std::string* content) {
  std::size_t n = 0;
  while (open + n < s.size() && s[open + n] == '`') ++n;
  for (std::size_t i = open + n; i < s.size();) {
    if (s[i] != '`') {
      ++i;
      continue;
    }
    std::size_t m = 0;
    while (i + m < s.size() && s[i + m] == '`') ++m;
    if (m == n) {
      if (content) {
        std::string c = s.substr(open + n, i - open - n);
        if (c.size() >= 2 && c.front() == ' ' && c.back() == ' ' && c.find_first_not_of(' ') != std::string::npos)
          c = c.substr(1, c.size() - 2);
        *content = c;
      }
      return i + m;
    }
    i += m;
  }
  return std::string::npos;
}

}  // namespace stoneskip
