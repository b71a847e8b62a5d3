// Oracle: the folder listing. A baseline kept in a folder of its own names its case beside it: the
// case is found there; a case found nowhere is named with every place looked in.
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <string>

#include "tools/io/atomic_file.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/scratch_dir.hpp"
#include "tools/scene/baseline_file.hpp"

namespace fs = std::filesystem;
using namespace stoneskip;

namespace {
// The shipped baseline `shipped` with its `case = ...` line naming `case_file` instead, written to
// s.dir/name.
fs::path baseline_naming(const ScratchDir& s, const std::string& name, const std::string& shipped, const std::string& case_file) {
  std::string text = read_text_file(shipped);
  const auto at = text.find("\ncase = \"");
  BOOST_REQUIRE(at != std::string::npos);
  const auto end = text.find('\n', at + 1);
  return s.write(name, text.replace(at + 1, end - at - 1, "case = \"" + case_file + "\""));
}
}  // namespace

BOOST_AUTO_TEST_SUITE(baseline_file)

BOOST_AUTO_TEST_CASE(a_baseline_finds_its_case_beside_it_and_names_every_place_when_it_cannot) {
  ScratchDir s("stoneskip_baseline_beside");
  const std::string shipped = "cases/baselines/spin_physical_realtime.toml";
  s.write("mycase.toml", read_text_file("cases/studies/convergence_bounce.toml"));
  const fs::path found = baseline_naming(s, "found.toml", shipped, "mycase.toml");
  BOOST_TEST(fs::equivalent(resolve_case_file(read_baseline(found.string())), s.dir / "mycase.toml"));
  const fs::path lost = baseline_naming(s, "lost.toml", shipped, "nowhere.toml");
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
  std::string case_text = read_text_file("cases/spin_sweep_base.toml");
  const std::string env = "[environment]\nconvention = \"physical\"\n";
  const auto e = case_text.find(env);
  BOOST_REQUIRE(e != std::string::npos);
  case_text.replace(e, env.size(), env + "water_coefficient = 0.7\n");
  s.write("weak.toml", case_text);
  const fs::path paper = baseline_naming(s, "paper.toml", "cases/baselines/spin_paper_realtime.toml", "weak.toml");
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
