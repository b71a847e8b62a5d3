// Output names that a shell would read as commands, given to every command that writes through an
// external program (gnuplot: `report render`, `capture validate --out`, `sweep-plot`; gnuplot and
// ffmpeg: `scene --movie`). Oracle: through a shell each name below runs `touch PWNED` (or is read
// by gnuplot/ffmpeg as an option); started with an argument vector it is only a name, so the one
// allowed outcomes are the named output written whole, or exit 2 with one line and nothing
// written — and no file named PWNED anywhere.
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "tools/cli/test_support.hpp"

namespace fs = std::filesystem;
using stoneskip::test::Args;

namespace {

// Single and double quotes around a command, a substitution, backticks, a newline, a leading '-'.
const std::vector<std::string> kNames = {"z'; touch PWNED; echo '", "q\"; touch PWNED; echo \"", "$(touch PWNED)",
                                         "`touch PWNED`", "a\nb", "-x"};

constexpr double kTimeout_s = 120;  // each command here takes seconds; a hang is a failure

struct Scratch : stoneskip::test::ScratchDir {
  Scratch() : ScratchDir("stoneskip_shell_names") {}
  std::set<std::string> entries() const {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
    return names;
  }
};

struct Ran {
  int status = -1;
  std::string out, err;
};

// The executable started in `dir` (so a relative name like "-x" is a name in it).
Ran run_in(const fs::path& dir, const Args& args) {
  stoneskip::SubprocessOptions o;
  o.working_dir = dir;
  o.timeout_s = kTimeout_s;
  const stoneskip::SubprocessResult p = stoneskip::run_program(stoneskip::test::stoneskip_argv(args), o);
  return {p.timed_out ? 124 : p.exit_status, p.out, p.err};
}

bool pwned_anywhere(const fs::path& dir) {
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename() == "PWNED") return true;
  return fs::exists(fs::current_path() / "PWNED") || fs::exists(fs::temp_directory_path() / "PWNED");
}

// The command either wrote `name` (and nothing else new in the folder) or was refused cleanly.
void expect_written_or_refused(const Scratch& s, const std::set<std::string>& before, const Ran& r, const std::string& name,
                               const std::string& what) {
  BOOST_TEST_CONTEXT(what << " '" << name << "'") {
    BOOST_TEST(!pwned_anywhere(s.dir));
    std::set<std::string> expected = before;
    if (r.status == 0) {
      expected.insert(name);
    } else {
      BOOST_TEST(r.status == 2, "exit " << r.status << ": " << r.err);
      BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1, r.err);
    }
    BOOST_TEST((s.entries() == expected), "exit " << r.status << ": " << r.err);
  }
}

int png_count(const fs::path& dir) {
  int n = 0;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir)) n += e.path().extension() == ".png";
  return n;
}

Args cat(Args a, const Args& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(shell_names)

BOOST_AUTO_TEST_CASE(capture_validate_and_report_render_draw_into_a_folder_of_any_name) {
  // Oracle: as above; the report folder holds index.md and its figures when written.
  Scratch s;
  const std::string capture = fs::absolute("cases/captures/gentle_sidearm.log").string();
  for (const auto& name : kNames) {
    const auto before = s.entries();
    const Ran made = run_in(s.dir, {"capture", "validate", capture, "--no-simulate", "--out=" + name});
    expect_written_or_refused(s, before, made, name, "capture validate --out");
    if (made.status != 0) continue;
    BOOST_TEST(fs::is_regular_file(s.dir / name / "index.md"), name);
    BOOST_TEST(png_count(s.dir / name / "figures") > 0, name);
    const Ran again = run_in(s.dir, {"report", "render", "--", name});  // "--": "-x" is the folder, not an option
    expect_written_or_refused(s, before, again, name, "report render");
  }
}

BOOST_AUTO_TEST_CASE(sweep_plot_writes_a_page_of_any_name) {
  // Oracle: as above; the page holds index.md when written.
  Scratch s;
  const std::string base = (fs::current_path() / "cases" / "paper_8ms_spin.toml").string();
  std::ofstream(s.dir / "small.toml") << "base = \"" + base +
                                             "\"\n[design]\nkind = \"grid\"\n[[vary]]\nkey = \"throw.speed_m_s\"\nfrom = 4.0\nto = "
                                             "14.0\ncount = 2\n[[vary]]\nkey = \"throw.spin_rev_s\"\nfrom = 0.0\nto = 40.0\ncount = 2\n";
  BOOST_REQUIRE(run_in(s.dir, {"sweep", "small.toml", "--quiet", "--out", "small.h5"}).status == 0);
  for (const auto& name : kNames) {
    const auto before = s.entries();
    const Ran r = run_in(s.dir, {"sweep-plot", "small.h5", "--out=" + name});
    expect_written_or_refused(s, before, r, name, "sweep-plot --out");
    if (r.status == 0) BOOST_TEST(fs::is_regular_file(s.dir / name / "index.md"), name);
  }
}

BOOST_AUTO_TEST_CASE(scene_movie_writes_a_movie_of_any_name) {
  // Oracle: as above; a written movie is a non-empty file (its frames are counted in
  // scene_command_test). "-y.mp4" given as a separate word is also only a name, or refused.
  Scratch s;
  const Args scene = {"scene",         fs::absolute("cases/scenes/seed_8ms.toml").string(),
                      "--set",         "water.nx=60",
                      "--set",         "water.ny=60",
                      "--set",         "water.origin_x_m=-0.1",
                      "--set",         "water.origin_y_m=-0.6",
                      "--set",         "scene.duration_s=0.05",
                      "--movie-size",  "320x160"};
  for (const auto& stem : kNames) {
    const std::string name = stem + ".mp4";
    const auto before = s.entries();
    const Ran r = run_in(s.dir, cat(scene, {"--movie=" + name}));
    expect_written_or_refused(s, before, r, name, "scene --movie");
    if (r.status == 0) BOOST_TEST(fs::file_size(s.dir / name) > 0u, name);
  }
  const auto before = s.entries();
  const Ran r = run_in(s.dir, cat(scene, {"--movie", "-y.mp4"}));
  expect_written_or_refused(s, before, r, "-y.mp4", "scene --movie -y.mp4");
}

BOOST_AUTO_TEST_SUITE_END()
