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

namespace {

// A cell's text with each '|' outside a code span escaped as "\|" (a case's title "a | b" split
// its row and shifted the columns after it); one already escaped, or inside a code span (which
// the page's table reader keeps whole, reports/common/html_page.cpp), is left as it is.
std::string table_cell(const std::string& c) {
  std::string out;
  for (std::size_t i = 0; i < c.size();) {
    if (c[i] == '`') {
      std::size_t n = 0;
      while (i + n < c.size() && c[i + n] == '`') ++n;
      // The span's end: the next run of exactly n backticks.
      std::size_t end = std::string::npos;
      for (std::size_t k = i + n; k < c.size();) {
        if (c[k] != '`') {
          ++k;
          continue;
        }
        std::size_t m = 0;
        while (k + m < c.size() && c[k + m] == '`') ++m;
        if (m == n) {
          end = k + m;
          break;
        }
        k += m;
      }
      if (end == std::string::npos) {  // an unclosed run is text
        out.append(c, i, n);
        i += n;
      } else {
        out.append(c, i, end - i);
        i = end;
      }
      continue;
    }
    if (c[i] == '\\' && i + 1 < c.size()) {
      out.append(c, i, 2);
      i += 2;
      continue;
    }
    if (c[i] == '|') out += "\\|";
    else if (c[i] == '\n') out += ' ';  // a row is one line
    else out += c[i];
    ++i;
  }
  return out;
}

}  // namespace

std::string MarkdownTable::str() const {
  std::string s = "|";
  for (const auto& h : headers_) s += " " + table_cell(h) + " |";
  s += "\n|";
  for (std::size_t i = 0; i < headers_.size(); ++i) s += "---|";
  s += "\n";
  for (const auto& r : rows_) {
    s += "|";
    for (const auto& c : r) s += " " + table_cell(c) + " |";
    s += "\n";
  }
  return s;
}

}  // namespace stoneskip
