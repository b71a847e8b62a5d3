#pragma once
// Strict reading of TOML case files. Every key a reader asks for is recorded; finish() rejects any
// key that was not asked for (a misspelt key is an error, never a silent default). Every error is
// one line: "FILE:LINE: section.key: what is wrong".
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <toml.hpp>

namespace stoneskip {

// Maps a line of the text toml11 parsed to the line of the file as written (the pre-scan breaks
// long arrays over lines: tools/io/toml_prescan.hpp). Null: the same lines.
using TomlLineMap = std::shared_ptr<const std::vector<std::uint32_t>>;

class TomlTable {
 public:
  TomlTable(const toml::value* table, std::string file, std::string prefix, TomlLineMap lines = nullptr);

  bool has(const std::string& key) const;
  // Numbers: integers are accepted where a real is asked for; NaN and infinities are rejected.
  double number(const std::string& key);
  double number_or(const std::string& key, double fallback);
  std::optional<double> maybe_number(const std::string& key);
  long long integer(const std::string& key);
  long long integer_or(const std::string& key, long long fallback);
  std::string string(const std::string& key);
  std::string string_or(const std::string& key, const std::string& fallback);
  bool boolean_or(const std::string& key, bool fallback);
  std::vector<double> numbers(const std::string& key);  // an array of numbers
  std::optional<std::vector<double>> maybe_numbers(const std::string& key);
  std::vector<std::string> strings(const std::string& key);  // an array of strings
  std::optional<std::vector<std::string>> maybe_strings(const std::string& key);
  TomlTable table(const std::string& key);             // a required sub-table
  std::optional<TomlTable> maybe_table(const std::string& key);
  std::vector<TomlTable> tables(const std::string& key);  // an array of tables [[key]]
  std::vector<std::string> keys() const;

  // Range checks with the standard message.
  void require_positive(const std::string& key, double value) const;        // > 0
  void require_non_negative(const std::string& key, double value) const;    // >= 0
  void require_in(const std::string& key, double value, double lo, double hi) const;  // [lo, hi]
  // A number in [lo, hi], the key's documented plausibility bounds (cases/README.md): read (with
  // a fallback when given) and checked, "must be in [lo, hi] (got v)".
  double bounded(const std::string& key, double lo, double hi);
  double bounded_or(const std::string& key, double fallback, double lo, double hi);
  long long bounded_integer_or(const std::string& key, long long fallback, long long lo, long long hi);
  // Throws InputError naming this key: "FILE:LINE: prefix.key: what".
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;

  // Rejects keys that no reader asked for.
  void finish() const;

  const std::string& file() const { return file_; }
  const std::string& prefix() const { return prefix_; }

 private:
  const toml::value& at(const std::string& key) const;
  long line_of(const std::string& key) const;
  std::string full(const std::string& key) const;

  // Where a key's value (or, if absent, this table) came from: "--set" for an override, the file
  // and its line otherwise (line 0 when unknown, e.g. a table an override created).
  std::pair<std::string, long> where(const std::string& key) const;

  const toml::value* table_;
  std::string file_;
  std::string prefix_;
  TomlLineMap lines_;
  mutable std::set<std::string> used_;
};

// A parsed case file with its original text (attached to results) and any command-line overrides
// ("section.key=value", value in TOML syntax; a bare word is taken as a string) applied.
//
// Before parsing, the text is pre-scanned (nesting depth, long lines: tools/io/toml_prescan.hpp);
// after, every number is checked against its text: a float beyond ±1.8e308 (1e400), a non-zero
// float that rounds to 0 (1e-400) or an integer beyond 64 bits is an error, never clamped.
struct TomlDocument {
  std::string file;
  std::string text;
  std::vector<std::string> overrides;
  toml::value root;
  TomlLineMap lines;
  TomlTable top() const { return TomlTable(&root, file, "", lines); }
};

// The optional [case] table every case file may open with (title, description); returns the
// title, or the file's stem when none is given.
std::string read_case_title(TomlTable& top);

// What --set does once its value is parsed: sets the dotted key ("section.key") to the value,
// creating missing tables. For callers that hold the value already (a sweep's numbers).
void set_value(toml::value& root, const std::string& file, const std::string& dotted_key, toml::value value);

TomlDocument load_toml(const std::string& path, const std::vector<std::string>& overrides = {});
TomlDocument parse_toml_text(const std::string& text, const std::string& name,
                             const std::vector<std::string>& overrides = {});

}  // namespace stoneskip
