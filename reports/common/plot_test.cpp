// A title quoted for gnuplot stays one string, whatever it holds. Oracle: gnuplot's rules for a
// single-quoted string (a quote is doubled, a line break ends the command), checked on the text,
// and gnuplot itself run on a title that would otherwise call `system "touch PWNED"`: no PWNED.
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "reports/common/plot.hpp"
#include "tools/io/subprocess.hpp"

using namespace stoneskip;
namespace fs = std::filesystem;

BOOST_AUTO_TEST_SUITE(plot)

BOOST_AUTO_TEST_CASE(quotes_are_doubled_and_line_breaks_become_spaces) {
  BOOST_TEST(gnuplot_quote("it's") == "'it''s'");
  BOOST_TEST(gnuplot_quote("a\nb\rc") == "'a b c'");
  BOOST_TEST(gnuplot_quote("x_1") == "'x\\_1'");
}

BOOST_AUTO_TEST_CASE(gnuplot_runs_no_command_hidden_in_a_title) {
  // Premise: gnuplot is installed (tools/setup installs it); without it there is nothing to run.
  if (!program_runs({"gnuplot", "--version"})) {
    BOOST_TEST_MESSAGE("gnuplot not found: the end-to-end half of this test is skipped");
    return;
  }
  const fs::path dir = fs::temp_directory_path() / ("stoneskip_plot_quote_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string hostile = "t'\nsystem \"touch PWNED\"\nset title '";
  std::ofstream(dir / "t.gp") << "set terminal dumb\nset output 'out.txt'\nset title " << gnuplot_quote(hostile)
                              << "\nplot x\n";
  SubprocessOptions o;
  o.working_dir = dir;
  const SubprocessResult r = run_program({"gnuplot", "t.gp"}, o);
  BOOST_TEST(r.ok(), r.err);
  BOOST_TEST(!fs::exists(dir / "PWNED"));
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_long_caption_gives_a_title_that_fits_the_plot) {
  // Oracle: the rule by hand. The stones report's Clanet caption (171 characters) ran off both
  // edges of its plot: its closing parenthetical goes, leaving 96; a caption of words only is cut
  // at a word before 108 with " …"; a short caption is the title whole. The caption keeps it all.
  const std::string clanet =
      "Clanet's disk: minimum bouncing speed against attack angle at β = 20°, measured and each variant "
      "(crosses: the ends of each bisection's bracket)";
  BOOST_TEST(plot_title(clanet) == "Clanet's disk: minimum bouncing speed against attack angle at β = 20°, measured and each variant");
  std::string words;
  for (int i = 0; i < 30; ++i) words += "word" + std::to_string(i) + " ";
  const std::string cut = plot_title(words);
  BOOST_TEST(cut.size() <= 110u);
  BOOST_TEST(cut.substr(cut.size() - 4) == " …");
  BOOST_TEST(words.find(cut.substr(0, cut.size() - 4) + " ") == 0u);  // whole words, from the start
  BOOST_TEST(plot_title("Bounces against spin (two solvers)") == "Bounces against spin (two solvers)");
}

BOOST_AUTO_TEST_SUITE_END()
