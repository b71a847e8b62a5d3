#include "tools/io/printable_text.hpp"

#include <cstdio>

namespace stoneskip {

namespace {

// The length of the valid UTF-8 sequence starting at s[i] (RFC 3629 §4, the UTF8-2..4 rules),
// 0 where there is none; its code point in cp.
std::size_t utf8_sequence(std::string_view s, std::size_t i, unsigned& cp) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned c = b(i);
  std::size_t n = 0;
  unsigned lo = 0x80, hi = 0xBF;  // the second byte's range (the first continuation)
  if (c >= 0xC2 && c <= 0xDF) n = 2;
  else if (c == 0xE0) n = 3, lo = 0xA0;
  else if (c >= 0xE1 && c <= 0xEC) n = 3;
  else if (c == 0xED) n = 3, hi = 0x9F;  // no surrogates
  else if (c >= 0xEE && c <= 0xEF) n = 3;
  else if (c == 0xF0) n = 4, lo = 0x90;
  else if (c >= 0xF1 && c <= 0xF3) n = 4;
  else if (c == 0xF4) n = 4, hi = 0x8F;  // nothing past U+10FFFF
  else return 0;
  if (i + n > s.size()) return 0;
  if (b(i + 1) < lo || b(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (b(i + k) < 0x80 || b(i + k) > 0xBF) return 0;
  cp = c & (0xFF >> (n + 1));
  for (std::size_t k = 1; k < n; ++k) cp = (cp << 6) | (b(i + k) & 0x3F);
  return n;
}

void append_escape(std::string& out, unsigned char c) {
  char e[5];
  std::snprintf(e, sizeof e, "\\x%02X", c);
  out += e;
}

}  // namespace

std::string printable_text(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) {
      if (c == '\n') out += "\\n";
      else if (c == '\r') out += "\\r";
      else if (c == '\t' || (c >= 0x20 && c != 0x7F)) out += static_cast<char>(c);
      else append_escape(out, c);
      ++i;
      continue;
    }
    unsigned cp = 0;
    const std::size_t n = utf8_sequence(s, i, cp);
    if (n == 0 || cp <= 0x9F) {  // not UTF-8, or a C1 control: each byte escaped
      const std::size_t end = n == 0 ? i + 1 : i + n;
      for (; i < end; ++i) append_escape(out, static_cast<unsigned char>(s[i]));
      continue;
    }
    out.append(s.substr(i, n));
    i += n;
  }
  return out;
}

}  // namespace stoneskip
