#pragma once
// The edit distance of two keys, compared without case (Levenshtein's, with a swap of two
// neighbouring letters as one edit): a key written "Solver", "radiuss_m" or "cuont", or a header
// line "has_gyroo", for the one meant. Used to name a misspelt key
// instead of ignoring it or only calling it unknown.
#include <cstddef>
#include <string>

namespace stoneskip {

std::size_t edit_distance(const std::string& a, const std::string& b);

// True when `key` is within two edits of `known` (at most a third of its length: "ab" is not a
// misspelling of "xy") without being it.
bool looks_misspelt(const std::string& key, const std::string& known);

}  // namespace stoneskip
