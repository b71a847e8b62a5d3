#pragma once
// The skeleton every report section follows, so that all sections read alike and differ only
// where the science differs:
//   ## N. Title
//   **The question.** …   **What is measured.** … (settings formatted from the stored record)
//   **What it finds.** one bullet per stored verdict: subject: **verdict** — reason
//   tables and figures
//   **How to read it.** … (explanation without numbers or verdicts of its own)
//   *Cost of this section: … wall, … CPU.*
// A section renderer is a function of one Record read back from data.h5: it formats stored
// numbers, texts and verdicts and never computes a result of its own.
#include <string>
#include <vector>

#include "reports/common/figure.hpp"
#include "reports/common/markdown.hpp"
#include "verification/study/record.hpp"

namespace stoneskip {

struct SectionOutput {
  std::string markdown;
  std::vector<Figure> figures;
};

class SectionWriter {
 public:
  // heading: "2. Convergence against the exact solution" (written as a level-2 heading).
  SectionWriter(const Record& section, const std::string& heading);

  SectionWriter& text(const std::string& markdown);                            // a paragraph as given
  SectionWriter& lead(const std::string& lead, const std::string& markdown);   // "**lead** markdown"
  SectionWriter& subheading(const std::string& title);                         // ### title
  // "* subject: **verdict** — reason", from a stored verdict record (verification/study/record.hpp).
  SectionWriter& verdict(const std::string& subject, const Record& verdict);
  SectionWriter& bullet(const std::string& markdown);
  SectionWriter& end_list();  // a blank line after bullets
  SectionWriter& table(const MarkdownTable& t);
  SectionWriter& figure(Figure f);
  // The section's markdown and figures, with the cost line from the record's "cost" child.
  SectionOutput finish();

 private:
  const Record& section_;
  std::string md_;
  std::vector<Figure> figures_;
  bool in_list_ = false;
};

// "**verdict** — reason" of a stored verdict record.
std::string verdict_markdown(const Record& verdict);
// A stored order fit (verification/convergence/order_fit.hpp) as "p [low, high]", "–" when not
// valid; a fit of fewer than 3 points has a slope and no interval (its stored bounds are the slope
// itself, which would read as a certain order): "p (2 pts: no interval)".
std::string order_interval(const Record& fit);
// "`name`"
std::string code(const std::string& s);
// A number or "–" when it is NaN (formatted with `significant` digits).
std::string fmt_or_dash(double v, int significant = 3);

}  // namespace stoneskip
