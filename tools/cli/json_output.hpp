#pragma once
// The text of a --json answer. Names, columns and messages come from the user's files and may not
// be UTF-8 (a Latin-1 column name, a 0xFF byte in a file name): such bytes become U+FFFD rather
// than an exception from nlohmann::json (exit 3 for a user's input).
#include <nlohmann/json.hpp>
#include <string>

namespace stoneskip::cli {

inline std::string json_text(const nlohmann::json& j, int indent = 2) {
  return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace stoneskip::cli
