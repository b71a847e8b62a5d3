// A figure gnuplot cannot draw leaves no picture behind. Oracle: the files themselves. A figure
// drawn once and then, with a script gnuplot refuses, drawn again: the second render names the
// failure and the first render's PNG is gone, not shown beside data it was not drawn from. And the
// page: every picture it links is on disk, and a figure not drawn is named in its place with
// gnuplot's words (oracle: the written index.md against the folder).
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "reports/common/figure.hpp"
#include "reports/common/stored_report.hpp"
#include "tools/io/subprocess.hpp"

using namespace stoneskip;
namespace fs = std::filesystem;

BOOST_AUTO_TEST_SUITE(figure_render)

BOOST_AUTO_TEST_CASE(a_figure_that_fails_to_draw_leaves_no_older_picture) {
  if (!program_runs({"gnuplot", "--version"})) {
    BOOST_TEST_MESSAGE("gnuplot not found: nothing to draw");
    return;
  }
  const fs::path dir = fs::temp_directory_path() / ("stoneskip_figure_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  Figure f;
  f.name = "curve";
  f.title = "a curve";
  f.script = "plot x";
  RenderSummary first = render_figures(dir, {f});
  BOOST_TEST(first.failures.empty());
  BOOST_TEST(first.rendered == 1);
  BOOST_REQUIRE(fs::exists(dir / "figures" / "curve.png"));
  f.script = "plot no_such_function_here(x)";  // gnuplot: "undefined function"
  RenderSummary second = render_figures(dir, {f});
  BOOST_TEST(second.failures.size() == 2u);  // the PNG and the SVG
  BOOST_TEST(second.rendered == 0);
  BOOST_TEST(!fs::exists(dir / "figures" / "curve.png"));
  BOOST_TEST(!fs::exists(dir / "figures" / "curve.svg"));
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(the_page_names_a_figure_not_drawn_in_its_place_and_links_only_pictures_on_disk) {
  if (!program_runs({"gnuplot", "--version"})) {
    BOOST_TEST_MESSAGE("gnuplot not found: nothing to draw");
    return;
  }
  const fs::path dir = fs::temp_directory_path() / ("stoneskip_figure_page_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  Figure good, bad;
  good.name = "good";
  good.title = "a curve that draws";
  good.script = "plot x";
  bad.name = "bad";
  bad.title = "a curve gnuplot refuses";
  bad.script = "plot no_such_function_here(x)";
  bad.data_path = "/sections/somewhere";
  RenderedReport r;
  r.figures = {good, bad};
  r.markdown = "# A page\n\n" + figure_markdown(good) + figure_markdown(bad) + "The end.\n";
  const RenderSummary s = write_rendered_report(dir, r);
  BOOST_TEST(s.rendered == 1);
  BOOST_REQUIRE(s.not_drawn.size() == 1u);  // one entry for the figure, not one per file
  BOOST_TEST(s.not_drawn.front().first == "bad");
  std::ifstream in(dir / "index.md");
  std::stringstream md;
  md << in.rdbuf();
  const std::string page = md.str();
  // Every image and link into figures/ names a file that is there.
  const std::regex link(R"(\]\((figures/[^)]+)\))");
  int links = 0;
  for (std::sregex_iterator it(page.begin(), page.end(), link), end; it != end; ++it, ++links)
    BOOST_TEST(fs::exists(dir / (*it)[1].str()), (*it)[1].str() + " is linked but not on disk");
  BOOST_TEST(links == 2);  // the good figure's PNG and SVG
  BOOST_TEST(page.find("**Figure not drawn:** *a curve gnuplot refuses*") != std::string::npos);
  BOOST_TEST(page.find("undefined function") != std::string::npos);  // gnuplot's words, as it said them
  BOOST_TEST(page.find("`data.h5:/sections/somewhere`") != std::string::npos);
  BOOST_TEST(page.find("The end.") != std::string::npos);
  BOOST_TEST(page.find("Its script: `figures/bad.gp`") != std::string::npos);
  // Where gnuplot is not found no script is written, and none is named.
  BOOST_TEST(figure_not_drawn_markdown(bad, "gnuplot not found", false).find("Its script") == std::string::npos);
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
