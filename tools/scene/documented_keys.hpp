#pragma once
// Test support (header only, for the property tests of tools/scene and tools/cli): every key
// documented in cases/README.md's TOML blocks, with the type of its example value and the bounds
// its comment states, and values that the documentation says are bad for it. The documentation
// is the oracle: a key whose documented bound the code does not enforce, or a documented key the
// code does not read, fails the tests.
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace stoneskip::test {

enum class KeyKind { number, integer, string, array };

struct DocumentedKey {
  std::string block;    // "stone", "scene", "wave", "baseline", "sweep": the README section it is in
  std::string section;  // "stone", "throw.state", "water.initial", ...
  std::string key;      // "radius_m"
  KeyKind kind = KeyKind::number;
  bool enumerated = false;  // a string with documented alternatives
  bool has_lo = false, has_hi = false;
  double lo = 0, hi = 0;
  std::string example;
  std::string full() const { return section.empty() ? key : section + "." + key; }
};

// A plain stone case (the paper's prism, 1 s) that the bad values are set into.
inline constexpr const char* kPlainStoneCase = R"([stone]
shape = "prism"
radius_m = 0.03
thickness_m = 0.008
density_kg_m3 = 2500.0
[throw]
speed_m_s = 8.0
path_angle_deg = 10.0
attack_angle_deg = 10.0
height_m = 0.1
[solver]
dt_s = 1.0e-3
contact_dt_s = 1.0e-5
t_max_s = 1.0
)";

// A plain live water for it: a plane wave on 50 × 50 cells, stable (σ = c dt / d = 0.3125).
inline constexpr const char* kPlainWater = R"(
[water]
stencil = "nine_point_isotropic"
nx = 50
ny = 50
cell_m = 0.02
wave_speed_m_s = 1.25
boundary = "reflecting"
dt_s = 0.005
[water.initial]
kind = "plane_wave"
amplitude_m = 0.02
wavelength_m = 1.0
)";

struct BadValue {
  std::string text;  // TOML
  std::string why;   // "wrong type", "below the bound", ...
};

inline std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t p = s.find(from); p != std::string::npos; p = s.find(from, p + to.size())) s.replace(p, from.size(), to);
  return s;
}

inline bool parse_double(const std::string& t, double& out) {
  const std::string s = replace_all(t, "−", "-");
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  while (end && *end == ' ') ++end;
  return end && end != s.c_str() && *end == 0;
}

// The bounds "[lo, hi]" in a comment: the last pair for a scalar, the first for an array (whose
// comment may then give a component its own pair).
inline void read_bounds(const std::string& comment, DocumentedKey& k) {
  static const std::regex pair(R"(\[([^\[\],]+),([^\[\],]+)\])");
  std::vector<std::pair<std::string, std::string>> found;
  for (std::sregex_iterator it(comment.begin(), comment.end(), pair), end; it != end; ++it) found.emplace_back((*it)[1], (*it)[2]);
  if (found.empty()) {
    // ">= 1" (sweep files) is a lower bound alone.
    static const std::regex at_least(R"(>=\s*(-?[0-9.eE+-]+))");
    std::smatch m;
    if (std::regex_search(comment, m, at_least)) k.has_lo = parse_double(m[1], k.lo);
    return;
  }
  const auto& b = k.kind == KeyKind::array ? found.front() : found.back();
  k.has_lo = parse_double(b.first, k.lo);
  k.has_hi = parse_double(b.second, k.hi);
}

inline std::vector<DocumentedKey> documented_keys(const std::string& readme_path = "cases/README.md") {
  std::ifstream in(readme_path);
  std::vector<DocumentedKey> keys;
  std::string line, heading, block, section;
  bool in_toml = false;
  static const std::regex key_line(R"(^#?\s*([a-z_]+)\s*=\s*("[^"]*"|\[[^\]]*\]|[^#\s]+)\s*(#.*)?$)");
  static const std::regex header(R"(^#?\s*\[?\[([a-z_.]+)\]\]?\s*(#.*)?$)");  // [table] or [[array]]
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0 || line.rfind("### ", 0) == 0) heading = line;
    if (line.rfind("```", 0) == 0) {
      in_toml = !in_toml && line == "```toml";
      section.clear();
      if (heading.find("Stone cases") != std::string::npos) block = "stone";
      else if (heading.find("live water") != std::string::npos) block = "scene";
      else if (heading.find("Wave cases") != std::string::npos) block = "wave";
      else if (heading.find("golden baselines") != std::string::npos) block = "baseline";
      else if (heading.find("Sweep files") != std::string::npos) block = "sweep";
      else block.clear();
      continue;
    }
    if (!in_toml || block.empty()) continue;
    std::smatch m;
    if (std::regex_match(line, m, header)) {
      section = m[1];
      continue;
    }
    if (!std::regex_match(line, m, key_line)) continue;
    DocumentedKey k;
    k.block = block;
    k.section = section;
    k.key = m[1];
    k.example = m[2];
    const std::string comment = m[3];
    double d = 0;
    if (k.example[0] == '"')
      k.kind = KeyKind::string;
    else if (k.example[0] == '[')
      k.kind = KeyKind::array;
    else if (k.example.find_first_of(".eE") == std::string::npos && parse_double(k.example, d))
      k.kind = KeyKind::integer;
    else
      k.kind = KeyKind::number;
    k.enumerated = k.kind == KeyKind::string && (comment.find('"') != std::string::npos || comment.find('|') != std::string::npos);
    read_bounds(comment, k);
    keys.push_back(k);
  }
  return keys;
}

// The README's TOML block under the heading that contains `heading` (a valid file of that kind).
inline std::string readme_block(const std::string& heading, const std::string& readme_path = "cases/README.md") {
  std::ifstream in(readme_path);
  std::string line, text;
  bool in_block = false, after_heading = false;
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0) after_heading = line.find(heading) != std::string::npos;
    if (!after_heading && !in_block) continue;
    if (line == "```toml") {
      in_block = true;
      continue;
    }
    if (in_block && line.rfind("```", 0) == 0) break;
    if (in_block) text += line + "\n";
  }
  return text;
}

// The README's sweep block as a sweep file in which `k` can be set: a random design for its
// random-only keys (samples, seed), with the key's line replaced by `key = value`.
inline std::string sweep_text_with(const DocumentedKey& k, const std::string& value) {
  std::string t = "\n" + readme_block("Sweep files");
  if (k.section == "design" && (k.key == "samples" || k.key == "seed")) {
    t = replace_all(t, "kind = \"grid\"", "kind = \"random\"");
    t = replace_all(t, "# samples = ", "samples = ");
    t = replace_all(t, "# seed = ", "seed = ");
    const auto c = t.find("\ncount = ");
    t.erase(c, t.find('\n', c + 1) - c);
  }
  const auto p = t.find("\n" + k.key + " = ");
  if (p == std::string::npos) return "";
  t.replace(p + 1, t.find('\n', p + 1) - p - 1, k.key + " = " + value);
  return t.substr(1);
}

// How an error names the key: a [[vary]] table by its number.
inline std::string error_name(const DocumentedKey& k) {
  if (k.block == "sweep" && k.section == "vary") return "vary[1]." + k.key;
  return k.full();
}

inline std::string number_text(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  std::string s = b;
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

// Values the documentation says are bad for a key: other types, non-finite numbers, numbers
// beyond a double or 64 bits, huge counts, and numbers just outside the documented bounds.
inline std::vector<BadValue> bad_values(const DocumentedKey& k) {
  std::vector<BadValue> v;
  switch (k.kind) {
    case KeyKind::number:
    case KeyKind::integer: {
      for (const char* t : {"\"x\"", "true", "[1.0]", "{ a = 1.0 }"}) v.push_back({t, "wrong type"});
      for (const char* t : {"nan", "inf", "-inf"}) v.push_back({t, "not finite"});
      for (const char* t : {"1e400", "-1e400", "1e-400"}) v.push_back({t, "beyond a double"});
      if (k.kind == KeyKind::integer) {
        v.push_back({"2.5", "not an integer"});
        v.push_back({"99999999999999999999", "beyond 64 bits"});
        v.push_back({"-99999999999999999999", "beyond 64 bits"});
        if (k.has_lo) v.push_back({std::to_string(static_cast<long long>(k.lo) - 1), "below the bound"});
        if (k.has_hi) v.push_back({std::to_string(static_cast<long long>(k.hi) + 1), "above the bound"});
        if (k.has_hi) v.push_back({"9223372036854775807", "huge count"});
      } else {
        if (k.has_lo) {
          v.push_back({number_text(k.lo > 0 ? k.lo / 2 : (k.lo == 0 ? -1.0 : 2 * k.lo)), "below the bound"});
          v.push_back({"-1e300", "far below the bound"});
          if (k.lo > 0) v.push_back({"0.0", "zero below the bound"});
        }
        if (k.has_hi) {
          v.push_back({number_text(k.hi > 0 ? 2 * k.hi : (k.hi == 0 ? 1.0 : k.hi / 2)), "above the bound"});
          v.push_back({"1e300", "far above the bound"});
        }
      }
      break;
    }
    case KeyKind::string:
      for (const char* t : {"1", "2.5", "true", "[\"a\"]", "{ a = \"b\" }"}) v.push_back({t, "wrong type"});
      if (k.enumerated) v.push_back({"\"no_such_value\"", "not one of the documented values"});
      break;
    case KeyKind::array: {
      if (k.example.size() > 1 && k.example[1] == '"') {  // an array of strings: names or overrides
        for (const char* t : {"1.0", "\"x\"", "[1.0]", "[[\"a\"]]"}) v.push_back({t, "wrong type"});
        v.push_back({"[\"no_such_value\"]", "an element that is not one of the documented values"});
        break;
      }
      // The example with its first element replaced.
      const std::string inner = k.example.substr(1, k.example.size() - 2);
      const auto comma = inner.find(',');
      const std::string rest = comma == std::string::npos ? "" : inner.substr(comma);
      for (const char* t : {"1.0", "\"x\"", "[[1.0]]"}) v.push_back({t, "wrong type"});
      v.push_back({"[]", "empty"});
      for (const char* t : {"\"a\"", "nan", "inf", "1e400", "-1e400"}) v.push_back({"[" + std::string(t) + rest + "]", "bad element"});
      if (k.has_lo) v.push_back({"[" + number_text(k.lo > 0 ? k.lo / 2 : (k.lo == 0 ? -1.0 : 2 * k.lo)) + rest + "]", "element below the bound"});
      if (k.has_hi) v.push_back({"[" + number_text(k.hi > 0 ? 2 * k.hi : 1.0) + rest + "]", "element above the bound"});
      break;
    }
  }
  return v;
}

}  // namespace stoneskip::test
