#include "tools/io/toml_table.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "tools/io/atomic_file.hpp"
#include "tools/io/dotted_key.hpp"
#include "tools/io/edit_distance.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/toml_prescan.hpp"

namespace stoneskip {

namespace {

constexpr const char* kSetName = "--set";

std::string short_type(const toml::value& v) {
  std::ostringstream s;
  s << v.type();
  return s.str();
}

// A number in a message: %g, never std::to_string's fixed 6 decimals or 309 digits.
std::string num(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

// A value outside [lo, hi] as the message shows it: six digits, or the shortest text that reads
// back as it where six digits would print a bound ("90.0000001" is not shown as 90).
std::string got(double v, double lo, double hi) {
  const std::string six = num(v);
  if (six != num(lo) && six != num(hi)) return six;
  char b[64];
  for (int digits = 7; digits <= 17; ++digits) {
    std::snprintf(b, sizeof b, "%.*g", digits, v);
    if (std::strtod(b, nullptr) == v) break;
  }
  return b;
}

// The text of a value as written (toml11 keeps the line and the column of each value's region).
std::string token_of(const toml::value& v) {
  const auto loc = v.location();
  const std::string& l = loc.line_str();
  if (loc.column() == 0 || loc.column() - 1 >= l.size()) return "";
  std::string t = l.substr(loc.column() - 1, loc.region());
  std::string out;
  for (char c : t)
    if (c != '_') out.push_back(c);
  return out;
}

bool nonzero_mantissa(const std::string& t) {
  for (char c : t) {
    if (c == 'e' || c == 'E') break;
    if (c >= '1' && c <= '9') return true;
  }
  return false;
}

// What is wrong with a number toml11 read, or "" (toml11 3.7 clamps an overflowing float to
// ±DBL_MAX, an overflowing integer to INT64_MAX, and reads 1e-400 as 0: each is checked against
// the text as written).
std::string number_problem(const toml::value& v) {
  if (v.is_floating()) {
    const double x = v.as_floating();
    const bool suspect = std::abs(x) == DBL_MAX || x == 0 || (std::isfinite(x) && std::abs(x) < DBL_MIN);
    if (!suspect) return "";
    const std::string t = token_of(v);
    if (t.empty()) return "";
    errno = 0;
    const double r = std::strtod(t.c_str(), nullptr);
    if (errno == ERANGE && std::isinf(r)) return "the number " + t + " is beyond the range of a double (about ±1.8e308)";
    if (r == 0 && nonzero_mantissa(t)) return "the number " + t + " is too small for a double: it would be read as 0";
    return "";
  }
  if (v.is_integer()) {
    const auto x = v.as_integer();
    if (x != INT64_MAX && x != INT64_MIN) return "";
    std::string t = token_of(v);
    if (t.empty()) return "";
    int base = 10;
    std::size_t start = 0;
    if (t[0] == '+') start = 1;
    if (t.size() > 2 && t[0] == '0' && (t[1] == 'x' || t[1] == 'o' || t[1] == 'b')) {
      base = t[1] == 'x' ? 16 : t[1] == 'o' ? 8 : 2;
      start = 2;
    }
    std::int64_t parsed = 0;
    const auto res = std::from_chars(t.data() + start, t.data() + t.size(), parsed, base);
    if (res.ec == std::errc::result_out_of_range)
      return "the integer " + t + " does not fit in 64 bits (at most 9223372036854775807)";
  }
  return "";
}

// Every number of a parsed value, checked against its text.
void check_numbers(const toml::value& v, const std::string& key, const std::string& file, const PrescannedToml* map) {
  if (v.is_table()) {
    for (const auto& kv : v.as_table()) check_numbers(kv.second, key.empty() ? kv.first : key + "." + kv.first, file, map);
  } else if (v.is_array()) {
    const auto& a = v.as_array();
    // A component of a vector counts from 0 (position_m[2]); a table of an array of tables from 1,
    // as its readers name it ([[vary]] → vary[1]).
    for (std::size_t i = 0; i < a.size(); ++i)
      check_numbers(a[i], key + "[" + std::to_string(a[i].is_table() ? i + 1 : i) + "]", file, map);
  } else {
    const std::string problem = number_problem(v);
    if (problem.empty()) return;
    const auto loc = v.location();
    if (loc.file_name() == kSetName) throw_input_error(file, 0, "--set " + key, problem);
    throw_input_error(file, map ? map->line_of(loc.line()) : loc.line(), key, problem);
  }
}

// toml11's syntax error text holds " --> NAME" and then a line " LINE | text"; the first line is
// the reason. Returns the reason and the line (0 if not found).
struct SyntaxError {
  std::string detail;
  long line = 0;        // the line the error is at (toml11's numbering of the text it read)
  long first_line = 0;  // a key defined twice: the line of its first definition, else 0
};

SyntaxError syntax_error_of(const std::string& what, const std::string& name) {
  SyntaxError r;
  r.detail = what.substr(0, what.find('\n'));
  const auto pos = what.find(" --> " + name);
  if (pos != std::string::npos) {
    const auto line_pos = what.find('\n', pos);
    if (line_pos != std::string::npos) {
      // toml11 quotes each line it points at ("  5 | radius_m = 0.04") with a note under it
      // ("    |   ~~~~ value defined twice"). The error's line is the first quoted one, except for a
      // key defined twice, whose first quoted line is the first definition: then the line noted
      // "defined twice" is the error's, and the first is named beside it.
      std::istringstream rest(what.substr(line_pos + 1));
      std::string l;
      long first_quoted = 0, last_quoted = 0, twice = 0;
      while (std::getline(rest, l)) {
        const auto bar = l.find('|');
        if (bar == std::string::npos) continue;
        const std::string head = l.substr(0, bar);
        if (head.find_first_not_of(' ') == std::string::npos) {
          if (l.find("defined twice") != std::string::npos && last_quoted > 0) twice = last_quoted;
          continue;
        }
        try {
          last_quoted = std::stol(head);
          if (first_quoted == 0) first_quoted = last_quoted;
        } catch (...) {
        }
      }
      r.line = first_quoted;
      if (twice > 0 && twice != first_quoted) {
        r.line = twice;
        r.first_line = first_quoted;
      }
    }
  }
  if (r.detail.rfind("[error] ", 0) == 0) r.detail = r.detail.substr(8);
  return r;
}

// Parses "v = TEXT" as an override's value, its location named "--set".
toml::value parse_override_value(const std::string& text, const std::string& path, const std::string& file) {
  const PrescannedToml pre = prescan_toml("v = " + text, file + ": --set " + path, false);
  std::istringstream in(pre.text);
  return toml::find(toml::parse(in, kSetName), "v");
}

// A TOML basic string holding s (quotes, backslashes and control characters escaped).
std::string toml_string_literal(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') {
      out.push_back('\\');
      out.push_back(static_cast<char>(c));
    } else if (c < 0x20 || c == 0x7f) {
      char b[8];
      std::snprintf(b, sizeof b, "\\u%04x", c);
      out += b;
    } else {
      out.push_back(static_cast<char>(c));
    }
  }
  return out + "\"";
}

// Apply "a.b.c=value" to the document. The value is parsed as TOML; if that fails it is a string.
void apply_override(toml::value& root, const std::string& file, const std::string& assignment) {
  const auto eq = assignment_equals(assignment);  // an '=' inside a quoted key part is the key's
  if (eq == std::string::npos || eq == 0)
    throw_input_error(file, 0, "--set " + assignment, "expected section.key=value");
  const std::string key = assignment.substr(0, eq);
  std::string path = key;  // in messages: the key one way however written ("stone.radius_m")
  {
    std::vector<std::string> parts;
    if (parse_dotted_key(key, parts, nullptr) && assignment.find_first_of("\n\r") == std::string::npos)
      path = join_dotted_key(parts);
  }
  std::string raw = assignment.substr(eq + 1);
  // TOML would read the text after a line break as a further line (another key, a table header)
  // or drop it: one --set is one key and one value.
  if (assignment.find_first_of("\n\r") != std::string::npos)
    throw_input_error(file, 0, "--set " + path.substr(0, path.find_first_of("\n\r")),
                      "the assignment holds a line break (give each key its own --set)");
  toml::value parsed;
  try {
    parsed = parse_override_value(raw, path, file);
  } catch (const InputError&) {
    throw;  // nested too deep, a line too long
  } catch (const std::exception&) {
    try {
      parsed = parse_override_value(toml_string_literal(raw), path, file);
    } catch (const std::exception&) {
      throw_input_error(file, 0, "--set " + path, "the value is neither TOML nor a plain string (not UTF-8?)");
    }
  }
  check_numbers(parsed, path, file, nullptr);
  set_value(root, file, key, std::move(parsed));
}

}  // namespace

void set_value(toml::value& root, const std::string& file, const std::string& path, toml::value value) {
  std::vector<std::string> parts;
  std::string why;
  if (!parse_dotted_key(path, parts, &why)) throw_input_error(file, 0, "--set " + path, why);
  toml::value* node = &root;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    const std::string& part = parts[k];
    if (!node->is_table()) throw_input_error(file, 0, "--set " + join_dotted_key(parts), "'" + part + "' is not inside a table");
    auto& tbl = node->as_table();
    if (k + 1 == parts.size()) {
      tbl[part] = std::move(value);
      return;
    }
    if (tbl.find(part) == tbl.end()) tbl[part] = toml::table{};
    node = &tbl[part];
  }
}

TomlTable::TomlTable(const toml::value* table, std::string file, std::string prefix, TomlLineMap lines)
    : table_(table), file_(std::move(file)), prefix_(std::move(prefix)), lines_(std::move(lines)) {}

std::string TomlTable::full(const std::string& key) const { return prefix_.empty() ? key : prefix_ + "." + key; }

bool TomlTable::has(const std::string& key) const {
  return table_->is_table() && table_->as_table().count(key) > 0;
}


const toml::value& TomlTable::at(const std::string& key) const {
  used_.insert(key);
  if (!has(key)) {
    const auto [f, line] = where("");
    // A key of this table within two edits of the missing one (or differing in case only) is
    // probably it, misspelt: named with its line, so the error points at the typo.
    std::string hint;
    if (table_->is_table())
      for (const auto& kv : table_->as_table())
        if (!used_.count(kv.first) && looks_misspelt(kv.first, key)) {
          const auto [kf, kline] = where(kv.first);
          hint = " (is '" + kv.first + "'" + (kf == file_ && kline > 0 ? " on line " + std::to_string(kline) : "") +
                 " a misspelling of it?)";
          break;
        }
    throw_input_error(f == kSetName ? file_ : f, f == kSetName ? 0 : line, full(key), "missing key" + hint);
  }
  return table_->as_table().at(key);
}

std::pair<std::string, long> TomlTable::where(const std::string& key) const {
  const toml::value* v = table_;
  if (!key.empty() && has(key)) v = &table_->as_table().at(key);
  const auto loc = v->location();
  // From an override: its value (parsed as "--set"), or a table an override's dotted path made
  // (a table with no location at all; a sweep's axis values, also without one, are not tables).
  if (loc.file_name() == kSetName ||
      (v != table_ && v->is_table() && (loc.file_name().empty() || loc.file_name() == "unknown file")))
    return {kSetName, 0};
  if (loc.file_name() != file_) return {file_, 0};  // made by an override: no line of the file
  long line = static_cast<long>(loc.line());
  if (lines_ && line > 0) {
    const auto& m = *lines_;
    line = static_cast<std::size_t>(line) < m.size() ? m[static_cast<std::size_t>(line)] : (m.empty() ? line : m.back());
  }
  return {file_, line};
}

long TomlTable::line_of(const std::string& key) const { return where(key).second; }

void TomlTable::fail(const std::string& key, const std::string& what) const {
  const auto [f, line] = where(key);
  // A value from an override names the case file and the override: "case.toml: --set a.b: ...".
  if (f == kSetName) throw_input_error(file_, 0, "--set " + full(key), what);
  throw_input_error(f, line, full(key), what);
}

double TomlTable::number(const std::string& key) {
  const toml::value& v = at(key);
  double x = 0;
  if (v.is_floating())
    x = v.as_floating();
  else if (v.is_integer())
    x = static_cast<double>(v.as_integer());
  else
    fail(key, "expected a number, got " + short_type(v));
  if (!std::isfinite(x)) fail(key, "must be a finite number");
  return x;
}

double TomlTable::number_or(const std::string& key, double fallback) {
  used_.insert(key);
  return has(key) ? number(key) : fallback;
}

std::optional<double> TomlTable::maybe_number(const std::string& key) {
  used_.insert(key);
  if (!has(key)) return std::nullopt;
  return number(key);
}

long long TomlTable::integer(const std::string& key) {
  const toml::value& v = at(key);
  if (!v.is_integer()) fail(key, "expected an integer, got " + short_type(v));
  return v.as_integer();
}

long long TomlTable::integer_or(const std::string& key, long long fallback) {
  used_.insert(key);
  return has(key) ? integer(key) : fallback;
}

std::string TomlTable::string(const std::string& key) {
  const toml::value& v = at(key);
  if (!v.is_string()) fail(key, "expected a string, got " + short_type(v));
  return v.as_string().str;
}

std::string TomlTable::string_or(const std::string& key, const std::string& fallback) {
  used_.insert(key);
  return has(key) ? string(key) : fallback;
}

bool TomlTable::boolean_or(const std::string& key, bool fallback) {
  used_.insert(key);
  if (!has(key)) return fallback;
  const toml::value& v = at(key);
  if (!v.is_boolean()) fail(key, "expected true or false, got " + short_type(v));
  return v.as_boolean();
}

std::vector<double> TomlTable::numbers(const std::string& key) {
  const toml::value& v = at(key);
  if (!v.is_array()) fail(key, "expected an array of numbers, got " + short_type(v));
  std::vector<double> out;
  for (const auto& e : v.as_array()) {
    double x = 0;
    if (e.is_floating())
      x = e.as_floating();
    else if (e.is_integer())
      x = static_cast<double>(e.as_integer());
    else
      fail(key, "expected an array of numbers, found " + short_type(e));
    if (!std::isfinite(x)) fail(key, "array elements must be finite numbers");
    out.push_back(x);
  }
  return out;
}

std::optional<std::vector<double>> TomlTable::maybe_numbers(const std::string& key) {
  used_.insert(key);
  if (!has(key)) return std::nullopt;
  return numbers(key);
}

std::vector<std::string> TomlTable::strings(const std::string& key) {
  const toml::value& v = at(key);
  if (!v.is_array()) fail(key, "expected an array of strings, got " + short_type(v));
  std::vector<std::string> out;
  for (const auto& e : v.as_array()) {
    if (!e.is_string()) fail(key, "expected an array of strings, found " + short_type(e));
    out.push_back(e.as_string().str);
  }
  return out;
}

std::optional<std::vector<std::string>> TomlTable::maybe_strings(const std::string& key) {
  used_.insert(key);
  if (!has(key)) return std::nullopt;
  return strings(key);
}

TomlTable TomlTable::table(const std::string& key) {
  const toml::value& v = at(key);
  if (!v.is_table()) fail(key, "expected a table [" + full(key) + "], got " + short_type(v));
  return TomlTable(&v, file_, full(key), lines_);
}

std::vector<TomlTable> TomlTable::tables(const std::string& key) {
  const toml::value& v = at(key);
  if (!v.is_array()) fail(key, "expected an array of tables [[" + full(key) + "]], got " + short_type(v));
  std::vector<TomlTable> out;
  const auto& a = v.as_array();
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!a[i].is_table()) fail(key, "expected an array of tables [[" + full(key) + "]], found " + short_type(a[i]));
    out.emplace_back(&a[i], file_, full(key) + "[" + std::to_string(i) + "]", lines_);
  }
  return out;
}

std::optional<TomlTable> TomlTable::maybe_table(const std::string& key) {
  used_.insert(key);
  if (!has(key)) return std::nullopt;
  return table(key);
}

std::vector<std::string> TomlTable::keys() const {
  std::vector<std::string> k;
  if (table_->is_table())
    for (const auto& kv : table_->as_table()) k.push_back(kv.first);
  return k;
}

void TomlTable::require_positive(const std::string& key, double value) const {
  if (!(value > 0)) fail(key, "must be > 0 (got " + num(value) + ")");
}

void TomlTable::require_non_negative(const std::string& key, double value) const {
  if (!(value >= 0)) fail(key, "must be >= 0 (got " + num(value) + ")");
}

void TomlTable::require_in(const std::string& key, double value, double lo, double hi) const {
  if (!(value >= lo && value <= hi)) fail(key, "must be in [" + num(lo) + ", " + num(hi) + "] (got " + got(value, lo, hi) + ")");
}

double TomlTable::bounded(const std::string& key, double lo, double hi) {
  const double v = number(key);
  require_in(key, v, lo, hi);
  return v;
}

double TomlTable::bounded_or(const std::string& key, double fallback, double lo, double hi) {
  used_.insert(key);
  return has(key) ? bounded(key, lo, hi) : fallback;
}

long long TomlTable::bounded_integer_or(const std::string& key, long long fallback, long long lo, long long hi) {
  const long long v = integer_or(key, fallback);
  if (v < lo || v > hi)
    fail(key, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] (got " + std::to_string(v) + ")");
  return v;
}

void TomlTable::finish() const {
  if (!table_->is_table()) return;
  for (const auto& kv : table_->as_table()) {
    if (!used_.count(kv.first)) fail(kv.first, "unknown key (misspelt? see cases/README.md)");
  }
}

TomlDocument parse_toml_text(const std::string& text, const std::string& name,
                             const std::vector<std::string>& overrides) {
  TomlDocument doc;
  doc.file = name;
  doc.text = text;
  doc.overrides = overrides;
  auto pre = std::make_shared<PrescannedToml>(prescan_toml(text, name));
  try {
    std::istringstream in(pre->text);
    doc.root = toml::parse(in, name);
  } catch (const toml::syntax_error& e) {
    // toml11's message is multi-line with the location inside; keep its first line.
    const SyntaxError x = syntax_error_of(e.what(), name);
    std::string detail = x.detail;
    if (x.first_line > 0) {
      // "toml::insert_value: value ("radius_m") already exists." named the first definition's line.
      const auto q1 = detail.find("(\""), q2 = detail.find("\")", q1 == std::string::npos ? 0 : q1);
      const std::string key = q1 != std::string::npos && q2 != std::string::npos ? detail.substr(q1 + 2, q2 - q1 - 2) : "a key";
      detail = "\"" + key + "\" is defined twice (first on line " +
               std::to_string(pre->line_of(static_cast<std::uint32_t>(x.first_line))) + "): keep one";
    }
    throw_input_error(name, pre->line_of(static_cast<std::uint32_t>(x.line)), "", "TOML syntax error: " + detail);
  } catch (const std::exception& e) {
    throw_input_error(name, 0, "", std::string("TOML error: ") + e.what());
  }
  check_numbers(doc.root, "", name, pre.get());
  doc.lines = TomlLineMap(pre, &pre->source_line);
  // Applied in order: a key set twice takes the last value (a script's base settings, then what one
  // run changes; tools/README.md). A key repeated inside a file is an error, above.
  for (const auto& o : overrides) apply_override(doc.root, name, o);
  return doc;
}

std::string read_case_title(TomlTable& top) {
  std::string title = std::filesystem::path(top.file()).stem().string();
  if (auto meta = top.maybe_table("case")) {
    title = meta->string_or("title", title);
    meta->string_or("description", "");
    meta->finish();
  }
  return title;
}

TomlDocument load_toml(const std::string& path, const std::vector<std::string>& overrides) {
  return parse_toml_text(read_text_file(path, kMaxTomlFileBytes), path, overrides);
}

}  // namespace stoneskip
