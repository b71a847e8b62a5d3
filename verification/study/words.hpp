#pragma once
// Numbers in the computed reasons of verdicts: "%.{significant}g", NaN as "–", infinities as "∞"
// (the same form the reports use for numbers, reports/common/markdown.hpp).
#include <string>

namespace stoneskip {

std::string num(double value, int significant = 3);

}  // namespace stoneskip
