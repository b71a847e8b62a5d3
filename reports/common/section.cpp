#include "reports/common/section.hpp"

#include <algorithm>

namespace stoneskip {

std::string verdict_markdown(const Record& v) { return "**" + v.text("verdict") + "** — " + v.text("reason"); }

std::string order_interval(const Record& fit) {
  if (!fit.flag("valid")) return "–";
  if (fit.has("points") && fit.number("points") < 3)
    return fmt(fit.number("order"), 3) + " (" + fmt(fit.number("points")) + " pts: no interval)";
  return fmt(fit.number("order"), 3) + " [" + fmt(fit.number("order_low"), 3) + ", " + fmt(fit.number("order_high"), 3) + "]";
}

std::string code(const std::string& s) {
  // A code span holds any text (CommonMark 0.30 §6.1): delimited by more backticks than the longest
  // run inside, padded with a space where the text starts or ends with one; a line break, which
  // would end the span or the paragraph (a stored name used to start a heading), is written \n.
  std::string text;
  std::size_t run = 0, longest = 0;
  for (char ch : s) {
    run = ch == '`' ? run + 1 : 0;
    longest = std::max(longest, run);
    if (ch == '\n') text += "\\n";
    else if (ch == '\r') text += "\\r";
    else text += ch;
  }
  const std::string fence(longest + 1, '`');
  // Padded where the text starts or ends with a backtick, or starts and ends with a space (one of
  // which a reader strips).
  const bool pad = !text.empty() && (text.front() == '`' || text.back() == '`' ||
                                     (text.front() == ' ' && text.back() == ' ' && text.find_first_not_of(' ') != std::string::npos));
  return fence + (pad ? " " : "") + text + (pad ? " " : "") + fence;
}

std::string fmt_or_dash(double v, int significant) { return fmt(v, significant); }

SectionWriter::SectionWriter(const Record& section, const std::string& heading) : section_(section) {
  md_ = "## " + heading + "\n\n";
}

SectionWriter& SectionWriter::end_list() {
  if (in_list_) md_ += "\n";
  in_list_ = false;
  return *this;
}

SectionWriter& SectionWriter::text(const std::string& markdown) {
  end_list();
  md_ += markdown + "\n\n";
  return *this;
}

SectionWriter& SectionWriter::lead(const std::string& lead, const std::string& markdown) {
  return text("**" + lead + "** " + markdown);
}

SectionWriter& SectionWriter::subheading(const std::string& title) {
  end_list();
  md_ += "### " + title + "\n\n";
  return *this;
}

SectionWriter& SectionWriter::bullet(const std::string& markdown) {
  md_ += "* " + markdown + "\n";
  in_list_ = true;
  return *this;
}

SectionWriter& SectionWriter::verdict(const std::string& subject, const Record& v) {
  return bullet(subject + ": " + verdict_markdown(v));
}

SectionWriter& SectionWriter::table(const MarkdownTable& t) {
  end_list();
  md_ += t.str() + "\n";
  return *this;
}

SectionWriter& SectionWriter::figure(Figure f) {
  end_list();
  if (f.data_path.empty()) f.data_path = section_.path();
  md_ += figure_markdown(f);
  figures_.push_back(std::move(f));
  return *this;
}

SectionOutput SectionWriter::finish() {
  end_list();
  if (section_.has_child("cost")) {
    const Record& c = section_.at("cost");
    md_ += "*Cost of this section: " + fmt(c.number("wall_s"), 3) + " s wall, " + fmt(c.number("cpu_s"), 3) +
           " s CPU (all threads).*\n\n";
  }
  return SectionOutput{md_, figures_};
}

}  // namespace stoneskip
