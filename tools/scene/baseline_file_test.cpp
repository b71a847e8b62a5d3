// Oracle: the folder listing. A baseline kept in a folder of its own names its case beside it: the
// case is found there; a case found nowhere is named with every place looked in.
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tools/io/input_error.hpp"
#include "tools/io/scratch_dir.hpp"
#include "tools/scene/baseline_file.hpp"

namespace fs = std::filesystem;
using namespace stoneskip;

namespace {
std::string text_of(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

BOOST_AUTO_TEST_SUITE(baseline_file)

BOOST_AUTO_TEST_CASE(a_baseline_finds_its_case_beside_it_and_names_every_place_when_it_cannot) {
  ScratchDir s("stoneskip_baseline_beside");
  std::string baseline = text_of("cases/baselines/spin_physical_realtime.toml");
  const std::string shipped_case = "case = \"cases/studies/convergence_bounce.toml\"";
  const auto at = baseline.find(shipped_case);
  BOOST_REQUIRE(at != std::string::npos);
  s.write("mycase.toml", text_of("cases/studies/convergence_bounce.toml"));
  const fs::path found = s.write("found.toml", std::string(baseline).replace(at, shipped_case.size(), "case = \"mycase.toml\""));
  BOOST_TEST(fs::equivalent(resolve_case_file(read_baseline(found.string())), s.dir / "mycase.toml"));
  const fs::path lost = s.write("lost.toml", std::string(baseline).replace(at, shipped_case.size(), "case = \"nowhere.toml\""));
  try {
    resolve_case_file(read_baseline(lost.string()));
    BOOST_ERROR("a missing case was found");
  } catch (const InputError& e) {
    const std::string m = e.what();
    BOOST_TEST(m.find("case file 'nowhere.toml' not found in the working directory, beside the baseline (" +
                      fs::absolute(s.dir).string() + ")") != std::string::npos, m);
    BOOST_TEST(m.find("among the shipped files") != std::string::npos, m);
  }
}

BOOST_AUTO_TEST_SUITE_END()
