#include "tools/io/toml_table.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "tools/io/atomic_file.hpp"
#include "tools/io/input_error.hpp"

namespace stoneskip {

namespace {

std::string short_type(const toml::value& v) {
  std::ostringstream s;
  s << v.type();
  return s.str();
}

// Apply "a.b.c=value" to the document. The value is parsed as TOML; if that fails it is a string.
void apply_override(toml::value& root, const std::string& file, const std::string& assignment) {
  auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw_input_error(file, 0, "--set " + assignment, "expected section.key=value");
  std::string path = assignment.substr(0, eq);
  std::string raw = assignment.substr(eq + 1);
  toml::value parsed;
  try {
    std::istringstream in("v = " + raw);
    parsed = toml::find(toml::parse(in, "--set"), "v");
  } catch (const std::exception&) {
    parsed = toml::value(raw);
  }
  set_value(root, file, path, std::move(parsed));
}

}  // namespace

void set_value(toml::value& root, const std::string& file, const std::string& path, toml::value value) {
  toml::value* node = &root;
  std::size_t start = 0;
  while (true) {
    std::size_t dot = path.find('.', start);
    std::string part = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (part.empty()) throw_input_error(file, 0, "--set " + path, "empty key component");
    if (!node->is_table()) throw_input_error(file, 0, "--set " + path, "'" + part + "' is not inside a table");
    auto& tbl = node->as_table();
    if (dot == std::string::npos) {
      tbl[part] = std::move(value);
      return;
    }
    if (tbl.find(part) == tbl.end()) tbl[part] = toml::table{};
    node = &tbl[part];
    start = dot + 1;
  }
}

TomlTable::TomlTable(const toml::value* table, std::string file, std::string prefix)
    : table_(table), file_(std::move(file)), prefix_(std::move(prefix)) {}

std::string TomlTable::full(const std::string& key) const { return prefix_.empty() ? key : prefix_ + "." + key; }

bool TomlTable::has(const std::string& key) const {
  return table_->is_table() && table_->as_table().count(key) > 0;
}

const toml::value& TomlTable::at(const std::string& key) const {
  used_.insert(key);
  if (!has(key)) throw_input_error(file_, line_of(""), full(key), "missing key");
  return table_->as_table().at(key);
}

long TomlTable::line_of(const std::string& key) const {
  const toml::value* v = table_;
  if (!key.empty() && has(key)) v = &table_->as_table().at(key);
  auto loc = v->location();
  if (loc.file_name() == "--set") return 0;
  return static_cast<long>(loc.line());
}

void TomlTable::fail(const std::string& key, const std::string& what) const {
  std::string where = file_;
  if (has(key) && table_->as_table().at(key).location().file_name() == "--set") where = "--set";
  throw_input_error(where, where == "--set" ? 0 : line_of(key), full(key), what);
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
  return TomlTable(&v, file_, full(key));
}

std::vector<TomlTable> TomlTable::tables(const std::string& key) {
  const toml::value& v = at(key);
  if (!v.is_array()) fail(key, "expected an array of tables [[" + full(key) + "]], got " + short_type(v));
  std::vector<TomlTable> out;
  const auto& a = v.as_array();
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!a[i].is_table()) fail(key, "expected an array of tables [[" + full(key) + "]], found " + short_type(a[i]));
    out.emplace_back(&a[i], file_, full(key) + "[" + std::to_string(i) + "]");
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
  if (!(value > 0)) fail(key, "must be > 0 (got " + std::to_string(value) + ")");
}

void TomlTable::require_non_negative(const std::string& key, double value) const {
  if (!(value >= 0)) fail(key, "must be >= 0 (got " + std::to_string(value) + ")");
}

void TomlTable::require_in(const std::string& key, double value, double lo, double hi) const {
  if (!(value >= lo && value <= hi)) {
    std::ostringstream s;
    s << "must be in [" << lo << ", " << hi << "] (got " << value << ")";
    fail(key, s.str());
  }
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
  try {
    std::istringstream in(text);
    doc.root = toml::parse(in, name);
  } catch (const toml::syntax_error& e) {
    // toml11's message is multi-line with the location inside; keep its first lines, folded.
    std::string what = e.what();
    long line = 0;
    auto pos = what.find(" --> " + name);
    std::string detail = what.substr(0, what.find('\n'));
    if (pos != std::string::npos) {
      auto line_pos = what.find("\n", pos);
      // toml11 prints " --> FILE" then a line " LINE | text"
      if (line_pos != std::string::npos) {
        std::istringstream rest(what.substr(line_pos + 1));
        std::string l;
        while (std::getline(rest, l)) {
          auto bar = l.find('|');
          if (bar != std::string::npos) {
            try {
              line = std::stol(l.substr(0, bar));
              break;
            } catch (...) {
            }
          }
        }
      }
    }
    if (detail.rfind("[error] ", 0) == 0) detail = detail.substr(8);
    throw_input_error(name, line, "", "TOML syntax error: " + detail);
  } catch (const std::exception& e) {
    throw_input_error(name, 0, "", std::string("TOML error: ") + e.what());
  }
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
  return parse_toml_text(read_text_file(path), path, overrides);
}

}  // namespace stoneskip
