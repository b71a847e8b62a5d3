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

BOOST_AUTO_TEST_CASE(a_paper_baseline_refuses_a_case_whose_water_law_the_paper_would_replace) {
  // A paper baseline ran its case under the printed law (with_convention), so a case's own C_w of
  // 0.7 was replaced by 1 without a word. Oracle: the input rules, one error naming the baseline's
  // key and the case's.
  ScratchDir s("stoneskip_baseline_paper");
  std::string case_text = text_of("cases/spin_sweep_base.toml");
  const std::string env = "[environment]\nconvention = \"physical\"\n";
  const auto e = case_text.find(env);
  BOOST_REQUIRE(e != std::string::npos);
  case_text.replace(e, env.size(), env + "water_coefficient = 0.7\n");
  s.write("weak.toml", case_text);
  std::string baseline = text_of("cases/baselines/spin_paper_realtime.toml");
  const std::string shipped_case = "case = \"cases/spin_sweep_base.toml\"";
  const auto at = baseline.find(shipped_case);
  BOOST_REQUIRE(at != std::string::npos);
  const fs::path paper = s.write("paper.toml", std::string(baseline).replace(at, shipped_case.size(), "case = \"weak.toml\""));
  try {
    sweep_of(read_baseline(paper.string()));
    BOOST_ERROR("a case's C_w was replaced without a word");
  } catch (const InputError& x) {
    const std::string m = x.what();
    BOOST_TEST(m.find("baseline.convention: the case does not run in the paper convention") != std::string::npos, m);
    BOOST_TEST(m.find("water_coefficient") != std::string::npos, m);
  }
}

BOOST_AUTO_TEST_SUITE_END()
