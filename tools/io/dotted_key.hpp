#pragma once
// Dotted keys as TOML writes them (TOML 1.0, "Keys"): the key of a --set, of a sweep's [[vary]]
// and of its top-level set. Parts are bare (A-Za-z0-9_-) or quoted, "…" with a basic string's
// escapes or '…' literal, joined by dots with optional blanks around them. stoneskip's own keys
// are all bare, so a part that is empty or holds a '.' is refused (no key has one, and a message
// that names the key joined by dots would name another).
#include <cstddef>
#include <string>
#include <vector>

namespace stoneskip {

// The parts of `key`; false with the reason in *why when it is malformed.
bool parse_dotted_key(const std::string& key, std::vector<std::string>& parts, std::string* why);

// The parts joined by '.' ("throw.speed_m_s"): one spelling for every way of writing a key.
std::string join_dotted_key(const std::vector<std::string>& parts);

// `key` written the one way: its parts joined by '.' when every part is bare (so that the result
// reads back as the same key), else `key` as given (malformed, or a part no stoneskip key has:
// refused where it is used).
std::string canonical_dotted_key(const std::string& key);

// The position of the '=' that ends the key of "KEY=VALUE" (the first outside a quoted part), or
// std::string::npos when there is none.
std::size_t assignment_equals(const std::string& assignment);

}  // namespace stoneskip
