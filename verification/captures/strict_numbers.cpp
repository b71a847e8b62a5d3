#include "verification/captures/strict_numbers.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "tools/io/input_error.hpp"

namespace stoneskip {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split_fields(std::string_view line, bool comma) {
  std::vector<std::string_view> out;
  if (comma) {
    std::size_t begin = 0;
    for (std::size_t i = 0; i <= line.size(); ++i) {
      if (i == line.size() || line[i] == ',') {
        out.push_back(trim(line.substr(begin, i - begin)));
        begin = i + 1;
      }
    }
    return out;
  }
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t b = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > b) out.push_back(line.substr(b, i - b));
  }
  return out;
}

std::optional<double> parse_real(std::string_view f) {
  f = trim(f);
  if (f.empty() || f.size() > 64) return std::nullopt;
  // strtod needs a terminated string; also refuse hex floats, "nan", "inf".
  char buf[72];
  for (std::size_t i = 0; i < f.size(); ++i) {
    const char c = f[i];
    if (!((c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == 'e' || c == 'E')) return std::nullopt;
    buf[i] = c;
  }
  buf[f.size()] = '\0';
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(buf, &end);
  if (end != buf + f.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<long long> parse_integer(std::string_view f, int base) {
  f = trim(f);
  if (f.empty()) return std::nullopt;
  long long v = 0;
  const auto r = std::from_chars(f.data(), f.data() + f.size(), v, base);
  if (r.ec != std::errc() || r.ptr != f.data() + f.size()) return std::nullopt;
  return v;
}

std::pair<std::string, std::string> split_setting(const std::string& setting, const std::string& where) {
  const auto eq = setting.find('=');
  if (eq == std::string::npos) throw_input_error(where, 0, setting, "expected key=value");
  return {std::string(trim(std::string_view(setting).substr(0, eq))), std::string(trim(std::string_view(setting).substr(eq + 1)))};
}

}  // namespace stoneskip
