// A figure gnuplot cannot draw leaves no picture behind. Oracle: the files themselves. A figure
// drawn once and then, with a script gnuplot refuses, drawn again: the second render names the
// failure and the first render's PNG is gone, not shown beside data it was not drawn from.
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <filesystem>
#include <string>

#include "reports/common/figure.hpp"
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

BOOST_AUTO_TEST_SUITE_END()
