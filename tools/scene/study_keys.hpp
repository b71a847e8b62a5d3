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
// Fractions in (0, 1], at least `least` of them, decreasing strictly (coarse to fine), each a
// fraction of `of_what` (as the error says); `fallback` if absent.
std::vector<double> refining_fractions(TomlTable& t, const std::string& key, const std::vector<double>& fallback, std::size_t least,
                                       const std::string& of_what);
// A number > 0; `fallback` if absent.
double positive(TomlTable& t, const std::string& key, double fallback);
// A whole number in [lo, hi]; `fallback` if absent.
long long count_in(TomlTable& t, const std::string& key, long long fallback, long long lo, long long hi);
// from, from + step, … up to `to` (and `to` itself within 1e-9 step), summed step by step as the
// studies always have (their grids' values are bit for bit those of earlier runs). `key` is failed
// when step ≤ 0, to < from, there would be more than max_values values, or adding step to a value
// does not change it (a step below the values' resolution: [1e20, 1e20, 1] never ended).
std::vector<double> from_to_step(TomlTable& t, const std::string& key, double from, double to, double step,
                                 double max_values);
// The [study] table's kind, which must be `kind` ("waves", "stones", "scene"), and its preset;
// the table is left open for the study's own keys.
std::string study_preset(TomlTable& study, const std::string& kind);

}  // namespace stoneskip
