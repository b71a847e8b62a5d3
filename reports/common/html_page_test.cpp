// The Markdown subset the renderers write becomes the HTML a reader expects. Oracle: the HTML
// written out by hand for each construct (CommonMark's output for the same input, less its
// whitespace), and GitHub's anchors for the same headings (checked on github.com by hand).
#include <boost/test/unit_test.hpp>

#include <string>

#include "reports/common/html_page.hpp"
#include "reports/common/markdown.hpp"
#include "reports/common/section.hpp"

using namespace stoneskip;

BOOST_AUTO_TEST_SUITE(markdown_as_html)

BOOST_AUTO_TEST_CASE(headings_get_githubs_anchors) {
  BOOST_TEST(heading_anchor("2. Convergence against the exact solution") == "2-convergence-against-the-exact-solution");
  BOOST_TEST(heading_anchor("Capture `cases/captures/gentle_sidearm.log`") == "capture-casescapturesgentle_sidearmlog");
  BOOST_TEST(heading_anchor("4. Isotropy: do waves travel at the same speed?") == "4-isotropy-do-waves-travel-at-the-same-speed");
  BOOST_TEST(heading_anchor("σ and μΔt — the limits × 2") == "σ-and-μδt--the-limits--2");
  BOOST_TEST(heading_anchor("See [the model](model/README.md)") == "see-the-model");
}

BOOST_AUTO_TEST_CASE(blocks_become_their_elements) {
  const std::string md =
      "# Title\n\nA paragraph\nover two lines.\n\n## 1. A section\n\n* one\n* two with `a|b`\n  continued\n\n"
      "1. first\n2. second\n\n```sh\nx < y\n```\n";
  const std::string html =
      "<h1 id=\"title\">Title</h1>\n<p>A paragraph\nover two lines.</p>\n<h2 id=\"1-a-section\">1. A section</h2>\n"
      "<ul>\n<li>one</li>\n<li>two with <code>a|b</code>\ncontinued</li>\n</ul>\n"
      "<ol>\n<li>first</li>\n<li>second</li>\n</ol>\n<pre><code>x &lt; y\n</code></pre>\n";
  BOOST_TEST(markdown_to_html(md) == html);
}

BOOST_AUTO_TEST_CASE(a_repeated_heading_gets_a_numbered_anchor) {
  BOOST_TEST(markdown_to_html("### Throw\n\n### Throw\n") == "<h3 id=\"throw\">Throw</h3>\n<h3 id=\"throw-1\">Throw</h3>\n");
}

BOOST_AUTO_TEST_CASE(a_pipe_table_scrolls_in_its_own_box) {
  const std::string md = "| a | `x|y` | **c** |\n|---|---|---|\n| 1 | 2 | 3 \\| 4 |\n\nafter\n";
  const std::string html =
      "<div class=\"table\"><table>\n<thead><tr><th>a</th><th><code>x|y</code></th><th><strong>c</strong></th></tr></thead>\n"
      "<tbody>\n<tr><td>1</td><td>2</td><td>3 | 4</td></tr>\n</tbody>\n</table></div>\n<p>after</p>\n";
  BOOST_TEST(markdown_to_html(md) == html);
}

BOOST_AUTO_TEST_CASE(inline_marks_links_and_images) {
  BOOST_TEST(markdown_to_html("**bold** and *it* and a * b and 2*3*4\n") ==
             "<p><strong>bold</strong> and <em>it</em> and a * b and 2<em>3</em>4</p>\n");
  BOOST_TEST(markdown_to_html("*Figure: a **b** c* ([SVG](figures/f.svg))\n") ==
             "<p><em>Figure: a <strong>b</strong> c</em> (<a href=\"figures/f.svg\">SVG</a>)</p>\n");
  BOOST_TEST(markdown_to_html("![A \"t\" < 2](figures/f.png)\n") ==
             "<p class=\"figure\"><img src=\"figures/f.png\" alt=\"A &quot;t&quot; &lt; 2\"></p>\n");
  BOOST_TEST(markdown_to_html("[`x`](#x_log) [w](waves/index.md#2-a) [o](https://e.org/a.md)\n") ==
             "<p><a href=\"#x_log\"><code>x</code></a> <a href=\"waves/index.html#2-a\">w</a> "
             "<a href=\"https://e.org/a.md\">o</a></p>\n");
}

BOOST_AUTO_TEST_CASE(a_link_from_the_data_runs_no_script_and_a_pipe_in_a_cell_keeps_the_columns) {
  // Titles and notes come from the user's files: "[link](javascript:alert(2))" in a case's title
  // became a live link on the front page. Oracle: a browser's reading of the scheme (tabs and line
  // breaks dropped, leading controls and spaces too, case folded): every such target is shown as
  // text; http, https, mailto, fragments and relative paths stay links.
  BOOST_TEST(markdown_to_html("[a](javascript:alert(2))\n") == "<p>a</p>\n");
  BOOST_TEST(markdown_to_html("[a](JavaScript:alert(2))\n") == "<p>a</p>\n");
  BOOST_TEST(markdown_to_html("[a](java\tscript:alert(2))\n") == "<p>a</p>\n");
  BOOST_TEST(markdown_to_html("[a](data:text/html,x)\n") == "<p>a</p>\n");
  BOOST_TEST(markdown_to_html("![pic](data:image/svg+xml,x)\n").find("<img") == std::string::npos);
  BOOST_TEST(markdown_to_html("[a](http://e.org/x) [b](mailto:a@b.c) [c](dir/x:y.html)\n") ==
             "<p><a href=\"http://e.org/x\">a</a> <a href=\"mailto:a@b.c\">b</a> <a href=\"dir/x:y.html\">c</a></p>\n");
  // A cell holding '|' (a title "a | b") keeps its row's columns; in a code span it stays as is.
  MarkdownTable t({"title", "n"});
  t.row({"a | b", "1"}).row({"`x|y`", "2"});
  const std::string html = markdown_to_html(t.str());
  BOOST_TEST(html.find("<td>a | b</td>") != std::string::npos, html);
  BOOST_TEST(html.find("<td><code>x|y</code></td>") != std::string::npos, html);
  BOOST_TEST(html.find("<td>1</td>") != std::string::npos, html);
}

BOOST_AUTO_TEST_CASE(code_spans_of_several_backticks_hold_backticks_and_pipes) {
  // CommonMark 0.30 §6.1, examples 328–331 and 339 (a span ends at a run of exactly its opening
  // length; one space is stripped from each end when both have one), and code() writing them.
  BOOST_TEST(markdown_to_html("``foo ` bar``\n") == "<p><code>foo ` bar</code></p>\n");
  BOOST_TEST(markdown_to_html("` `` `\n") == "<p><code>``</code></p>\n");
  BOOST_TEST(markdown_to_html("a ```foo`` b\n") == "<p>a ```foo`` b</p>\n");
  BOOST_TEST(markdown_to_html("| ``a|`b`` | c |\n|---|---|\n") ==
             "<div class=\"table\"><table>\n<thead><tr><th><code>a|`b</code></th><th>c</th></tr></thead>\n"
             "<tbody>\n</tbody>\n</table></div>\n");
  BOOST_TEST(code("a`b") == "``a`b``");
  BOOST_TEST(code("`a``b`") == "``` `a``b` ```");
  BOOST_TEST(code(" x ") == "`  x  `");
  BOOST_TEST(code("two\nlines") == "`two\\nlines`");
  BOOST_TEST(markdown_to_html("Made by: " + code("run --out `a``b`") + ".\n") ==
             "<p>Made by: <code>run --out `a``b`</code>.</p>\n");
}

BOOST_AUTO_TEST_CASE(anchor_lines_pass_through_and_other_html_is_text) {
  BOOST_TEST(markdown_to_html("<a id=\"gentle_log\"></a>\n<script>x</script>\n") ==
             "<a id=\"gentle_log\"></a>\n<p>&lt;script&gt;x&lt;/script&gt;</p>\n");
}

BOOST_AUTO_TEST_CASE(the_page_is_whole_and_needs_nothing_from_elsewhere) {
  const std::string page = html_page("# Waves: *z_tt*\n\ntext\n");
  BOOST_TEST(page.rfind("<!DOCTYPE html>", 0) == 0);
  BOOST_TEST(page.find("<title>Waves: z_tt</title>") != std::string::npos);
  BOOST_TEST(page.find("overflow-x:auto") != std::string::npos);  // wide tables scroll
  BOOST_TEST(page.find("<script") == std::string::npos);
  BOOST_TEST(page.find("http") == std::string::npos);  // no style sheet, font or script from elsewhere
  BOOST_TEST(page.find("</html>\n") == page.size() - 8);
}

BOOST_AUTO_TEST_SUITE_END()
