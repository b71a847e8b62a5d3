#pragma once
// Two numbers a sentence compares, written so that the reader sees the comparison it states:
// "sigma = 0.7071 exceeds the limit 0.7071" was true (0.70711 > 0.707107) and read as false.
#include <string>
#include <utility>

namespace stoneskip {

// a and b with `digits` significant digits (printf %g), or more, up to 17, where fewer would print
// two different numbers the same. Equal numbers (and NaN) keep `digits`.
std::pair<std::string, std::string> numbers_apart(double a, double b, int digits);

// x (> 0) with `digits` significant digits, rounded down: a bound the reader may take as it reads
// ("take dt_s <= 0.01386", printed from 0.0138598, was itself refused).
std::string at_most(double x, int digits);

}  // namespace stoneskip
