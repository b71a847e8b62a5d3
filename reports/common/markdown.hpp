#pragma once
// Markdown building blocks for reports: tables with a header row (units in the headers), numbers
// formatted with a fixed number of significant digits.
#include <string>
#include <vector>

namespace stoneskip {

// "%.{sig}g" formatting; NaN as "–", infinities as "∞".
std::string fmt(double value, int significant = 4);
// A fraction as a percentage to 3 significant digits: 0.0512 → "5.12 %".
std::string pct(double fraction);
// Items as prose: "a", "a and b", "a, b and c"; "" for none.
std::string and_list(const std::vector<std::string>& items);

class MarkdownTable {
 public:
  explicit MarkdownTable(std::vector<std::string> headers);
  MarkdownTable& row(std::vector<std::string> cells);
  std::string str() const;

 private:
  std::vector<std::string> headers_;
  std::vector<std::vector<std::string>> rows_;
};

}  // namespace stoneskip
