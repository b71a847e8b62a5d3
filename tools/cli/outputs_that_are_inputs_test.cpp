// An output that is one of the command's inputs is refused before any work: exit 2, one line
// naming --out, and the input left byte for byte as it was. Oracle: on main each of these commands
// exited 0 having replaced its input with HDF5 or deleted it with the folder it replaced; the bytes
// of each input are read before the command and compared after.
#include <boost/test/unit_test.hpp>

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

struct Scratch : stoneskip::test::ScratchDir {
  Scratch() : ScratchDir("stoneskip_out_in") {}
};

void expect_refused_and_kept(const RanApart& r, const fs::path& input, const std::string& bytes, const std::string& why) {
  BOOST_TEST(r.status == 2, "exit " << r.status << ": " << r.err);
  BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1, r.err);
  BOOST_TEST(r.err.find("--out") != std::string::npos, r.err);
  BOOST_TEST(r.err.find(why) != std::string::npos, r.err);
  BOOST_TEST(r.out.empty(), r.out);
  BOOST_TEST(fs::is_regular_file(input));
  BOOST_TEST(read_file(input) == bytes, input);
}

std::string small_sweep(const fs::path& base) {
  return "base = \"" + base.string() +
         "\"\n[design]\nkind = \"grid\"\n[[vary]]\nkey = \"throw.speed_m_s\"\nfrom = 4.0\nto = 14.0\ncount = 2\n[[vary]]\n"
         "key = \"throw.spin_rev_s\"\nfrom = 0.0\nto = 40.0\ncount = 2\n";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(outputs_that_are_inputs)

BOOST_AUTO_TEST_CASE(run_refuses_to_write_over_its_case_however_it_is_spelt) {
  Scratch s;
  const fs::path c = s.write("case.toml", stoneskip::test::kGoodStoneCase);
  const std::string bytes = read_file(c);
  expect_refused_and_kept(run_apart({"run", c.string(), "--out", c.string()}), c, bytes, "is the input");
  expect_refused_and_kept(run_apart({"run", c.string(), "--out", (s.dir / "." / "case.toml").string()}), c, bytes, "is the input");
  fs::create_symlink(c, s.dir / "link.h5");
  expect_refused_and_kept(run_apart({"run", c.string(), "--out", (s.dir / "link.h5").string()}), c, bytes, "is the input");
}

BOOST_AUTO_TEST_CASE(sweep_refuses_to_write_over_its_sweep_file_or_base_case) {
  Scratch s;
  const fs::path base = s.write("base.toml", stoneskip::test::kGoodStoneCase);
  const fs::path x = s.write("x.toml", small_sweep(base));
  const std::string bytes = read_file(x), base_bytes = read_file(base);
  expect_refused_and_kept(run_apart({"sweep", x.string(), "--quiet", "--out", x.string()}), x, bytes, "is the input");
  expect_refused_and_kept(run_apart({"sweep", x.string(), "--quiet", "--out", base.string()}), base, base_bytes, "is the input");
  BOOST_TEST(!fs::exists(x.string() + ".journal"));
}

BOOST_AUTO_TEST_CASE(sweep_plot_refuses_a_folder_that_holds_its_result) {
  // sp1 also holds an index.md and a data.h5, so it looks like a page the command may replace:
  // only the input check stands between it and the deletion of sp1/results.h5.
  Scratch s;
  const fs::path x = s.write("x.toml", small_sweep(fs::current_path() / "cases" / "paper_8ms_spin.toml"));
  fs::create_directories(s.dir / "sp1");
  const fs::path results = s.dir / "sp1" / "results.h5";
  BOOST_REQUIRE(run_apart({"sweep", x.string(), "--quiet", "--out", results.string()}).status == 0);
  std::ofstream(s.dir / "sp1" / "index.md") << "# a page\n";
  std::ofstream(s.dir / "sp1" / "data.h5") << "not hdf5\n";
  const std::string bytes = read_file(results);
  expect_refused_and_kept(run_apart({"sweep-plot", results.string(), "--no-render", "--out", (s.dir / "sp1").string()}), results,
                          bytes, "holds the input");
  expect_refused_and_kept(run_apart({"sweep-plot", results.string(), "--no-render", "--out", s.dir.string()}), results, bytes,
                          "holds the input");
}

BOOST_AUTO_TEST_CASE(capture_validate_refuses_a_report_folder_that_holds_its_recording) {
  Scratch s;
  fs::create_directories(s.dir / "dir");
  const fs::path log = s.dir / "dir" / "my_throw.log";
  fs::copy_file("cases/captures/gentle_sidearm.log", log);
  const std::string bytes = read_file(log);
  expect_refused_and_kept(run_apart({"capture", "validate", log.string(), "--no-simulate", "--out", (s.dir / "dir").string()}),
                          log, bytes, "holds the input");
  // capture convert and capture throw: the same rule for a file output.
  expect_refused_and_kept(run_apart({"capture", "convert", log.string(), "--out", log.string()}), log, bytes, "is the input");
  expect_refused_and_kept(run_apart({"capture", "throw", log.string(), "--out", log.string()}), log, bytes, "is the input");
}

BOOST_AUTO_TEST_SUITE_END()
