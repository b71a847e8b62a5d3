#include "reports/common/summary.hpp"

#include <sstream>

#include "reports/common/html_page.hpp"

namespace stoneskip {

std::string with_contents(const std::string& markdown) {
  std::string links;
  for (const Heading& h : headings(markdown))
    if (h.level == 2) links += (links.empty() ? "" : " · ") + ("[" + h.text + "](#" + h.anchor + ")");
  if (links.empty()) return markdown;
  // The first level-2 heading at the start of a line (not inside fenced code: headings() agrees).
  std::size_t at = markdown.rfind("## ", 0) == 0 ? 0 : markdown.find("\n## ");
  bool in_code = false;
  std::istringstream in(markdown);
  std::size_t pos = 0;
  for (std::string line; std::getline(in, line); pos += line.size() + 1) {
    if (line.rfind("```", 0) == 0) in_code = !in_code;
    if (!in_code && line.rfind("## ", 0) == 0) {
      at = pos;
      break;
    }
  }
  return markdown.substr(0, at) + "**In this report:** " + links + "\n\n" + markdown.substr(at);
}

std::vector<std::string> report_findings(const std::string& markdown) {
  std::vector<std::string> out;
  std::string first_paragraph;
  bool paragraph_done = false;
  std::istringstream in(markdown);
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("## ", 0) == 0) {
      if (inside) break;
      inside = line == "## Findings" || line == "## Verdicts";
      continue;
    }
    if (!inside) continue;
    if (!paragraph_done && out.empty()) {
      if (line.empty() || line[0] == '|' || line[0] == '<' || line[0] == '!' || line.rfind("* ", 0) == 0)
        paragraph_done = paragraph_done || !first_paragraph.empty();
      else
        first_paragraph += (first_paragraph.empty() ? "" : " ") + line;
    }
    if (line.rfind("* ", 0) == 0)
      out.push_back(line.substr(2));
    else if (!out.empty() && !line.empty() && (line[0] == ' ' || line[0] == '\t'))
      out.back() += " " + line.substr(line.find_first_not_of(" \t"));
  }
  if (out.empty() && !first_paragraph.empty()) out.push_back(first_paragraph);
  return out;
}

std::vector<std::string> verdict_phrases(const std::string& finding) {
  std::vector<std::string> out;
  for (std::size_t at = finding.find("**"); at != std::string::npos;) {
    const std::size_t end = finding.find("**", at + 2);
    if (end == std::string::npos) break;
    out.push_back(finding.substr(at + 2, end - at - 2));
    at = finding.find("**", end + 2);
  }
  return out;
}

}  // namespace stoneskip
