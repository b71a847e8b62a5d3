// A report's opening is read back from its Markdown as written. Oracle: small pages written here by
// hand, with the findings, verdict phrases and anchors a reader would take from them.
#include <boost/test/unit_test.hpp>

#include <string>
#include <vector>

#include "reports/common/summary.hpp"

using namespace stoneskip;

BOOST_AUTO_TEST_SUITE(summary)

BOOST_AUTO_TEST_CASE(findings_are_read_from_a_reports_opening) {
  const std::string md =
      "# R\n\nintro\n\n## Findings\n\n* a: **x** — y\n  continued\n* b: **z**\n\n## 1. First\n\n* not a finding\n";
  const auto f = report_findings(md);
  BOOST_TEST(f.size() == 2u);
  BOOST_TEST(f[0] == "a: **x** — y continued");
  BOOST_TEST(verdict_phrases(f[0]).size() == 1u);
  BOOST_TEST(report_findings("# R\n\n## Verdicts\n\n3 captures: 2 usable.\n\n| a |\n|---|\n") ==
             std::vector<std::string>{"3 captures: 2 usable."});
  BOOST_TEST(report_findings("# R\n\n## 1. First\n\n* x\n").empty());
}

BOOST_AUTO_TEST_CASE(the_contents_line_links_every_section_before_the_first) {
  const std::string md = "# R\n\nintro\n\n## Findings\n\n* a\n\n## 1. First: a\n\n## 1. First: a\n";
  BOOST_TEST(with_contents(md) ==
             "# R\n\nintro\n\n**In this report:** [Findings](#findings) · [1. First: a](#1-first-a) · [1. First: a](#1-first-a-1)\n\n"
             "## Findings\n\n* a\n\n## 1. First: a\n\n## 1. First: a\n");
  BOOST_TEST(with_contents("# R\n\nno sections\n") == "# R\n\nno sections\n");
}

BOOST_AUTO_TEST_SUITE_END()
