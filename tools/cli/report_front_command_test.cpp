// End-to-end tests of `stoneskip report front OUT` on a folder holding one real report (a captures
// report written by `capture validate --out`, the quickest to make) and things that are not one.
// Oracle: the output contract (nothing written through a link; nothing in OUT dropped without a
// word) and the page's own lines, which name what they read.
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tools/cli/test_support.hpp"

namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// OUT with one captures report in OUT/captures.
struct Folder {
  fs::path out = fs::temp_directory_path() / ("stoneskip_front_cli_" + std::to_string(::getpid()));
  Folder() {
    fs::remove_all(out);
    fs::create_directories(out);
    const auto r = stoneskip::test::run_stoneskip("capture validate cases/captures/gentle_sidearm.log --no-simulate --members 4 --out " +
                                                  (out / "captures").string());
    BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  }
  ~Folder() { fs::remove_all(out); }
};

}  // namespace

BOOST_AUTO_TEST_SUITE(report_front_command)

BOOST_AUTO_TEST_CASE(what_is_not_shown_is_said_and_links_are_not_followed) {
  // A damaged copy of the report's data.h5 (its first 2 KB), a link to the report folder, a text
  // file named as a movie and a report's data.h5 put among the throws: none is shown as what it
  // seems, each is listed under "Not shown" on the page and on stderr. Before, the damaged report
  // vanished from a page that says it links everything, the link was listed twice, and the text
  // file was "the scene as a movie".
  Folder f;
  fs::create_directories(f.out / "broken");
  {
    const std::string h5 = read(f.out / "captures" / "data.h5");
    std::ofstream(f.out / "broken" / "data.h5", std::ios::binary) << h5.substr(0, 2048);
  }
  fs::create_directory_symlink(f.out / "captures", f.out / "linked");
  fs::create_directories(f.out / "linked_data");  // a real folder whose data.h5 is a link
  fs::create_symlink(f.out / "captures" / "data.h5", f.out / "linked_data" / "data.h5");
  fs::create_directories(f.out / "folder_data" / "data.h5");  // a data.h5 that is a folder
  fs::create_directories(f.out / "movies");
  std::ofstream(f.out / "movies" / "fake.mp4") << "not a movie\n";
  fs::create_directories(f.out / "throws");
  fs::copy_file(f.out / "captures" / "data.h5", f.out / "throws" / "report.h5");
  const auto r = stoneskip::test::run_stoneskip("report front " + f.out.string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  BOOST_TEST(has(r.out, "1 reports, 0 movies, 0 throws"), r.out);
  const std::string md = read(f.out / "index.md");
  BOOST_TEST(has(md, "## Not shown"), md);
  for (const char* path : {"`broken/data.h5`", "`linked`", "`movies/fake.mp4`", "`throws/report.h5`", "`linked_data/data.h5`",
                           "`folder_data/data.h5`"}) {
    BOOST_TEST(has(md, path), path << "\n" << md);
    BOOST_TEST(has(r.out, std::string("not shown: ") + std::string(path).substr(1, std::string(path).size() - 2)), path << "\n" << r.out);
  }
  BOOST_TEST(!has(md, "(linked/index.md)"), md);
  BOOST_TEST(!has(md, "the scene as a movie"), md);
}

BOOST_AUTO_TEST_CASE(a_report_without_its_page_is_not_linked_and_linked_figures_are_not_shown) {
  // A copy of the report with no index.md (data written, page not rendered) would be a link that
  // leads nowhere: it is listed under "Not shown" with the command that renders it. A copy whose
  // figures/ is a link to another folder is shown, but with no picture read through the link.
  Folder f;
  BOOST_REQUIRE(fs::is_regular_file(f.out / "captures" / "index.md"));
  BOOST_REQUIRE(fs::is_directory(f.out / "captures" / "figures"));
  fs::create_directories(f.out / "unrendered");
  fs::copy_file(f.out / "captures" / "data.h5", f.out / "unrendered" / "data.h5");
  fs::create_directories(f.out / "zlinked_figures");
  fs::copy_file(f.out / "captures" / "data.h5", f.out / "zlinked_figures" / "data.h5");
  fs::copy_file(f.out / "captures" / "index.md", f.out / "zlinked_figures" / "index.md");
  fs::create_directory_symlink(f.out / "captures" / "figures", f.out / "zlinked_figures" / "figures");
  const auto r = stoneskip::test::run_stoneskip("report front " + f.out.string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  BOOST_TEST(has(r.out, "2 reports, 0 movies, 0 throws"), r.out);
  const std::string md = read(f.out / "index.md");
  BOOST_TEST(has(md, "`unrendered/index.md`"), md);
  BOOST_TEST(has(md, "stoneskip report render " + (f.out / "unrendered").string()), md);
  BOOST_TEST(!has(md, "(unrendered/index.md)"), md);
  BOOST_TEST(has(md, "(zlinked_figures/index.md)"), md);
  BOOST_TEST(has(md, "(captures/figures/"), md);
  BOOST_TEST(!has(md, "(zlinked_figures/figures/"), md);
  // Its folder line says the link is not followed, where it listed `figures/` among its contents.
  BOOST_TEST(has(md, "[page](zlinked_figures/index.md), `data.h5` (its `figures/` is a link, not followed)."), md);
  BOOST_TEST(has(md, "[page](captures/index.md), `data.h5`, `figures/`."), md);
}

BOOST_AUTO_TEST_CASE(a_linked_output_folder_is_refused) {
  // The pages go into OUT itself: through a link they would land in another folder. Refused with
  // one line, exit 2, nothing written there (with or without a trailing slash).
  Folder f;
  const fs::path link = f.out.string() + "_link";
  fs::remove(link);
  fs::create_directory_symlink(f.out, link);
  for (const std::string& name : {link.string(), link.string() + "/"}) {
    const auto r = stoneskip::test::run_stoneskip("report front " + name);
    BOOST_TEST(r.status == 2, r.out);
    BOOST_TEST(has(r.out, "is a link"), r.out);
    BOOST_TEST(std::count(r.out.begin(), r.out.end(), '\n') == 1, r.out);
  }
  BOOST_TEST(!fs::exists(f.out / "index.md"));
  fs::remove(link);
}

BOOST_AUTO_TEST_SUITE_END()
