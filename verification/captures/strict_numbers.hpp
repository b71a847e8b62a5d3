#pragma once
// Strict text fields and key=value settings, shared by the capture readers (tools/capture) and the settings of the
// analysis (mounting.hpp, virtual_thrower.hpp): a number is the whole field, finite, in plain
// decimal notation (no "nan", "inf" or hex floats); an integer may be given in any base.
#include <optional>
#include <string>
#include <utility>
#include <string_view>
#include <vector>

namespace stoneskip {

// Whitespace- (or, with comma = true, comma-) separated fields.
std::vector<std::string_view> split_fields(std::string_view line, bool comma);
std::string_view trim(std::string_view s);

// Strict numbers: the whole field must parse and be finite.
std::optional<double> parse_real(std::string_view field);
std::optional<long long> parse_integer(std::string_view field, int base = 10);

// "key=value" → trimmed key and value; throws InputError "WHERE: SETTING: expected key=value".
std::pair<std::string, std::string> split_setting(const std::string& setting, const std::string& where);

}  // namespace stoneskip
