#include "tools/io/dotted_key.hpp"

#include <sstream>

#include <toml.hpp>

namespace stoneskip {

namespace {

bool is_bare(unsigned char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

const char* kBareRule = "a bare key component holds only letters, digits, _ and - (quote any other: \"…\")";

// The end of the quoted part that opens at key[i] (the index of its closing quote), or npos.
std::size_t closing_quote(const std::string& key, std::size_t i) {
  const char quote = key[i];
  std::size_t end = i + 1;
  while (end < key.size() && key[end] != quote) end += quote == '"' && key[end] == '\\' ? 2 : 1;
  return end < key.size() ? end : std::string::npos;
}

}  // namespace

bool parse_dotted_key(const std::string& key, std::vector<std::string>& parts, std::string* why) {
  auto fail = [&](const std::string& what) {
    if (why) *why = what;
    return false;
  };
  parts.clear();
  std::size_t i = 0;
  auto blanks = [&] {
    while (i < key.size() && (key[i] == ' ' || key[i] == '\t')) ++i;
  };
  while (true) {
    blanks();
    std::string part;
    if (i < key.size() && (key[i] == '"' || key[i] == '\'')) {
      const std::size_t end = closing_quote(key, i);
      if (end == std::string::npos) return fail("a quoted key component has no closing quote");
      const std::string quoted = key.substr(i, end + 1 - i);
      if (key[i] == '"') {
        try {  // the escapes, read by the TOML parser itself
          std::istringstream in("k = " + quoted + "\n");
          part = toml::find<std::string>(toml::parse(in, "key"), "k");
        } catch (const std::exception&) {
          return fail("a quoted key component is not a TOML string: " + quoted);
        }
      } else {
        part = quoted.substr(1, quoted.size() - 2);
      }
      if (part.empty()) return fail("empty key component");
      if (part.find('.') != std::string::npos)
        return fail("the quoted component " + quoted + " holds a '.': no key has one (quote each part on its own)");
      i = end + 1;
    } else {
      const std::size_t start = i;
      while (i < key.size() && is_bare(static_cast<unsigned char>(key[i]))) ++i;
      part = key.substr(start, i - start);
      if (part.empty()) return fail(i < key.size() && key[i] != '.' ? kBareRule : "empty key component");
    }
    parts.push_back(part);
    blanks();
    if (i == key.size()) return true;
    if (key[i] != '.') return fail("expected '.' after the key component '" + part + "' (" + kBareRule + ")");
    ++i;
  }
}

std::string join_dotted_key(const std::vector<std::string>& parts) {
  std::string s;
  for (const auto& p : parts) s += (s.empty() ? "" : ".") + p;
  return s;
}

std::string canonical_dotted_key(const std::string& key) {
  std::vector<std::string> parts;
  if (!parse_dotted_key(key, parts, nullptr)) return key;
  for (const auto& p : parts)
    for (unsigned char c : p)
      if (!is_bare(c)) return key;
  return join_dotted_key(parts);
}

std::size_t assignment_equals(const std::string& assignment) {
  for (std::size_t i = 0; i < assignment.size(); ++i) {
    if (assignment[i] == '=') return i;
    if (assignment[i] == '"' || assignment[i] == '\'') {
      const std::size_t end = closing_quote(assignment, i);
      if (end == std::string::npos) return assignment.find('=', i);  // the key is malformed: said later
      i = end;
    }
  }
  return std::string::npos;
}

}  // namespace stoneskip
