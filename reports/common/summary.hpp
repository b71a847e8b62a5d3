#pragma once
// What a report's opening says, read back from its own Markdown: its findings (the bullets of its
// "## Findings" or "## Verdicts" section, each formatted from a stored verdict by the report's
// renderer) and links to its sections. The front page (reports/front/) lists the same findings,
// so the two never say different things.
#include <string>
#include <vector>

namespace stoneskip {

// The report with a line of links to its sections ("**In this report:** [1. …](#1-…) · …") put
// before its first level-2 heading; a report without level-2 headings is returned as it is.
std::string with_contents(const std::string& markdown);

// The bullets of the first "## Findings" or "## Verdicts" section, without their "* " (a bullet
// that runs over several lines is one finding); a section without bullets gives its first
// paragraph as its one finding; empty when there is no such section.
std::vector<std::string> report_findings(const std::string& markdown);

// The bold verdict phrases of a finding ("`x`: **consistent**; … (**does not converge**)" ->
// {"consistent", "does not converge"}).
std::vector<std::string> verdict_phrases(const std::string& finding);

}  // namespace stoneskip
