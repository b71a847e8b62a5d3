// End-to-end tests of the reports: `report waves --quick`, `report stones --quick` and
// `capture validate --out` run the built executable, then `report render` rebuilds the page from
// data.h5 alone.
#include <boost/test/unit_test.hpp>

#include <regex>
#include <set>

#include "tools/cli/test_support.hpp"
#include "tools/io/hdf5_file.hpp"
#include "verification/study/record.hpp"
#include "verification/study/verdict_rules.hpp"

namespace {

using stoneskip::Record;
using stoneskip::test::read_file;
using stoneskip::test::run_stoneskip;
using stoneskip::test::TempDir;
namespace fs = std::filesystem;

// Every verdict stored under r: (phrase, reason).
void stored_verdicts(const Record& r, std::set<std::pair<std::string, std::string>>& out) {
  if (r.has_text("rule") && r.has_text("verdict") && r.has_text("reason")) out.emplace(r.text("verdict"), r.text("reason"));
  for (const auto& c : r.child_names()) stored_verdicts(r.at(c), out);
}

// The checks every report must pass, on a report folder just written.
void check_report(const fs::path& dir) {
  const std::string index = read_file(dir / "index.md");
  const std::string page = read_file(dir / "index.html");
  BOOST_REQUIRE(!index.empty());
  BOOST_TEST(page.rfind("<!DOCTYPE html>", 0) == 0);  // the same page for the browser, beside it
  // 1. Every figure the page names exists (PNG and SVG), and nothing is left of the build.
  const std::regex figure(R"(\]\(figures/([a-z0-9_]+)\.png\))");
  int figures = 0;
  for (std::sregex_iterator it(index.begin(), index.end(), figure), end; it != end; ++it, ++figures) {
    const std::string name = (*it)[1];
    BOOST_TEST_CONTEXT("figure " << name) {
      BOOST_TEST(fs::file_size(dir / "figures" / (name + ".png")) > 0u);
      BOOST_TEST(fs::file_size(dir / "figures" / (name + ".svg")) > 0u);
    }
  }
  BOOST_TEST(figures > 0);
  BOOST_TEST(!fs::exists(fs::path(dir.string() + ".partial")));
  BOOST_TEST(!fs::exists(dir / "sections"));

  // 2. No stored verdict contradicts its own rule applied to its stored inputs, and every verdict
  //    the page states ("**phrase** — reason") is one of the stored ones, word for word.
  stoneskip::Hdf5Reader data(dir / "data.h5");
  const Record sections = stoneskip::load_record(data.root().open_group("sections"));
  const auto contradictions = stoneskip::contradicted_verdicts(sections);
  for (const auto& c : contradictions) BOOST_ERROR(c);
  std::set<std::pair<std::string, std::string>> stored;
  stored_verdicts(sections, stored);
  BOOST_TEST(stored.size() > 5u);
  std::set<std::string> phrases;
  for (const auto& [v, r] : stored) phrases.insert(v);
  const std::regex stated(R"(\*\*([^*]+)\*\* — ([^|\n]+?)(?= \||\.? *\n|$))");
  int checked = 0;
  for (std::sregex_iterator it(index.begin(), index.end(), stated), end; it != end; ++it) {
    const std::string phrase = (*it)[1];
    if (!phrases.count(phrase)) continue;  // bold text that is not a verdict
    std::string reason = (*it)[2];
    bool found = false;
    for (const auto& [v, r] : stored)
      if (v == phrase && (reason == r || reason + "." == r || reason.rfind(r, 0) == 0)) found = true;
    BOOST_TEST(found, "the page states '" << phrase << " — " << reason << "', which no stored verdict says");
    ++checked;
  }
  BOOST_TEST(checked > 5);

  // 3. The page is a function of data.h5: rendering it again gives the same bytes, in both forms.
  const auto r = run_stoneskip("report render " + dir.string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  BOOST_TEST(read_file(dir / "index.md") == index);
  BOOST_TEST(read_file(dir / "index.html") == page);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(report_command_)

BOOST_AUTO_TEST_CASE(waves_quick_report_is_a_function_of_its_data) {
  // Oracle: the report's own data — every figure it names is drawn, every verdict it states is
  // stored and agrees with its rule, and rendering data.h5 again reproduces index.md byte for byte.
  TempDir tmp("stoneskip-report-waves");
  const fs::path dir = tmp.path() / "waves";
  const auto r = run_stoneskip("report waves --quick --out " + dir.string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  check_report(dir);
}

BOOST_AUTO_TEST_CASE(stones_quick_report_is_a_function_of_its_data) {
  // Oracle: as for the waves report; and the validation's rows of the quick preset are there: a
  // column per law × distribution × attitude, the regimes, the sphere, each contact's energy
  // balance, the attitude figures at 10 and 65 rev/s, Bocquet's rows beside the model, the answer.
  TempDir tmp("stoneskip-report-stones");
  const fs::path dir = tmp.path() / "stones";
  const auto r = run_stoneskip("report stones --quick --out " + dir.string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  check_report(dir);
  const std::string index = read_file(dir / "index.md");
  for (const char* text : {"model: planing, uniform, held", "model: planing, savitsky_wagner, free", "Rosellini: surfing",
                           "Johnson & Reid: largest ricochet path angle of a sphere", "**Energy over each contact.**",
                           "### Model beside model (not scored)", "figures/attitude_regime_10.png",
                           "figures/attitude_regime_65.png", "* The answer: **"})
    BOOST_TEST(index.find(text) != std::string::npos, text);
}

BOOST_AUTO_TEST_CASE(scene_quick_report_is_a_function_of_its_data) {
  // Oracle: as for the waves report; and the still frames the page promises are drawn.
  TempDir tmp("stoneskip-report-scene");
  const fs::path dir = tmp.path() / "scene";
  const auto r = run_stoneskip("report scene --quick --out " + dir.string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  check_report(dir);
  BOOST_TEST(fs::file_size(dir / "figures" / "still_seed_8ms.png") > 0u);
}

BOOST_AUTO_TEST_CASE(captures_report_is_a_function_of_its_data) {
  // Oracle: as for the waves report — on three shipped captures (a WiiYourself! log with jitter and
  // clipping, a throw at the physical convention's first bounce, an unusable one) and a small
  // ensemble, each usable one also thrown into a small coupled scene: every capture has its
  // section and anchor, every figure is drawn (the scene's two among them), every verdict agrees
  // with its rule, and rendering data.h5 again reproduces index.md byte for byte.
  TempDir tmp("stoneskip-report-captures");
  const fs::path dir = tmp.path() / "captures";
  const auto r = run_stoneskip("capture validate cases/captures/skip_two_remotes_wiiyourself.csv "
                               "cases/captures/skip_threshold_14ms.log cases/captures/no_still_part.log --members 12 "
                               "--scene cases/captures/pond_two_way.toml --scene-set scene.duration_s=0.3 "
                               "--scene-set solver.t_max_s=0.3 --scene-set water.nx=80 --scene-set water.ny=40 "
                               "--scene-set water.cell_m=0.04 --out " +
                               dir.string());
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  check_report(dir);
  const std::string index = read_file(dir / "index.md");
  for (const char* key : {"skip_two_remotes_wiiyourself_csv", "skip_threshold_14ms_log", "no_still_part_log"}) {
    BOOST_TEST(index.find("<a id=\"" + std::string(key) + "\"></a>") != std::string::npos, key);
    BOOST_TEST(index.find("](#" + std::string(key) + ")") != std::string::npos, key);
  }
  BOOST_TEST(index.find("**unusable** — no still part") != std::string::npos);
  for (const char* key : {"skip_two_remotes_wiiyourself_csv", "skip_threshold_14ms_log"}) {
    BOOST_TEST(index.find("](figures/" + std::string(key) + "_scene_stone.png)") != std::string::npos, key);
    BOOST_TEST(index.find("](figures/" + std::string(key) + "_scene_waves.png)") != std::string::npos, key);
  }
  // A folder that is not a report is refused before any work (exit 2, nothing written into it).
  const fs::path other = tmp.path() / "other";
  fs::create_directories(other);
  { std::ofstream(other / "notes.txt") << "mine\n"; }
  const auto refused = run_stoneskip("capture validate cases/captures/gentle_sidearm.log --no-simulate --out " + other.string());
  BOOST_TEST(refused.status == 2, refused.out);
  BOOST_TEST(!fs::exists(other / "index.md"));
}

BOOST_AUTO_TEST_CASE(a_bad_study_file_fails_before_any_work_and_leaves_nothing) {
  // Oracle: the input rules — one line naming the file and key, exit 2, no folder.
  TempDir tmp("stoneskip-report-bad");
  const fs::path study = tmp.path() / "bad.toml";
  {
    std::ofstream f(study);
    f << "[study]\nkind = \"waves\"\npreset = \"x\"\n[convergence]\nspace_grid = [32, 64]\n";
  }
  const fs::path dir = tmp.path() / "out";
  const auto r = run_stoneskip("report waves --study " + study.string() + " --out " + dir.string());
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.out.find("convergence.space_grid") != std::string::npos, r.out);
  BOOST_TEST(!fs::exists(dir));
  BOOST_TEST(!fs::exists(fs::path(dir.string() + ".partial")));
}

BOOST_AUTO_TEST_CASE(render_refuses_a_folder_that_is_not_a_report) {
  // Oracle: the input rules — exit 2 and a line naming the file.
  TempDir tmp("stoneskip-render-bad");
  const auto r = run_stoneskip("report render " + tmp.path().string());
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.out.find("data.h5") != std::string::npos, r.out);
}

BOOST_AUTO_TEST_SUITE_END()
