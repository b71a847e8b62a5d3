#include "reports/common/markdown.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace stoneskip {

std::string fmt(double value, int significant) {
  if (std::isnan(value)) return "–";
  if (std::isinf(value)) return value > 0 ? "∞" : "−∞";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", significant, value);
  return buf;
}

std::string pct(double fraction) { return fmt(100 * fraction, 3) + " %"; }

MarkdownTable::MarkdownTable(std::vector<std::string> headers) : headers_(std::move(headers)) {}

MarkdownTable& MarkdownTable::row(std::vector<std::string> cells) {
  if (cells.size() != headers_.size()) throw std::invalid_argument("MarkdownTable: wrong number of cells");
  rows_.push_back(std::move(cells));
  return *this;
}

std::string MarkdownTable::str() const {
  std::string s = "|";
  for (const auto& h : headers_) s += " " + h + " |";
  s += "\n|";
  for (std::size_t i = 0; i < headers_.size(); ++i) s += "---|";
  s += "\n";
  for (const auto& r : rows_) {
    s += "|";
    for (const auto& c : r) s += " " + c + " |";
    s += "\n";
  }
  return s;
}

}  // namespace stoneskip
