#include "reports/common/html_page.hpp"

#include "reports/common/code_span.hpp"

#include <cctype>
#include <map>
#include <sstream>
#include <vector>

namespace stoneskip {

namespace {

std::string escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

bool starts_with(const std::string& s, const std::string& p) { return s.compare(0, p.size(), p) == 0; }

// A relative link to a Markdown page goes to the HTML page beside it ("waves/index.md#x" ->
// "waves/index.html#x"); links with a scheme and in-page fragments are left as they are.
// Whether a page may link to (or show) url: a relative path or a fragment, or an http, https or
// mailto address. Titles and notes come from the user's data (a case's title, a sweep's notes) and
// reach the page as Markdown: "[x](javascript:…)" there became a live script link. Any other
// scheme (javascript:, data:, vbscript:, file:) is shown as text. Browsers drop tabs and line
// breaks inside a URL and controls and spaces before it ("java\tscript:" is javascript:), so the
// scheme is read as they read it; a colon before any '/', '?' or '#' marks one (RFC 3986 §3.1).
bool safe_target(const std::string& url) {
  std::string u;
  for (char c : url)
    if (c != '\t' && c != '\n' && c != '\r') u += c;
  std::size_t a = 0;
  while (a < u.size() && static_cast<unsigned char>(u[a]) <= 0x20) ++a;
  u.erase(0, a);
  const std::size_t colon = u.find(':');
  if (colon == std::string::npos) return true;
  const std::size_t sep = u.find_first_of("/?#");
  if (sep != std::string::npos && sep < colon) return true;
  std::string scheme = u.substr(0, colon);
  for (char& c : scheme) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return scheme == "http" || scheme == "https" || scheme == "mailto";
}

std::string html_target(const std::string& url) {
  if (url.find("://") != std::string::npos || starts_with(url, "mailto:") || starts_with(url, "#")) return url;
  const std::size_t hash = url.find('#');
  const std::string path = url.substr(0, hash);
  if (path.size() > 3 && path.compare(path.size() - 3, 3, ".md") == 0)
    return path.substr(0, path.size() - 3) + ".html" + (hash == std::string::npos ? "" : url.substr(hash));
  return url;
}

// Index of the ']' closing the '[' at `open`, skipping code spans; npos when there is none.
std::size_t closing_bracket(const std::string& s, std::size_t open) {
  int depth = 0;
  for (std::size_t i = open; i < s.size(); ++i) {
    if (s[i] == '`') {
      const std::size_t end = code_span(s, i);
      if (end == std::string::npos) return std::string::npos;
      i = end - 1;
    } else if (s[i] == '[') {
      ++depth;
    } else if (s[i] == ']' && --depth == 0) {
      return i;
    }
  }
  return std::string::npos;
}

// "[text](url)" starting at `open`: text, url and the index after ')'; false when it is not one.
bool parse_link(const std::string& s, std::size_t open, std::string& text, std::string& url, std::size_t& next) {
  const std::size_t close = closing_bracket(s, open);
  if (close == std::string::npos || close + 1 >= s.size() || s[close + 1] != '(') return false;
  int depth = 0;
  for (std::size_t i = close + 1; i < s.size(); ++i) {
    if (s[i] == '(') ++depth;
    if (s[i] == ')' && --depth == 0) {
      text = s.substr(open + 1, close - open - 1);
      url = s.substr(close + 2, i - close - 2);
      next = i + 1;
      return true;
    }
  }
  return false;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n'; }

std::string inline_html(const std::string& s) {
  std::string out;
  std::size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    if (c == '`') {
      std::string content;
      const std::size_t end = code_span(s, i, &content);
      if (end != std::string::npos) {
        out += "<code>" + escape(content) + "</code>";
        i = end;
        continue;
      }
      while (i < s.size() && s[i] == '`') out += s[i++];  // an unclosed run is text, whole
      continue;
    } else if (c == '!' && i + 1 < s.size() && s[i + 1] == '[') {
      std::string text, url;
      std::size_t next = 0;
      if (parse_link(s, i + 1, text, url, next)) {
        out += safe_target(url) ? "<img src=\"" + escape(url) + "\" alt=\"" + escape(text) + "\">" : escape(text);
        i = next;
        continue;
      }
    } else if (c == '[') {
      std::string text, url;
      std::size_t next = 0;
      if (parse_link(s, i, text, url, next)) {
        out += safe_target(url) ? "<a href=\"" + escape(html_target(url)) + "\">" + inline_html(text) + "</a>" : inline_html(text);
        i = next;
        continue;
      }
    } else if (c == '*' && i + 1 < s.size() && s[i + 1] == '*') {
      const std::size_t end = s.find("**", i + 2);
      if (end != std::string::npos && end > i + 2) {
        out += "<strong>" + inline_html(s.substr(i + 2, end - i - 2)) + "</strong>";
        i = end + 2;
        continue;
      }
    } else if (c == '*' && i + 1 < s.size() && !is_space(s[i + 1])) {
      // *emphasis*: the closing '*' follows a non-space and is not half of "**".
      std::size_t end = i + 1;
      while ((end = s.find('*', end + 1)) != std::string::npos) {
        if (end + 1 < s.size() && s[end + 1] == '*') {
          const std::size_t bold_end = s.find("**", end + 2);  // a **bold** inside the emphasis
          if (bold_end == std::string::npos) break;
          end = bold_end + 1;
          continue;
        }
        if (!is_space(s[end - 1])) break;
      }
      if (end != std::string::npos) {
        out += "<em>" + inline_html(s.substr(i + 1, end - i - 1)) + "</em>";
        i = end + 1;
        continue;
      }
    } else if (c == '\\' && i + 1 < s.size() && std::ispunct(static_cast<unsigned char>(s[i + 1]))) {
      out += escape(std::string(1, s[i + 1]));
      i += 2;
      continue;
    }
    out += escape(std::string(1, c));
    ++i;
  }
  return out;
}

// The text of a heading as a reader sees it: Markdown marks and link targets dropped.
std::string plain_text(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    std::string text, url;
    std::size_t next = 0;
    if (s[i] == '[' && parse_link(s, i, text, url, next)) {
      out += plain_text(text);
      i = next - 1;
    } else if (s[i] != '`' && s[i] != '*') {
      out += s[i];
    }
  }
  return out;
}

// Splits a pipe-table row into its cells ('|' inside a code span or escaped as "\|" is text).
std::vector<std::string> table_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::size_t i = line.find('|') + 1;
  for (; i < line.size(); ++i) {
    const char c = line[i];
    if (c == '\\' && i + 1 < line.size() && line[i + 1] == '|') {
      cell += "\\|";
      ++i;
    } else if (c == '`') {
      // A whole code span, '|' inside it included; an unclosed run is text.
      const std::size_t end = code_span(line, i);
      while (i < line.size() && line[i] == '`') cell += line[i++];  // the opening run (or an unclosed one)
      if (end != std::string::npos) {
        cell += line.substr(i, end - i);
        i = end;
      }
      --i;
    } else if (c == '|') {
      cells.push_back(cell);
      cell.clear();
    } else {
      cell += c;
    }
  }
  if (cell.find_first_not_of(" \t") != std::string::npos) cells.push_back(cell);
  for (auto& x : cells) {
    const std::size_t a = x.find_first_not_of(" \t"), b = x.find_last_not_of(" \t");
    x = a == std::string::npos ? "" : x.substr(a, b - a + 1);
  }
  return cells;
}

bool is_table_separator(const std::string& line) {
  if (line.empty() || line[0] != '|') return false;
  return line.find_first_not_of("|-: \t") == std::string::npos && line.find('-') != std::string::npos;
}

bool is_blank(const std::string& line) { return line.find_first_not_of(" \t\r") == std::string::npos; }

int heading_level(const std::string& line) {
  std::size_t n = 0;
  while (n < line.size() && line[n] == '#') ++n;
  return n >= 1 && n <= 6 && n < line.size() && line[n] == ' ' ? static_cast<int>(n) : 0;
}

// A list item's marker: "* ", "- " or "12. "; returns the length of the marker, 0 when none.
std::size_t bullet_marker(const std::string& line) {
  if (line.size() > 2 && (line[0] == '*' || line[0] == '-') && line[1] == ' ') return 2;
  std::size_t n = 0;
  while (n < line.size() && std::isdigit(static_cast<unsigned char>(line[n]))) ++n;
  if (n > 0 && n + 1 < line.size() && line[n] == '.' && line[n + 1] == ' ') return n + 2;
  return 0;
}

bool is_anchor_line(const std::string& line) { return starts_with(line, "<a id=\"") && line.size() > 11 && line.compare(line.size() - 6, 6, "\"></a>") == 0 && line.find('>') == line.size() - 5; }

class Converter {
 public:
  explicit Converter(const std::string& md) {
    std::istringstream in(md);
    for (std::string line; std::getline(in, line);) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      lines_.push_back(line);
    }
  }

  std::string run() {
    while (at_ < lines_.size()) block();
    return out_.str();
  }

 private:
  void block() {
    const std::string& line = lines_[at_];
    if (is_blank(line)) {
      ++at_;
    } else if (starts_with(line, "```")) {
      code_block();
    } else if (const int level = heading_level(line)) {
      heading(level, line.substr(level + 1));
    } else if (is_anchor_line(line)) {
      out_ << line << "\n";
      ++at_;
    } else if (line[0] == '|' && at_ + 1 < lines_.size() && is_table_separator(lines_[at_ + 1])) {
      table();
    } else if (bullet_marker(line)) {
      list();
    } else {
      paragraph();
    }
  }

  void heading(int level, const std::string& text) {
    std::string id = heading_anchor(text);
    const int seen = used_ids_[id]++;
    if (seen > 0) id += "-" + std::to_string(seen);  // GitHub's rule for a repeated heading
    out_ << "<h" << level << " id=\"" << escape(id) << "\">" << inline_html(text) << "</h" << level << ">\n";
    ++at_;
  }

  void code_block() {
    ++at_;
    out_ << "<pre><code>";
    while (at_ < lines_.size() && !starts_with(lines_[at_], "```")) out_ << escape(lines_[at_++]) << "\n";
    if (at_ < lines_.size()) ++at_;
    out_ << "</code></pre>\n";
  }

  void table() {
    const std::vector<std::string> header = table_cells(lines_[at_]);
    at_ += 2;
    out_ << "<div class=\"table\"><table>\n<thead><tr>";
    for (const auto& h : header) out_ << "<th>" << inline_html(h) << "</th>";
    out_ << "</tr></thead>\n<tbody>\n";
    while (at_ < lines_.size() && !lines_[at_].empty() && lines_[at_][0] == '|') {
      out_ << "<tr>";
      for (const auto& c : table_cells(lines_[at_++])) out_ << "<td>" << inline_html(c) << "</td>";
      out_ << "</tr>\n";
    }
    out_ << "</tbody>\n</table></div>\n";
  }

  // Items run to a blank line; an indented or unmarked line continues the item above it.
  void list() {
    const bool ordered = std::isdigit(static_cast<unsigned char>(lines_[at_][0]));
    out_ << (ordered ? "<ol>\n" : "<ul>\n");
    std::string item;
    auto flush = [&] {
      if (!item.empty()) out_ << "<li>" << inline_html(item) << "</li>\n";
      item.clear();
    };
    while (at_ < lines_.size() && !is_blank(lines_[at_])) {
      const std::string& line = lines_[at_];
      const std::size_t marker = bullet_marker(line);
      const bool same_kind = marker && (std::isdigit(static_cast<unsigned char>(line[0])) != 0) == ordered;
      if (marker && !same_kind) break;
      if (heading_level(line) || (line[0] == '|' && at_ + 1 < lines_.size() && is_table_separator(lines_[at_ + 1]))) break;
      if (marker) {
        flush();
        item = line.substr(marker);
      } else {
        item += "\n" + line.substr(line.find_first_not_of(" \t"));
      }
      ++at_;
    }
    flush();
    out_ << (ordered ? "</ol>\n" : "</ul>\n");
  }

  void paragraph() {
    std::string text;
    while (at_ < lines_.size() && !is_blank(lines_[at_])) {
      const std::string& line = lines_[at_];
      if (!text.empty() && (heading_level(line) || starts_with(line, "```") || bullet_marker(line) || is_anchor_line(line) ||
                            (line[0] == '|' && at_ + 1 < lines_.size() && is_table_separator(lines_[at_ + 1]))))
        break;
      text += (text.empty() ? "" : "\n") + line;
      ++at_;
    }
    const bool lone_image = starts_with(text, "![") && text.find('\n') == std::string::npos && text.back() == ')' &&
                            text.find("](") != std::string::npos && text.find(")", text.find("](")) == text.size() - 1;
    out_ << (lone_image ? "<p class=\"figure\">" : "<p>") << inline_html(text) << "</p>\n";
  }

  std::vector<std::string> lines_;
  std::size_t at_ = 0;
  std::ostringstream out_;
  std::map<std::string, int> used_ids_;
};

// Decodes the UTF-8 code point at s[i] (advancing i); U+FFFD for a broken sequence.
char32_t next_code_point(const std::string& s, std::size_t& i) {
  const unsigned char c = static_cast<unsigned char>(s[i]);
  const int n = c < 0x80 ? 0 : (c >> 5) == 6 ? 1 : (c >> 4) == 14 ? 2 : (c >> 3) == 30 ? 3 : -1;
  if (n < 0 || i + static_cast<std::size_t>(n) >= s.size()) {
    ++i;
    return n == 0 ? c : 0xFFFD;
  }
  char32_t cp = n == 0 ? c : c & (0x3F >> n);
  for (int k = 1; k <= n; ++k) cp = (cp << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3F);
  i += n + 1;
  return cp;
}

// Letters of the Latin, Greek and Cyrillic blocks (an anchor keeps them, as GitHub's does).
bool is_letter_beyond_ascii(char32_t cp) {
  return (cp >= 0xC0 && cp <= 0x24F && cp != 0xD7 && cp != 0xF7) || (cp >= 0x370 && cp <= 0x3FF) || (cp >= 0x400 && cp <= 0x4FF);
}

// Lower case of the Latin-1, Latin Extended-A and Greek capitals (enough for report headings).
char32_t lower_case(char32_t cp) {
  if ((cp >= 0xC0 && cp <= 0xDE && cp != 0xD7) || (cp >= 0x391 && cp <= 0x3A9 && cp != 0x3A2)) return cp + 0x20;
  if (cp >= 0x100 && cp <= 0x137 && cp % 2 == 0) return cp + 1;
  return cp;
}

std::string utf8(char32_t cp) {
  std::string s;
  if (cp < 0x80) {
    s += static_cast<char>(cp);
  } else if (cp < 0x800) {
    s += static_cast<char>(0xC0 | (cp >> 6));
    s += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    s += static_cast<char>(0xE0 | (cp >> 12));
    s += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    s += static_cast<char>(0x80 | (cp & 0x3F));
  }
  return s;
}

const char kStyle[] = R"(body{font-family:system-ui,-apple-system,"Segoe UI",Roboto,"DejaVu Sans",sans-serif;line-height:1.5;color:#1b1f23;background:#fff;margin:0 auto;padding:1.5rem 2rem 4rem;max-width:72rem}
h1{font-size:1.9rem;border-bottom:2px solid #d0d7de;padding-bottom:.3rem}
h2{font-size:1.45rem;border-bottom:1px solid #d0d7de;padding-bottom:.2rem;margin-top:2.2rem}
h3{font-size:1.15rem;margin-top:1.6rem}
a{color:#0550ae}
code{font-family:"DejaVu Sans Mono",Menlo,Consolas,monospace;font-size:.88em;background:#f3f4f6;padding:.05em .3em;border-radius:3px}
pre{background:#f3f4f6;padding:.8rem;overflow-x:auto}
pre code{background:none;padding:0}
div.table{overflow-x:auto;margin:1rem 0;max-width:100%}
table{border-collapse:collapse;font-size:.9rem}
th,td{border:1px solid #d0d7de;padding:.25rem .55rem;text-align:left;vertical-align:top}
td{white-space:nowrap}
thead th{background:#f6f8fa;position:sticky;top:0}
tbody tr:nth-child(even){background:#fafbfc}
img{max-width:100%;height:auto}
p.figure{text-align:center;margin-bottom:0}
p.figure img{border:1px solid #e5e7eb}
li{margin:.2rem 0}
.cards{display:grid;grid-template-columns:repeat(auto-fill,minmax(20rem,1fr));gap:1rem}
)";

}  // namespace

std::string heading_anchor(const std::string& heading_text) {
  const std::string text = plain_text(heading_text);
  std::string id;
  for (std::size_t i = 0; i < text.size();) {
    const char32_t cp = next_code_point(text, i);
    if (cp < 0x80) {
      const char c = static_cast<char>(cp);
      if (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')
        id += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      else if (c == ' ')
        id += '-';
    } else if (is_letter_beyond_ascii(cp)) {
      id += utf8(lower_case(cp));
    }
  }
  return id;
}

std::string markdown_to_html(const std::string& markdown) { return Converter(markdown).run(); }

std::vector<Heading> headings(const std::string& markdown) {
  std::vector<Heading> out;
  std::map<std::string, int> used;
  std::istringstream in(markdown);
  bool in_code = false;
  for (std::string line; std::getline(in, line);) {
    if (starts_with(line, "```")) in_code = !in_code;
    const int level = in_code ? 0 : heading_level(line);
    if (!level) continue;
    Heading h{level, line.substr(level + 1), heading_anchor(line.substr(level + 1))};
    const int seen = used[h.anchor]++;
    if (seen > 0) h.anchor += "-" + std::to_string(seen);
    out.push_back(std::move(h));
  }
  return out;
}

std::string html_page(const std::string& markdown) {
  std::string title = "stoneskip";
  std::istringstream in(markdown);
  for (std::string line; std::getline(in, line);)
    if (heading_level(line) == 1) {
      title = plain_text(line.substr(2));
      break;
    }
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
         escape(title) + "</title>\n<style>\n" + kStyle + "</style>\n</head>\n<body>\n" + markdown_to_html(markdown) +
         "</body>\n</html>\n";
}

}  // namespace stoneskip
