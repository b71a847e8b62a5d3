// End-to-end tests of `stoneskip regress`: the stored golden baselines (cases/baselines/*.toml)
// pass; a copy with its counts deliberately changed fails with exit status 1 and names the
// difference; bad input (missing file, misspelt key) exits 2 with a one-line message naming the
// file and key. Oracles: the stored baselines themselves (made by `regress --update`), and a
// perturbation that no correct run can reproduce (every count shifted by 7).
#include <boost/test/unit_test.hpp>

#include <cctype>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <system_error>

#include "tools/cli/test_support.hpp"

namespace fs = std::filesystem;

namespace {

struct Run {
  int status = -1;
  std::string out;
  std::string err;
};

fs::path scratch_path() { return fs::temp_directory_path() / ("stoneskip_regress_" + std::to_string(::getpid())); }

fs::path scratch_dir() {
  fs::create_directories(scratch_path());
  return scratch_path();
}

// The suite's copies go when it ends (they were left in TMP, one folder per run).
struct RemoveScratch {
  ~RemoveScratch() {
    std::error_code ec;
    fs::remove_all(scratch_path(), ec);
  }
};

std::string slurp(const fs::path& p) {
  std::ifstream f(p);
  return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

// Runs the executable on plain words (test_support.hpp), stdout and stderr apart.
Run run(const std::string& args) {
  const stoneskip::SubprocessResult p = stoneskip::run_program(stoneskip::test::stoneskip_argv(stoneskip::test::words(args)));
  return {p.exit_status, p.out, p.err};
}

// A copy of a stored baseline in a temporary folder, its case path made absolute (the tests run
// in the repository root, as ctest's WORKING_DIRECTORY), with `edit` applied to its text.
fs::path copy_baseline(const std::string& stored, const std::string& name,
                       const std::function<std::string(const std::string&)>& edit) {
  std::string text = slurp(stored);
  text = std::regex_replace(text, std::regex("case = \"cases/"), "case = \"" + (fs::current_path() / "cases").string() + "/");
  const fs::path out = scratch_dir() / name;
  std::ofstream(out) << edit(text);
  return out;
}

constexpr const char* kStored = "cases/baselines/spin_paper_realtime.toml";

}  // namespace

BOOST_AUTO_TEST_SUITE(regress_command, *boost::unit_test::fixture<RemoveScratch>())

BOOST_AUTO_TEST_CASE(stored_baselines_pass) {
  // Oracle: the stored curves, made by `stoneskip regress --update` from the same settings.
  const Run r = run("regress");
  BOOST_TEST_INFO("stdout:\n" << r.out << "\nstderr:\n" << r.err);
  BOOST_TEST(r.status == 0);
  BOOST_TEST(r.out.find(" 0 failed") != std::string::npos);
  BOOST_TEST(r.out.find("REGRESSION") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_baseline_with_changed_counts_fails_and_names_the_difference) {
  // Oracle: every stored count, single, ensemble and either side of a threshold, shifted by 7 (a
  // [result] that still answers its own counts: baseline_file.cpp refuses one that does not) — no
  // run of the stored settings can give all of them (the robust values' ensembles, without spread,
  // are compared exactly), and a grid spacing (5 rev/s) far wider than compare_tolerance leaves
  // values away from thresholds.
  BOOST_REQUIRE(fs::exists(kStored));
  const fs::path perturbed = copy_baseline(kStored, "perturbed.toml", [](const std::string& text) {
    std::string out = text;
    for (const std::string key : {"\ncounts", "\nthreshold_count_below", "\nthreshold_count_above"}) {
      const std::regex line(key + " = \\[([^\\]]*)\\]");
      std::smatch m;
      const std::string before = out;
      BOOST_REQUIRE(std::regex_search(before, m, line));
      std::stringstream in(m[1].str()), shifted;
      std::string item;
      bool first = true;
      while (std::getline(in, item, ',')) {
        shifted << (first ? "" : ", ") << std::stoi(item) + 7;
        first = false;
      }
      out = m.prefix().str() + key + " = [" + shifted.str() + "]" + m.suffix().str();
    }
    // The ensemble rows ("  1, 1, ..., 1,"), each count + 7.
    const std::size_t at = out.find("ensemble_counts = [");
    BOOST_REQUIRE(at != std::string::npos);
    const std::size_t from = out.find('\n', at) + 1, to = out.find(']', from);
    std::string rows = out.substr(from, to - from), shifted_rows;
    std::size_t k = 0;
    while (k < rows.size()) {
      if (std::isdigit(static_cast<unsigned char>(rows[k])) || rows[k] == '-') {
        std::size_t used = 0;
        shifted_rows += std::to_string(std::stoi(rows.substr(k), &used) + 7);
        k += used;
      } else {
        shifted_rows += rows[k++];
      }
    }
    return out.substr(0, from) + shifted_rows + out.substr(to);
  });
  const Run r = run("regress --baseline " + perturbed.string());
  BOOST_TEST_INFO("stdout:\n" << r.out << "\nstderr:\n" << r.err);
  BOOST_TEST(r.status == 1);
  BOOST_TEST(r.out.find("FAIL") != std::string::npos);
  BOOST_TEST(r.out.find("REGRESSION: count at spin_rev_s = ") != std::string::npos);
  BOOST_TEST(r.out.find("1 failed") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_moved_threshold_fails) {
  // Oracle: the first stored threshold moved by 6 compare tolerances; a correct run puts it back.
  BOOST_REQUIRE(fs::exists(kStored));
  const std::string text = slurp(kStored);
  if (text.find("threshold_lo = []") != std::string::npos) return;  // no threshold stored: nothing to move
  const fs::path moved = copy_baseline(kStored, "moved.toml", [](const std::string& t) {
    std::string out = t;
    for (const char* key : {"threshold_lo = [", "threshold_hi = ["}) {
      const std::size_t at = out.find(key);
      const std::size_t start = at + std::string(key).size();
      const std::size_t end = out.find_first_of(",]", start);
      // 6 × compare_tolerance 0.5, up, within its own cell [5, 10] (elsewhere it would answer no
      // change of the counts, or overlap the second threshold: bad input).
      const double v = std::stod(out.substr(start, end - start)) + 3.0;
      out = out.substr(0, start) + std::to_string(v) + out.substr(end);
    }
    return out;
  });
  const Run r = run("regress --baseline " + moved.string());
  BOOST_TEST_INFO("stdout:\n" << r.out << "\nstderr:\n" << r.err);
  BOOST_TEST(r.status == 1);
  BOOST_TEST(r.out.find("REGRESSION: threshold") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_result_without_the_ensembles_it_asks_for_is_bad_input_before_any_work) {
  // Oracle: the command-line contract. ensemble_members = 8 and no ensemble_counts: exit 2 naming
  // the key (a comparison on single runs would call a chaotic count's nudge a regression).
  BOOST_REQUIRE(fs::exists(kStored));
  const fs::path bare = copy_baseline(kStored, "bare.toml", [](const std::string& t) {
    const std::size_t at = t.find("ensemble_counts = [");
    BOOST_REQUIRE(at != std::string::npos);
    return t.substr(0, at) + t.substr(t.find("]\n", at) + 2);
  });
  const Run r = run("regress --baseline " + bare.string());
  BOOST_TEST_INFO("stdout:\n" << r.out << "\nstderr:\n" << r.err);
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.err.find("result.ensemble_counts: missing") != std::string::npos);
  BOOST_TEST(r.out.find("PASS") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_missing_baseline_file_is_bad_input) {
  // Oracle: the command-line contract (exit 2, one line naming the file).
  const Run r = run("regress --baseline /nonexistent/baseline.toml");
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.err.find("/nonexistent/baseline.toml") != std::string::npos);
  BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}

BOOST_AUTO_TEST_CASE(a_misspelt_key_is_bad_input_naming_the_key) {
  // Oracle: strict case files — an unknown key is an error naming it, never a silent default.
  BOOST_REQUIRE(fs::exists(kStored));
  const fs::path bad = copy_baseline(kStored, "misspelt.toml", [](const std::string& t) {
    return std::regex_replace(t, std::regex("compare_tolerance ="), "compare_tolerence =");
  });
  const Run r = run("regress --baseline " + bad.string());
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.err.find("compare_tolerence") != std::string::npos);
  BOOST_TEST(r.err.find(bad.string()) != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_zero_where_a_positive_setting_is_due_is_bad_input_not_the_case_s_value) {
  // Oracle: strict case files — a key written with a value out of its range is an error naming
  // it; only a key left out means "the case's". t_max_s = 0 once ran with the case's 10 s.
  BOOST_REQUIRE(fs::exists(kStored));
  for (const std::string key : {"t_max_s", "dt_s", "contact_dt_s"}) {
    const fs::path bad = copy_baseline(kStored, "zero_" + key + ".toml", [&](const std::string& t) {
      return std::regex_replace(t, std::regex("\ncompare_tolerance ="), "\n" + key + " = 0\ncompare_tolerance =");
    });
    const Run r = run("regress --baseline " + bad.string());
    BOOST_TEST(r.status == 2, key << ": exit " << r.status);
    BOOST_TEST(r.err.find(key) != std::string::npos, r.err);
  }
}

BOOST_AUTO_TEST_CASE(update_refuses_a_linked_baseline_before_any_work) {
  // Oracle: the output contract (a link is never written through) and "bad input before any
  // work": the refusal comes before the sweep starts, which prints its "regress: N baseline" line.
  const fs::path copy = copy_baseline(kStored, "linked_target.toml", [](const std::string& t) { return t; });
  const fs::path link = scratch_dir() / "linked.toml";
  fs::remove(link);
  fs::create_symlink(copy, link);
  const std::string before = slurp(copy);
  const Run r = run("regress --baseline " + link.string() + " --update");
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.err.find("symbolic link") != std::string::npos, r.err);
  BOOST_TEST(r.out.find("regress:") == std::string::npos, r.out);
  BOOST_TEST(slurp(copy) == before);
}

BOOST_AUTO_TEST_CASE(update_refuses_a_curve_of_which_every_throw_failed) {
  // Oracle: the update's rule (regress_command.cpp): a curve of failures only is not golden, since
  // every later run that failed alike would pass. The baseline's solver is CVODE, allowed one step
  // (reference.max_steps = 1, its documented minimum), so every throw fails; the file is left byte for
  // byte, the line says why, and the exit status is 1. A new baseline made from the stored one
  // (its [baseline] only; two grid values, single runs) keeps it quick.
  BOOST_REQUIRE(fs::exists(kStored));
  const fs::path one_step = scratch_dir() / "one_step.toml";
  std::ofstream(one_step) << slurp("cases/spin_sweep_base.toml") << "\n[reference]\nmax_steps = 1\n";
  const fs::path copy = copy_baseline(kStored, "all_failed.toml", [&](const std::string& t) {
    std::string out = std::regex_replace(t, std::regex("case = \"[^\"]*\""), "case = \"" + one_step.string() + "\"");
    out = std::regex_replace(out, std::regex("\nvalues = \\[[^\\]]*\\]"), "\nvalues = [0.0, 10.0]");
    out = std::regex_replace(out, std::regex("\nensemble_members = 16"), "\nensemble_members = 0");
    out = std::regex_replace(out, std::regex("\nsolver = \"realtime\""), "\nsolver = \"reference\"");
    return out.substr(0, out.find("\n[result]") + 1);  // a new baseline: no [result] yet
  });
  const std::string before = slurp(copy);
  const Run r = run("regress --baseline " + copy.string() + " --update");
  BOOST_TEST_INFO("stdout:\n" << r.out << "\nstderr:\n" << r.err);
  BOOST_TEST(r.status == 1);
  BOOST_TEST(r.out.find("NOT UPDATED  every grid value's throw failed") != std::string::npos);
  BOOST_TEST(r.out.find("0 baselines rewritten, 1 refused") != std::string::npos);
  BOOST_TEST(slurp(copy) == before);
}

BOOST_AUTO_TEST_CASE(a_case_on_live_water_is_refused_not_run_on_still_water) {
  // Main dropped the case's [water] and stored still-water counts for a swell (1, 1, 9 bounces,
  // where `stoneskip run` on the swell gives 0, 0, 0). Oracle: the input rules — exit 2, one line
  // naming the baseline, its key and the case, and no sweep started.
  BOOST_REQUIRE(fs::exists(kStored));
  const fs::path swell = fs::current_path() / "cases/scenes/swell_8ms.toml";
  BOOST_REQUIRE(fs::exists(swell));
  const fs::path bad = copy_baseline(kStored, "live_water.toml", [&](const std::string& t) {
    return std::regex_replace(t, std::regex("case = \"[^\"]*\""), "case = \"" + swell.string() + "\"");
  });
  const Run r = run("regress --baseline " + bad.string());
  BOOST_TEST(r.status == 2, r.err);
  BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1, r.err);
  BOOST_TEST(r.err.find("baseline.case") != std::string::npos, r.err);
  BOOST_TEST(r.err.find("has [water]") != std::string::npos, r.err);
  BOOST_TEST(r.out.find("regress:") == std::string::npos, r.out);
}

BOOST_AUTO_TEST_SUITE_END()
