#include "verification/captures/capture_trace.hpp"

namespace stoneskip {

namespace {
constexpr struct {
  std::uint32_t flag;
  char letter;
} kLetters[] = {{kSaturatedX, 'X'}, {kSaturatedY, 'Y'}, {kSaturatedZ, 'Z'},
                {kGyroSaturated, 'P'}, {kRepeated, 'R'}, {kGapBefore, 'G'}, {kGyroHeld, 'H'}};
}  // namespace

std::string flags_to_string(std::uint32_t flags) {
  std::string s;
  for (const auto& l : kLetters)
    if (flags & l.flag) s += l.letter;
  return s.empty() ? "-" : s;
}

bool flags_from_string(const std::string& s, std::uint32_t& out) {
  out = 0;
  if (s == "-") return true;
  if (s.empty()) return false;
  for (char c : s) {
    bool known = false;
    for (const auto& l : kLetters)
      if (c == l.letter) {
        out |= l.flag;
        known = true;
      }
    if (!known) return false;
  }
  return true;
}

}  // namespace stoneskip
