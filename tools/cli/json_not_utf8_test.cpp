// --json answers stay JSON when the user's text is not UTF-8. Oracle: nlohmann::json parses the
// output (the offending bytes become U+FFFD), and the exit status is that of the same command on
// clean names (0) — never 3, which an exception from the JSON writer gave on main for a Latin-1
// column name and for a 0xFF byte in a file name.
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "tools/cli/test_support.hpp"

namespace fs = std::filesystem;
using stoneskip::test::read_file;
using stoneskip::test::run_stoneskip;

namespace {

struct Scratch : stoneskip::test::ScratchDir {
  Scratch() : ScratchDir("stoneskip_json_utf8") {}
};

void expect_json(const std::vector<std::string>& args) {
  const auto r = run_stoneskip(args, false);
  BOOST_TEST(r.status == 0, "exit " << r.status << ": " << r.out);
  BOOST_TEST(nlohmann::json::accept(r.out), r.out.substr(0, 300));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(json_not_utf8)

BOOST_AUTO_TEST_CASE(a_capture_with_a_latin1_column_name_or_file_name_gives_json) {
  Scratch s;
  // 1. A 0xFF byte in the file name (a copy of a shipped capture).
  const fs::path named = s.dir / "throw\xff.log";
  fs::copy_file("cases/captures/gentle_sidearm.log", named);
  expect_json({"capture", "validate", named.string(), "--json", "--no-simulate"});
  // 2. A Latin-1 column name ("Température", é = 0xE9), listed among the unrecognised columns.
  std::istringstream in(read_file("cases/captures/skip_two_remotes_wiiyourself.csv"));
  std::ofstream out(s.dir / "latin1.csv");
  bool header = true;
  for (std::string line; std::getline(in, line); header = false) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    out << line << (header ? ",Temp\xe9rature" : ",20") << "\n";
  }
  out.close();
  expect_json({"capture", "validate", (s.dir / "latin1.csv").string(), "--json", "--no-simulate"});
}

BOOST_AUTO_TEST_SUITE_END()
