// The front page says what the reports say, no more. Oracle: findings written here by hand as a
// report's opening would state them; the page must carry each verdict phrase once with its count,
// link each report, movie and throw, and point a finding's in-page link into its report.
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "reports/front/front_page.hpp"
#include "tools/io/input_error.hpp"

using namespace stoneskip;

namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

FrontPageInput two_reports() {
  FrontPageInput in;
  FrontReport w;
  w.folder = "waves";
  w.kind = "waves";
  w.title = "Water surface verification";
  w.findings = {"`five_point`: **consistent**; space order 2 (**converges at the expected order**)",
                "`paper_eq11`: **inconsistent** ([§1](#1-consistency))", "`nine_point_half`: **consistent**"};
  w.picture = "waves/figures/convergence.png";
  FrontReport c;
  c.folder = "captures";
  c.kind = "captures";
  c.title = "Wii Remote captures";
  c.findings = {"9 capture(s): 1 usable, 7 usable with caveats, 1 unusable."};
  in.reports = {w, c};
  in.movies = {FrontMovie{"movies/seed.mp4", 0.3, "scene/figures/still.png"}};
  FrontThrow t;
  t.file = "throws/paper_8ms_spin.h5";
  t.title = "Lee & Baek 8 m/s throw, with spin";
  t.case_file = "cases/paper_8ms_spin.toml";
  t.runs = {FrontThrowRun{"realtime", "sank", 7, 4.25}, FrontThrowRun{"reference", "sank", 1, 1.24}};
  in.throws = {t};
  return in;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(front_page_markdown_tests)

BOOST_AUTO_TEST_CASE(each_report_gets_its_verdicts_in_one_line_with_counts) {
  const std::string md = front_page_markdown(two_reports());
  BOOST_TEST(has(md, "### [Water surface verification](waves/index.md)"));
  BOOST_TEST(has(md, "**Its findings' verdicts:** **consistent** ×2 · **converges at the expected order** · **inconsistent**."));
  BOOST_TEST(has(md, "![Water surface verification](waves/figures/convergence.png)"));
  // Findings without bold verdicts give their first sentence.
  BOOST_TEST(has(md, "### [Wii Remote captures](captures/index.md)\n\n**Its findings' verdicts:** 9 capture(s): 1 usable, 7 usable with caveats, 1 unusable. "));
}

BOOST_AUTO_TEST_CASE(what_we_found_repeats_the_findings_with_links_into_the_reports) {
  const std::string md = front_page_markdown(two_reports());
  const std::string found = md.substr(md.find("## What we found"));
  BOOST_TEST(has(found, "* `paper_eq11`: **inconsistent** ([§1](waves/index.md#1-consistency))\n"));
  BOOST_TEST(has(found, "* 9 capture(s): 1 usable, 7 usable with caveats, 1 unusable.\n"));
}

BOOST_AUTO_TEST_CASE(the_movie_and_every_throw_are_linked) {
  const std::string md = front_page_markdown(two_reports());
  BOOST_TEST(has(md, "[`movies/seed.mp4`](movies/seed.mp4) (0.3 MB)"));
  BOOST_TEST(has(md, "![A still of the scene](scene/figures/still.png)"));
  // A movie without a throw of its name is "the scene"; one with it is named by that throw's title.
  BOOST_TEST(has(md, "(0.3 MB): the scene as a movie.\n"));
  FrontPageInput named = two_reports();
  named.movies.front().file = "movies/paper_8ms_spin.mp4";
  BOOST_TEST(has(front_page_markdown(named), "(0.3 MB): the scene of `paper_8ms_spin.h5` (Lee & Baek 8 m/s throw, with spin) as a movie.\n"));
  BOOST_TEST(has(md, "| [`paper_8ms_spin.h5`](throws/paper_8ms_spin.h5) | Lee & Baek 8 m/s throw, with spin | `cases/paper_8ms_spin.toml` | "
                     "7, 4.25, sank | 1, 1.24, sank |"));
}

BOOST_AUTO_TEST_CASE(two_reports_of_one_title_are_told_apart_by_folder) {
  FrontPageInput in = two_reports();
  in.reports.push_back(in.reports.back());
  in.reports.back().folder = "capture_scene";
  const std::string md = front_page_markdown(in);
  BOOST_TEST(has(md, "### [Wii Remote captures (`captures/`)](captures/index.md)"));
  BOOST_TEST(has(md, "### [Wii Remote captures (`capture_scene/`)](capture_scene/index.md)"));
  BOOST_TEST(has(md, "### [Water surface verification](waves/index.md)"));
}

BOOST_AUTO_TEST_CASE(a_folder_name_is_a_link_to_itself_whatever_its_characters) {
  // Oracle: RFC 3986 percent-encoding of the link target. "#x" had become an in-page anchor, "%41"
  // a link to "A", and a line break ended the heading's line.
  FrontPageInput in = two_reports();
  in.reports[0].folder = "#x %41\nb";
  in.reports[0].picture = "#x %41\nb/figures/c.png";
  const std::string md = front_page_markdown(in);
  BOOST_TEST(has(md, "](%23x%20%2541%0Ab/index.md)"), md);
  BOOST_TEST(has(md, "(%23x%20%2541%0Ab/figures/c.png)"), md);
  BOOST_TEST(!has(md, "](#x"), md);
  const std::string heading = md.substr(md.find("### [Water surface verification]"));
  BOOST_TEST(heading.substr(0, heading.find('\n')).find("index.md)") != std::string::npos, heading.substr(0, 200));
}

BOOST_AUTO_TEST_CASE(the_page_replaces_a_front_page_but_not_someone_s_index) {
  // Oracle: the output contract: a file stoneskip did not write is never replaced. A folder with
  // someone's index.md is refused and the file kept; the page itself is written, then rewritten.
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("stoneskip_front_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string page = front_page_markdown(two_reports());
  write_front_page(dir, page);
  write_front_page(dir, page);  // its own page: replaced
  { std::ofstream(dir / "index.md") << "# My notes\n"; }
  BOOST_CHECK_THROW(write_front_page(dir, page), InputError);
  std::ifstream in(dir / "index.md");
  std::string first;
  std::getline(in, first);
  BOOST_TEST(first == "# My notes");
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
