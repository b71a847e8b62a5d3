// Oracle: the folder listing. A baseline kept in a folder of its own names its case beside it: the
// case is found there; a case found nowhere is named with every place looked in.
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "tools/io/atomic_file.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/scratch_dir.hpp"
#include "tools/scene/baseline_file.hpp"

namespace fs = std::filesystem;
using namespace stoneskip;

namespace {
// The spin_physical_realtime baseline as shipped on 5 December (its [result] damaged at known values
// below; the shipped one changes with the model).
constexpr const char* kFixture = "tools/scene/baseline_file_test_fixture.toml";

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
    BOOST_TEST(m.find("beside the baseline (" + fs::absolute(s.dir).string() + "), in the working directory") != std::string::npos, m);
    BOOST_TEST(m.find("case file 'nowhere.toml' not found beside the baseline") != std::string::npos, m);
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

BOOST_AUTO_TEST_CASE(a_copied_tree_runs_its_own_case_not_the_working_directorys) {
  // Oracle: the folder listing. A tree T/cases/baselines/B.toml naming "cases/spin_sweep_base.toml"
  // runs T/cases/spin_sweep_base.toml even where the working directory (here, the repository) has
  // a file of that name: it ran the repository's, so a changed case passed from there.
  ScratchDir s("stoneskip_baseline_tree");
  fs::create_directories(s.dir / "cases" / "baselines");
  s.write("cases/spin_sweep_base.toml", read_text_file("cases/spin_sweep_base.toml"));
  const fs::path b = baseline_naming(s, "cases/baselines/b.toml", "cases/baselines/spin_physical_realtime.toml",
                                     "cases/spin_sweep_base.toml");
  BOOST_REQUIRE(fs::exists("cases/spin_sweep_base.toml"));  // the working directory holds one too
  BOOST_TEST(fs::equivalent(resolve_case_file(read_baseline(b.string())), s.dir / "cases" / "spin_sweep_base.toml"));
}

BOOST_AUTO_TEST_CASE(a_file_without_a_baseline_table_says_so) {
  // Oracle: the file's text: an empty file, and a case file named by mistake, have no [baseline];
  // the line names the table and what a baseline file starts with (it said "baseline: missing key").
  ScratchDir s("stoneskip_baseline_no_table");
  for (const std::string& text : {std::string(), read_text_file("cases/paper_8ms_spin.toml")}) {
    std::string e;
    try {
      read_baseline(s.write("no_table.toml", text).string());
    } catch (const InputError& x) {
      e = x.what();
    }
    BOOST_TEST(e.find("baseline: missing table: a baseline file starts with [baseline]") != std::string::npos, e);
  }
}

BOOST_AUTO_TEST_CASE(a_damaged_result_is_bad_input_naming_its_key) {
  // Oracle: the 5 December baseline (kFixture: grid 0–60 rev/s, threshold_tolerance 0.5) with one [result]
  // line damaged. These were reported as regressions of the code (exit 1) after the whole sweep.
  ScratchDir s("stoneskip_baseline_damaged");
  const std::string text = read_text_file(kFixture);
  auto refusal = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    const auto at = t.find(from);
    BOOST_REQUIRE(at != std::string::npos);
    const fs::path f = s.write("damaged.toml", t.replace(at, from.size(), to));
    try {
      read_baseline(f.string());
      return std::string();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
  };
  std::string m = refusal("threshold_lo = [14.375", "threshold_lo = [1400.375");  // and hi below lo
  BOOST_TEST(m.find("result.threshold_hi") != std::string::npos, m);
  m = refusal("threshold_lo = [14.375", "threshold_lo = [-1.375");
  BOOST_TEST(m.find("result.threshold_lo") != std::string::npos, m);
  BOOST_TEST(m.find("outside the grid [0, 60]") != std::string::npos, m);
  m = refusal("threshold_hi = [14.6875, 22.8125, 34.6875, 48.4375, 50.9375]",
              "threshold_hi = [14.6875, 22.8125, 34.6875, 48.4375, 60.9375]");  // the last ends past 60
  BOOST_TEST(m.find("result.threshold_hi: threshold 5 [50.625, 60.9375] lies outside the grid [0, 60]") != std::string::npos, m);
  m = refusal("threshold_count_above = [3", "threshold_count_above = [1");
  BOOST_TEST(m.find("changes nothing") != std::string::npos, m);
  m = refusal("threshold_lo = [14.375, 22.5", "threshold_lo = [22.5, 14.375");
  BOOST_TEST(m.find("result.threshold_") != std::string::npos, m);
  m = refusal("threshold_hi = [14.6875, 22.8125", "threshold_hi = [22.8125, 14.6875");
  BOOST_TEST(m.find("result.threshold_") != std::string::npos, m);
  m = refusal("threshold_lo = [14.375, 22.5", "threshold_lo = [14.375, 14.5");  // starts inside the first
  BOOST_TEST(m.find("ascending order without overlap") != std::string::npos, m);
  BOOST_TEST(refusal("generated = ", "generated = ") == "");  // the undamaged file itself is taken
}

BOOST_AUTO_TEST_CASE(thresholds_that_do_not_answer_the_counts_are_bad_input) {
  // Oracle: the sweep's rule (bounce_sweep.cpp): each grid cell whose two counts differ, neither a
  // failure, is bisected once, inside the cell, the left count kept below. The 5 December baseline
  // (values 0, 10, …, 60; counts 1, 1, 2, 3, 4, 5, 9; one threshold in each of the five cells that
  // change; kFixture) with its [result] made to contradict itself; each was read and compared, and reported
  // as a regression of the code (exit 1) after the whole sweep.
  ScratchDir s("stoneskip_baseline_contradicts");
  const std::string text = read_text_file(kFixture);
  auto refusal = [&](const std::vector<std::pair<std::string, std::string>>& edits) {
    std::string t = text;
    for (const auto& [from, to] : edits) {
      const auto at = t.find(from);
      BOOST_REQUIRE(at != std::string::npos);
      t.replace(at, from.size(), to);
    }
    try {
      read_baseline(s.write("contradicts.toml", t).string());
      return std::string();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
  };
  // The count changes in [0, 10] now, where no threshold lies; the first lies in [10, 20].
  std::string m = refusal({{"counts = [1, 1,", "counts = [1, 2,"}});
  BOOST_TEST(m.find("result.threshold_lo: threshold 1 [14.375, 14.6875] should lie in [0, 10]") != std::string::npos, m);
  // The last cell no longer changes, but threshold 5 still lies in it.
  m = refusal({{"counts = [1, 1, 2, 3, 4, 5, 9]", "counts = [1, 1, 2, 3, 4, 5, 5]"}});
  BOOST_TEST(m.find("threshold 5 [50.625, 50.9375] lies in no grid cell where counts changes") != std::string::npos, m);
  // A count below a threshold that the grid does not have there.
  m = refusal({{"threshold_count_below = [1, 2, 3, 4, 5]", "threshold_count_below = [1, 2, 3, 4, 7]"}});
  BOOST_TEST(m.find("result.threshold_count_below: threshold 5 has 7 below it, but counts has 5 at 50") != std::string::npos, m);
  // The last threshold removed: the change from 5 to 9 in [50, 60] has none.
  m = refusal({{"threshold_lo = [14.375, 22.5, 34.375, 48.125, 50.625]", "threshold_lo = [14.375, 22.5, 34.375, 48.125]"},
                {"threshold_hi = [14.6875, 22.8125, 34.6875, 48.4375, 50.9375]", "threshold_hi = [14.6875, 22.8125, 34.6875, 48.4375]"},
                {"threshold_count_below = [1, 2, 3, 4, 5]", "threshold_count_below = [1, 2, 3, 4]"},
                {"threshold_count_above = [3, 5, 4, 5, 4]", "threshold_count_above = [3, 5, 4, 5]"}});
  BOOST_TEST(m.find("the counts change from 5 to 9 in [50, 60] but no threshold lies there") != std::string::npos, m);
  // A failed grid run (−1) is bisected on neither side: its neighbours' thresholds are then extra.
  m = refusal({{"counts = [1, 1, 2, 3, 4, 5, 9]", "counts = [1, 1, 2, 3, 4, -1, 9]"}});
  BOOST_TEST(m.find("threshold 4 [48.125, 48.4375] lies in no grid cell where counts changes") != std::string::npos, m);
}

BOOST_AUTO_TEST_CASE(ensembles_are_read_written_and_read_back_and_a_wrong_count_is_refused) {
  // Oracle: the shipped file's text (its first row, the 16 members at 0 rev/s, is all 1) and the
  // identity of a write and a read.
  ScratchDir s("stoneskip_baseline_ensembles");
  const BounceBaseline b = read_baseline("cases/baselines/spin_paper_realtime.toml");
  BOOST_TEST(b.ensemble_members == 16);
  BOOST_REQUIRE(b.ensembles.size() == b.values.size());
  BOOST_TEST((b.ensembles[0] == std::vector<int>(16, 1)));
  BounceSweepResult r;
  r.counts = b.counts;
  r.thresholds = b.thresholds;
  r.ensembles = b.ensembles;
  const fs::path again = s.write("again.toml", baseline_text(b, r, "test"));
  const BounceBaseline c = read_baseline(again.string());
  BOOST_TEST((c.ensembles == b.ensembles));
  BOOST_TEST(c.ensemble_members == 16);
  std::string text = read_text_file(again.string());
  const auto at = text.find("ensemble_members = 16");
  BOOST_REQUIRE(at != std::string::npos);
  const fs::path six = s.write("six.toml", text.replace(at, 21, "ensemble_members = 6"));
  try {
    read_baseline(six.string());
    BOOST_ERROR("144 counts were taken for 9 values of 6");
  } catch (const InputError& e) {
    const std::string m = e.what();
    BOOST_TEST(m.find("result.ensemble_counts") != std::string::npos, m);
    BOOST_TEST(m.find("54 in all (got 144)") != std::string::npos, m);
  }
}

BOOST_AUTO_TEST_CASE(a_baseline_written_before_ensembles_is_compared_on_single_runs) {
  // Oracle: the file's own keys. No ensemble_members and a [result] without ensemble_counts: 0
  // (it was refused, and `--update` would have replaced its golden counts); without [result], the
  // default (a new baseline gets ensembles when first written).
  ScratchDir s("stoneskip_baseline_old");
  std::string text = read_text_file("cases/baselines/spin_physical_realtime.toml");
  const auto m = text.find("ensemble_members = 16\n");
  BOOST_REQUIRE(m != std::string::npos);
  text.erase(m, 22);
  const auto e = text.find("ensemble_counts = [");
  BOOST_REQUIRE(e != std::string::npos);
  const fs::path old = s.write("old.toml", text.substr(0, e) + text.substr(text.find("]\n", e) + 2));
  BOOST_TEST(read_baseline(old.string()).ensemble_members == 0);
  const fs::path fresh = s.write("fresh.toml", text.substr(0, text.find("\n[result]") + 1));
  BOOST_TEST(read_baseline(fresh.string()).ensemble_members == kDefaultEnsembleMembers);
}

BOOST_AUTO_TEST_CASE(an_update_keeps_the_users_text_before_result_and_replaces_only_result) {
  // Oracle: the texts themselves. A user's comments, layout and a multi-line description holding a
  // line "[result]" survive `regress --update` byte for byte; the old [result] (and a comment after
  // it) is gone; the file reads back with the new run's counts. A file without [result] gets one
  // after its text.
  ScratchDir s("stoneskip_baseline_update");
  std::string text = read_text_file("cases/baselines/spin_physical_realtime.toml");
  const auto settings_end = text.find("\n[result]");
  BOOST_REQUIRE(settings_end != std::string::npos);
  std::string mine = text.substr(0, settings_end + 1);
  const auto d = mine.find("description = ");
  BOOST_REQUIRE(d != std::string::npos);
  mine.replace(d, mine.find('\n', d) - d, "description = \"\"\"\nmy notes\n[result]\nstill the description\"\"\"");
  mine.insert(mine.find("[baseline]"), "# my own comment, kept\n");
  mine += "  # indented comment before the table\n";
  const std::string old_result = text.substr(settings_end + 1) + "# a comment after the old result\n";
  BounceSweepResult r;
  const BounceBaseline b = read_baseline("cases/baselines/spin_physical_realtime.toml");
  r.counts = std::vector<int>(b.values.size(), 1);  // no change over the grid: no thresholds
  r.ensembles = std::vector<std::vector<int>>(b.values.size(), std::vector<int>(b.ensemble_members, 1));
  const std::string updated = updated_baseline_text(mine + old_result, r, "test run");
  BOOST_TEST(updated.substr(0, mine.size()) == mine);
  BOOST_TEST(updated.substr(mine.size(), 9) == "[result]\n");
  BOOST_TEST(updated.find("a comment after the old result") == std::string::npos);
  BOOST_TEST(updated.find("test run") != std::string::npos);
  const BounceBaseline back = read_baseline(s.write("updated.toml", updated).string());
  BOOST_TEST((back.counts == r.counts));
  BOOST_TEST(back.thresholds.empty());
  BOOST_TEST(back.description.find("still the description") != std::string::npos);
  // Without [result]: the text, one blank line, the new [result].
  const std::string appended = updated_baseline_text(mine + "\n\n\n", r, "test run");
  BOOST_TEST(appended.substr(0, mine.size() + 1) == mine + "\n");
  BOOST_TEST(appended.substr(mine.size() + 1, 9) == "[result]\n");
  BOOST_TEST((read_baseline(s.write("appended.toml", appended).string()).counts == r.counts));
  // A file with CRLF line ends gets its new [result] with CRLF too: no bare LF in the whole text.
  std::string crlf;
  for (char ch : mine + old_result) {
    if (ch == '\n') crlf += '\r';
    crlf += ch;
  }
  const std::string updated_crlf = updated_baseline_text(crlf, r, "test run");
  bool bare_lf = false;
  for (std::size_t i = 0; i < updated_crlf.size(); ++i) bare_lf = bare_lf || (updated_crlf[i] == '\n' && (i == 0 || updated_crlf[i - 1] != '\r'));
  BOOST_TEST(!bare_lf);
  BOOST_TEST((read_baseline(s.write("crlf.toml", updated_crlf).string()).counts == r.counts));
}

BOOST_AUTO_TEST_CASE(a_baseline_in_a_folder_of_its_own_finds_its_case_beside_it_first) {
  // Oracle: the folder listing. T/a/b/base.toml naming "mycase.toml", which exists beside it and
  // at T/mycase.toml (two folders up): the one beside it, as the baseline is not in <T>/cases/baselines/.
  ScratchDir s("stoneskip_baseline_own_folder");
  fs::create_directories(s.dir / "a" / "b");
  s.write("mycase.toml", read_text_file("cases/studies/convergence_bounce.toml"));
  s.write("a/b/mycase.toml", read_text_file("cases/studies/convergence_bounce.toml"));
  const fs::path b = baseline_naming(s, "a/b/base.toml", "cases/baselines/spin_physical_realtime.toml", "mycase.toml");
  BOOST_TEST(fs::equivalent(resolve_case_file(read_baseline(b.string())), s.dir / "a" / "b" / "mycase.toml"));
}

BOOST_AUTO_TEST_SUITE_END()
