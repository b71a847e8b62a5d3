#pragma once
// Markdown building blocks for reports: tables with a header row (units in the headers), numbers
// formatted with a fixed number of significant digits.
#include <string>
#include <vector>

namespace stoneskip {

// "%.{sig}g" formatting; NaN as "–", infinities as "∞".
std::string fmt(double value, int significant = 4);

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
