#include "tools/capture/capture_text.hpp"

#include <cstdio>

#include "tools/io/input_error.hpp"

namespace stoneskip {

std::vector<TextLine> split_capture_lines(const std::string& text, const std::string& file) {
  std::vector<TextLine> lines;
  long number = 1;
  std::size_t begin = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    // A line ends at LF, CR LF, or a lone CR (classic Mac OS files, some loggers).
    const bool lone_cr = c == '\r' && (i + 1 == text.size() || text[i + 1] != '\n');
    if (c == '\n' || lone_cr) {
      std::string_view t(text.data() + begin, i - begin);
      if (!t.empty() && t.back() == '\r') t.remove_suffix(1);
      lines.push_back({number, t, false});
      ++number;
      begin = i + 1;
    } else if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7f) {
      char what[96];
      std::snprintf(what, sizeof what, "binary data (byte 0x%02x): not a text capture", c);
      throw_input_error(file, number, "", what);
    }
  }
  if (begin < text.size()) {
    std::string_view t(text.data() + begin, text.size() - begin);
    if (!t.empty() && t.back() == '\r') t.remove_suffix(1);
    lines.push_back({number, t, true});
  }
  return lines;
}

void malformed_line(const std::string& file, const TextLine& line, const std::string& what,
                    std::vector<std::string>& warnings) {
  if (line.last_unterminated) {
    warnings.push_back(input_location(file, line.number, "") + ": " + what +
                       " on the unterminated last line: the recording looks cut short; line dropped");
    return;
  }
  throw_input_error(file, line.number, "", what);
}

bool header_comment(std::string_view line, std::string& key, std::string& value) {
  line = trim(line);
  if (line.empty() || line.front() != '#') return false;
  line.remove_prefix(1);
  const auto colon = line.find(':');
  if (colon == std::string_view::npos) return false;
  key = std::string(trim(line.substr(0, colon)));
  value = std::string(trim(line.substr(colon + 1)));
  if (key.empty() || key.find(' ') != std::string::npos) return false;
  return true;
}

}  // namespace stoneskip
