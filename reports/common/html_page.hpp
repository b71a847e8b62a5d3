#pragma once
// A report's page in the browser: the Markdown the renderers write (a known subset — headings,
// paragraphs, bullet and numbered lists, pipe tables, images, links, **bold**, *italic*, `code`,
// fenced code and `<a id="…"></a>` anchor lines) turned into one self-contained HTML page, so
// index.html and index.md are made from the same text and never drift apart. No script, no
// font or style sheet from elsewhere: the page reads offline. Wide tables scroll sideways; a
// relative link to a `.md` file points at the `.html` beside it.
#include <string>
#include <vector>

namespace stoneskip {

// The id a heading gets in the HTML (and the `#fragment` a Markdown link to it uses): its text
// without Markdown marks, lower case, spaces as '-', punctuation dropped (letters beyond ASCII
// kept), as GitHub names its headings' anchors. "2. Convergence, in time" -> "2-convergence-in-time".
std::string heading_anchor(const std::string& heading_text);

// The headings of a Markdown text in order (not those inside fenced code), each with the id the
// HTML gives it: heading_anchor() of its text, "-1", "-2", … added to a repeat, as GitHub does.
struct Heading {
  int level = 0;
  std::string text;    // as written, Markdown marks included
  std::string anchor;
};
std::vector<Heading> headings(const std::string& markdown);

// The body of the page: the Markdown as HTML elements (no <html>/<head>).
std::string markdown_to_html(const std::string& markdown);

// The whole page: <!DOCTYPE html>, the title (the first level-1 heading), the style sheet inline,
// and the body above.
std::string html_page(const std::string& markdown);

}  // namespace stoneskip
