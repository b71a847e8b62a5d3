#pragma once
// Reading the keys of study files (cases/studies/*.toml): lists and counts with their range checks,
// a key left out keeping the library's default. Errors name the file, line and key (TomlTable).
#include <string>
#include <vector>

#include "tools/io/toml_table.hpp"

namespace stoneskip {

// A non-empty array of numbers, each > 0 (or any finite number for any_list); `fallback` if absent.
std::vector<double> positive_list(TomlTable& t, const std::string& key, const std::vector<double>& fallback);
std::vector<double> any_list(TomlTable& t, const std::string& key, const std::vector<double>& fallback);
// A number > 0; `fallback` if absent.
double positive(TomlTable& t, const std::string& key, double fallback);
// A whole number in [lo, hi]; `fallback` if absent.
long long count_in(TomlTable& t, const std::string& key, long long fallback, long long lo, long long hi);
// The [study] table's kind, which must be `kind` ("waves", "stones", "scene"), and its preset;
// the table is left open for the study's own keys.
std::string study_preset(TomlTable& study, const std::string& kind);

}  // namespace stoneskip
