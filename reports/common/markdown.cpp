#include "reports/common/markdown.hpp"

#include "reports/common/code_span.hpp"

#include <algorithm>
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

std::string and_list(const std::vector<std::string>& items) {
  std::string s;
  for (std::size_t i = 0; i < items.size(); ++i) s += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
  return s;
}

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
      const std::size_t end = code_span(c, i);
      if (end == std::string::npos) {  // an unclosed run is text
        const std::size_t run_end = std::min(c.find_first_not_of('`', i), c.size());
        out.append(c, i, run_end - i);
        i = run_end;
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
