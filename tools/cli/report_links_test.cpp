// `report render DIR` never writes through a link or into a FIFO put in DIR/figures. Oracle: on
// main a symbolic link named like a figure made render overwrite the link's target and a FIFO made
// it hang; every figure is now written beside its name and renamed over it, and a name that is not
// a regular file is refused first — exit 2, one line naming the file, the target's bytes unchanged,
// the command ending well within its time limit.
#include <boost/test/unit_test.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "tools/cli/test_support.hpp"

namespace fs = std::filesystem;
using stoneskip::test::read_file;
using stoneskip::test::RanApart;
using stoneskip::test::run_apart;

namespace {

constexpr int kTimeout_s = 60;  // a render of this report takes seconds; a hang on a FIFO would not end

struct Report {
  fs::path dir = fs::temp_directory_path() / ("stoneskip_report_links_" + std::to_string(::getpid()));
  fs::path page = dir / "rep";
  Report() {
    fs::remove_all(dir);
    fs::create_directories(dir);
    const RanApart r = run_apart({"capture", "validate", "cases/captures/gentle_sidearm.log", "--no-simulate", "--out", page.string()});
    BOOST_REQUIRE_MESSAGE(r.status == 0, r.err);
  }
  ~Report() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  // A figure's file of the given extension, as drawn by the report.
  fs::path first(const std::string& ext) const {
    for (const auto& e : fs::directory_iterator(page / "figures"))
      if (e.path().extension() == ext) return e.path();
    BOOST_FAIL("no " + ext + " in " + (page / "figures").string());
    return {};
  }
};

void expect_refused(const RanApart& r, const fs::path& named, const std::string& what) {
  BOOST_TEST(r.status == 2, "exit " << r.status << ": " << r.err);
  BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1, r.err);
  BOOST_TEST(r.err.find(named.string()) != std::string::npos, r.err);
  BOOST_TEST(r.err.find(what) != std::string::npos, r.err);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(report_links)

BOOST_AUTO_TEST_CASE(a_link_named_like_a_figure_or_its_data_is_refused_and_its_target_kept) {
  Report rep;
  const fs::path victim = rep.dir / "victim.txt";
  std::ofstream(victim) << "mine\n";
  for (const std::string ext : {".png", ".svg", ".dat", ".gp"}) {
    const fs::path f = rep.first(ext);
    fs::remove(f);
    fs::create_symlink(victim, f);
    expect_refused(run_apart({"report", "render", rep.page.string()}, kTimeout_s), f, "a symbolic link");
    BOOST_TEST(read_file(victim) == "mine\n", ext);
    BOOST_TEST(fs::is_symlink(f), ext);
    fs::remove(f);  // the next extension's test starts from a clean figure folder
  }
  // With the links gone the page renders again (the figures redrawn, exit 0).
  BOOST_TEST(run_apart({"report", "render", rep.page.string()}, kTimeout_s).status == 0);
}

BOOST_AUTO_TEST_CASE(a_fifo_named_like_a_figure_is_refused_without_hanging) {
  Report rep;
  const fs::path f = rep.first(".png");
  fs::remove(f);
  BOOST_REQUIRE(::mkfifo(f.c_str(), 0644) == 0);
  const RanApart r = run_apart({"report", "render", rep.page.string()}, kTimeout_s);
  expect_refused(r, f, "a FIFO");
  BOOST_TEST(r.wall_s < kTimeout_s);
  BOOST_TEST(fs::is_fifo(f));
}

BOOST_AUTO_TEST_CASE(a_figures_folder_that_is_a_link_is_refused) {
  Report rep;
  const fs::path elsewhere = rep.dir / "elsewhere";
  fs::create_directories(elsewhere);
  fs::remove_all(rep.page / "figures");
  fs::create_directory_symlink(elsewhere, rep.page / "figures");
  expect_refused(run_apart({"report", "render", rep.page.string()}, kTimeout_s), rep.page / "figures", "a symbolic link");
  BOOST_TEST(fs::is_empty(elsewhere));
}

BOOST_AUTO_TEST_SUITE_END()
