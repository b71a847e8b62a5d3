#pragma once
// Numbers read back from a stored record (data.h5) where a report needs more than "a number": a
// count it loops or allocates over, a coordinate it writes into a gnuplot script. data.h5 is an
// input to `report render` and may have been edited by hand; such a value out of its range throws
// RecordError naming the record's path and the key (`report render` refuses it in one line), where
// it used to allocate 2^62 entries, loop 1e300 times, or write `nan` into a script.
#include <cstddef>
#include <string>

#include "verification/study/record.hpp"

namespace stoneskip {

// The most points (and refinements) a stored order fit may claim: the studies' ladders have tens.
inline constexpr std::size_t kMostFitPoints = 1'000'000;

// A whole number in [0, most].
std::size_t stored_count(const Record& r, const std::string& key, std::size_t most);
// A finite number.
double stored_finite(const Record& r, const std::string& key);
// A number in [lo, hi] (NaN is not).
double stored_in(const Record& r, const std::string& key, double lo, double hi);

}  // namespace stoneskip
