// End-to-end tests of `stoneskip sweep` and `stoneskip sweep-plot`. Oracles: `stoneskip run` on the
// same overridden case (an independent path: the case text parsed with --set, a solve recording
// its trajectory, JSON out) for a throw's row; an uninterrupted run's table for a killed-and-
// resumed one and for runs on 1, 2 and 3 MPI ranks (bit for bit, every column but cost_*); the
// result table itself for the figures' data; the sweep file's text for bad-input messages.
#include <boost/test/unit_test.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>

#include "tools/cli/test_support.hpp"
#include "tools/io/hdf5_file.hpp"

namespace fs = std::filesystem;

namespace {

struct Outcome {
  int status = -1;
  std::string out, err;
};

fs::path work() {
  const fs::path d = fs::temp_directory_path() / ("stoneskip_sweep_cli_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

// The suite's files go when it ends.
struct RemoveScratch {
  ~RemoveScratch() {
    std::error_code ec;
    fs::remove_all(work(), ec);
  }
};

std::string text_of(const fs::path& p) {
  std::ifstream f(p);
  return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}

// Runs "PREFIX stoneskip ARGS" (plain words, no shell: test_support.hpp); PREFIX is an MPI
// launcher or empty.
Outcome command(const std::string& args, const std::string& prefix = "") {
  stoneskip::test::Args argv = stoneskip::test::words(prefix);
  for (const auto& a : stoneskip::test::stoneskip_argv(stoneskip::test::words(args))) argv.push_back(a);
  const stoneskip::SubprocessResult p = stoneskip::run_program(argv);
  return {p.exit_status, p.out, p.err};
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

// The shipped paper throw (physical convention: every throw sinks within about 0.1 s, so a throw
// costs milliseconds), cut at 2 s, with a cheaper reference.
const std::string kBaseSets = "--set solver.t_max_s=2.0 --set reference.rtol=1.0e-8";

std::string base_lines() {
  return "base = \"" + fs::absolute("cases/paper_8ms_spin.toml").string() +
         "\"\nset = [\"solver.t_max_s=2.0\", \"reference.rtol=1.0e-8\"]\n";
}

// A speeds × spins grid.
std::string grid_sweep(int speeds = 3, int spins = 3, const std::string& solvers = "[\"realtime\", \"reference\"]") {
  return base_lines() + "solvers = " + solvers + "\n[design]\nkind = \"grid\"\n[[vary]]\nkey = \"throw.speed_m_s\"\n" +
         "from = 6.0\nto = 10.0\ncount = " + std::to_string(speeds) + "\n[[vary]]\nkey = \"throw.spin_rev_s\"\nfrom = 0.0\n" +
         "to = 20.0\ncount = " + std::to_string(spins) + "\n";
}

fs::path setup(const std::string& name, const std::string& sweep_text) {
  const fs::path p = work() / (name + ".toml");
  write(p, sweep_text);
  return p;
}

stoneskip::Table table_of(const fs::path& h5) {
  stoneskip::Hdf5Reader r(h5);
  return r.root().read_table("throws");
}

double at(const stoneskip::Table& t, std::size_t row, const std::string& column) {
  for (std::size_t c = 0; c < t.columns.size(); ++c)
    if (t.columns[c] == column) return t.values[row * t.columns.size() + c];
  BOOST_FAIL("no column " << column);
  return 0;
}

// Bit-for-bit equality of every column that is not a cost_ column (NaN equal to the same NaN).
void expect_same_results(const stoneskip::Table& a, const stoneskip::Table& b, const std::string& what) {
  BOOST_REQUIRE(a.columns == b.columns);
  BOOST_REQUIRE_EQUAL(a.rows(), b.rows());
  std::size_t differ = 0, compared = 0;
  for (std::size_t c = 0; c < a.columns.size(); ++c) {
    if (a.columns[c].rfind("cost_", 0) == 0) continue;
    for (std::size_t r = 0; r < a.rows(); ++r) {
      const double x = a.values[r * a.columns.size() + c], y = b.values[r * b.columns.size() + c];
      ++compared;
      if (std::memcmp(&x, &y, sizeof x) != 0) {
        if (differ++ < 5) BOOST_ERROR(what << ": row " << r << " column " << a.columns[c] << ": " << x << " vs " << y);
      }
    }
  }
  BOOST_TEST(differ == 0u, what << ": " << differ << " of " << compared << " values differ");
}

// Exit 2, one line naming every fragment, no throw started, no result file (and no journal, unless
// one was there before: `had_journal`).
void expect_bad_input(const Outcome& r, const std::vector<std::string>& fragments, const fs::path& out,
                      bool had_journal = false) {
  BOOST_TEST(r.status == 2, "exit status " << r.status << ", stderr: " << r.err);
  BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1, "stderr must be one line: " << r.err);
  for (const auto& f : fragments) BOOST_TEST(r.err.find(f) != std::string::npos, "'" << f << "' not in: " << r.err);
  BOOST_TEST(!fs::exists(out), out << " was written");
  BOOST_TEST(fs::exists(fs::path(out.string() + ".journal")) == had_journal, "journal left or lost");
  BOOST_TEST(r.out.find("run ") == std::string::npos, "throws were started: " << r.out);
}

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  BOOST_REQUIRE(at != std::string::npos);
  return s.replace(at, from.size(), to);
}

std::string mpiexec() {
  const char* e = std::getenv("STONESKIP_MPIEXEC");
  return e && *e ? e : "mpirun";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(sweep_command, *boost::unit_test::fixture<RemoveScratch>())

BOOST_AUTO_TEST_CASE(a_throws_row_equals_stoneskip_run_on_the_same_overridden_case) {
  // Oracle: `stoneskip run BASE --set ... --solver both --json`, field by field, exactly.
  const fs::path sweep = setup("rows", grid_sweep()), out = work() / "rows.h5";
  const Outcome s = command("sweep " + sweep.string() + " --out " + out.string() + " --quiet");
  BOOST_REQUIRE_MESSAGE(s.status == 0, s.err);
  const stoneskip::Table t = table_of(out);
  BOOST_REQUIRE_EQUAL(t.rows(), 9u);
  for (std::size_t row : {0u, 4u, 8u}) {
    BOOST_TEST(at(t, row, "throw") == double(row));
    char set[256];
    std::snprintf(set, sizeof set, "--set throw.speed_m_s=%.17g --set throw.spin_rev_s=%.17g", at(t, row, "throw.speed_m_s"),
                  at(t, row, "throw.spin_rev_s"));
    const Outcome run = command("run cases/paper_8ms_spin.toml " + kBaseSets + " " + set + " --solver both --json");
    BOOST_REQUIRE_MESSAGE(run.status == 0, run.err);
    const nlohmann::json j = nlohmann::json::parse(run.out);
    for (const char* solver : {"realtime", "reference"}) {
      const nlohmann::json& r = j[solver];
      const std::string p = std::string(solver) + "_";
      BOOST_TEST(at(t, row, p + "bounces") == r["bounces"].get<double>());
      const std::string outcome = r["outcome"];
      BOOST_TEST(at(t, row, p + "outcome") == (outcome == "sank" ? 0 : outcome == "time_limit" ? 1 : 2));
      for (const char* f : {"distance_m", "lateral_m", "end_time_s", "max_energy_gain_J"})
        BOOST_TEST(at(t, row, p + f) == r[f].get<double>(), p + f);
      BOOST_TEST(at(t, row, p + "contacts") == double(r["contacts"].size()));
      BOOST_REQUIRE(!r["contacts"].empty());
      const nlohmann::json& c = r["contacts"][0];
      for (const char* f : {"start_s", "end_s", "entry_speed_m_s", "exit_speed_m_s", "entry_path_angle_deg", "entry_attack_angle_deg"})
        BOOST_TEST(at(t, row, p + "first_contact_" + f) == c[f].get<double>(), p + f);
      for (const char* f : {"steps", "contact_steps", "rhs_evaluations", "root_evaluations", "error_test_failures",
                            "nonlinear_iterations", "segments"})
        BOOST_TEST(at(t, row, p + f) == r["stats"][f].get<double>(), p + f);
    }
    BOOST_TEST(at(t, row, "disagreement_bounces") ==
               j["realtime"]["bounces"].get<double>() - j["reference"]["bounces"].get<double>());
  }
}

BOOST_AUTO_TEST_CASE(a_case_that_names_no_fixed_scheme_is_swept_with_the_adaptive_stepper) {
  // Oracle: `stoneskip run` on the same case with the adaptive stepper named explicitly (bs32 at
  // rtol = atol_m = 1e-9, the cases' default tolerance): the sweep's row must carry its counts of
  // work exactly (steps, right-hand sides, rejected trials: they differ between any two schemes or
  // tolerances), and must differ from the fixed stepper's.
  // The shipped case without the lines that would name a fixed stepper (if it still has them).
  std::istringstream lines(text_of("cases/paper_8ms_spin.toml"));
  std::string base, line;
  while (std::getline(lines, line))
    if (line.rfind("scheme", 0) != 0 && line.rfind("contact_dt_s", 0) != 0) base += line + "\n";
  const fs::path base_file = work() / "adaptive_base.toml";
  write(base_file, base);
  const std::string sweep_text = "base = \"" + base_file.string() + "\"\nset = [\"solver.t_max_s=2.0\"]\nsolvers = [\"realtime\"]\n" +
                                 "[design]\nkind = \"grid\"\n[[vary]]\nkey = \"throw.spin_rev_s\"\nfrom = 0.0\nto = 20.0\ncount = 2\n";
  const fs::path sweep = setup("adaptive", sweep_text), out = work() / "adaptive.h5";
  const Outcome s = command("sweep " + sweep.string() + " --out " + out.string() + " --quiet");
  BOOST_REQUIRE_MESSAGE(s.status == 0, s.err);
  const stoneskip::Table t = table_of(out);
  BOOST_REQUIRE_EQUAL(t.rows(), 2u);
  for (std::size_t row : {0u, 1u}) {
    char set[128];
    std::snprintf(set, sizeof set, " --set throw.spin_rev_s=%.17g", at(t, row, "throw.spin_rev_s"));
    const std::string args = "run cases/paper_8ms_spin.toml --set solver.t_max_s=2.0" + std::string(set) + " --solver realtime --json";
    const Outcome adaptive = command(args + " --set solver.scheme=bs32 --set solver.rtol=1e-9 --set solver.atol_m=1e-9");
    const Outcome fixed = command(args + " --set solver.scheme=semi_implicit_euler --set solver.dt_s=1e-3 --set solver.contact_dt_s=1e-5");
    BOOST_REQUIRE_MESSAGE(adaptive.status == 0 && fixed.status == 0, adaptive.err + fixed.err);
    const nlohmann::json a = nlohmann::json::parse(adaptive.out), f = nlohmann::json::parse(fixed.out);  // one solver: its result at the top
    for (const char* k : {"steps", "rhs_evaluations", "error_test_failures", "root_evaluations"})
      BOOST_TEST(at(t, row, std::string("realtime_") + k) == a["stats"][k].get<double>(), k);
    BOOST_TEST(at(t, row, "realtime_rhs_evaluations") != f["stats"]["rhs_evaluations"].get<double>());
    BOOST_TEST(at(t, row, "realtime_bounces") == a["bounces"].get<double>());
  }
  // A key both fixed by `set` and varied: the axis's values replace the fixed one, and a warning
  // says so, naming the [[vary]] key's line (oracle: the sweep file's text, line 7).
  const fs::path both = setup("both", replace(sweep_text, "\"solver.t_max_s=2.0\"", "\"solver.t_max_s=2.0\", \"throw.spin_rev_s=5\""));
  const fs::path both_out = work() / "both.h5";
  const Outcome w = command("sweep " + both.string() + " --out " + both_out.string() + " --quiet");
  BOOST_REQUIRE_MESSAGE(w.status == 0, w.err);
  BOOST_TEST(w.err.find("both.toml:7: vary[1].key: \"throw.spin_rev_s\" is also fixed by the top-level set "
                        "(\"throw.spin_rev_s=5\"): the axis's values replace it") != std::string::npos, w.err);
  const stoneskip::Table tb = table_of(both_out);
  BOOST_TEST(at(tb, 0, "throw.spin_rev_s") == 0.0);
  BOOST_TEST(at(tb, 1, "throw.spin_rev_s") == 20.0);
}

BOOST_AUTO_TEST_CASE(a_throw_whose_contacts_begin_off_a_walled_pond_has_runs_note_in_the_table) {
  // Oracle: `stoneskip run --json` on each throw's case (the same overridden scene case, solved
  // again): its note about contacts begun off the pond, word for word, is the sweep's note for that
  // throw, and a throw whose run has no such note has none. The seed's scene on a 2 m pond, 1 s,
  // at 4 and 12 m/s (paper convention, so the stone skips on): the pond at x in [-0.5, 1.48] m
  // holds the first landings; moved to x in [2, 3.98] m it holds none.
  const std::string scene = fs::absolute("cases/scenes/seed_8ms.toml").string();
  const std::string sets = "\"environment.convention=paper\", \"water.nx=100\", \"water.ny=100\", \"water.origin_y_m=-1.0\", "
                           "\"scene.duration_s=1.0\", \"solver.t_max_s=1.0\"";
  for (const char* origin_x : {"-0.5", "2.0"}) {
    const std::string sweep_text = "base = \"" + scene + "\"\nset = [" + sets + ", \"water.origin_x_m=" + origin_x +
                                   "\"]\nsolvers = [\"realtime\"]\n[design]\nkind = \"grid\"\n[[vary]]\nkey = \"throw.speed_m_s\"\n"
                                   "from = 4.0\nto = 12.0\ncount = 2\n";
    const fs::path sweep = setup(std::string("pond") + origin_x, sweep_text), out = work() / (std::string("pond") + origin_x + ".h5");
    const Outcome s = command("sweep " + sweep.string() + " --out " + out.string() + " --quiet");
    BOOST_REQUIRE_MESSAGE(s.status == 0, s.err);
    const stoneskip::Hdf5Reader r(out);
    const stoneskip::H5Group notes = r.root().open_group("notes");
    const std::vector<long long> ids = notes.read_ints("throw");
    const std::vector<std::string> solver = notes.read_strings("solver"), detail = notes.read_strings("detail");
    std::size_t off_pond_runs = 0;
    for (const double speed : {4.0, 12.0}) {
      const std::uint64_t index = speed == 4.0 ? 0 : 1;
      std::string args = "run " + scene + " --solver realtime --json --set throw.speed_m_s=" + std::to_string(speed);
      for (const char* k : {"environment.convention=paper", "water.nx=100", "water.ny=100", "water.origin_y_m=-1.0", "solver.t_max_s=1.0"})
        args += std::string(" --set ") + k;
      const Outcome run = command(args + " --set water.origin_x_m=" + origin_x);
      BOOST_REQUIRE_MESSAGE(run.status == 0, run.err);
      std::vector<std::string> expected;
      const nlohmann::json j = nlohmann::json::parse(run.out);
      for (const auto& n : j["notes"])
        if (n.get<std::string>().find("outside the pond") != std::string::npos) expected.push_back(n.get<std::string>());
      off_pond_runs += expected.empty() ? 0 : 1;
      std::vector<std::string> got;
      for (std::size_t k = 0; k < ids.size(); ++k)
        if (static_cast<std::uint64_t>(ids[k]) == index) {
          BOOST_TEST(solver[k] == "realtime");
          got.push_back(detail[k]);
        }
      BOOST_TEST(got == expected, "origin x " << origin_x << ", throw " << index << ": the sweep's notes\n  "
                                              << (got.empty() ? "(none)" : got[0]) << "\n`run`'s\n  "
                                              << (expected.empty() ? "(none)" : expected[0]));
    }
    // Moved off the landing, both throws' runs name contacts off the pond. Under it, the 12 m/s
    // throw's one contact (x ≈ 0.44 m) is on the pond and the 4 m/s throw's second (x ≈ 3.8 m,
    // 2.3 m past the rim) is not: a table with a note on one throw and none on the other.
    BOOST_TEST(off_pond_runs == (std::string(origin_x) == "2.0" ? 2u : 1u), "origin x " << origin_x);
    BOOST_TEST((s.out.find("with notes") != std::string::npos) == (off_pond_runs > 0), s.out);
  }
}

BOOST_AUTO_TEST_CASE(a_title_with_control_characters_is_printed_escaped) {
  // Oracle: printable_text's escapes. The sweep's configuration lines printed its title as written:
  // a bell and an escape sequence reached the terminal.
  const fs::path p = setup("ctrl", "title = \"s\\u0007w\\u001b[31m\"\n" + grid_sweep(2, 2, "[\"realtime\"]"));
  const Outcome r = command("sweep " + p.string() + " --out " + (work() / "ctrl.h5").string());
  BOOST_REQUIRE(r.status == 0);
  BOOST_TEST(r.out.find("sweep     s\\x07w\\x1B[31m (") != std::string::npos, r.out);
  BOOST_TEST(r.out.find('\a') == std::string::npos);
  BOOST_TEST(r.out.find('\x1b') == std::string::npos);
}

BOOST_AUTO_TEST_CASE(bad_sweep_files_fail_before_any_throw_with_one_line_and_no_output) {
  // Oracle: the line of the broken key in each file; no result file, no journal afterwards.
  setup("bad", grid_sweep());
  const fs::path out = work() / "bad.h5";
  struct Bad {
    std::string text, fragment;
  };
  const std::string g = grid_sweep();
  const std::vector<Bad> bad = {
      {g + "colour = \"red\"\n", "bad.toml:16: vary[2].colour: unknown key"},
      {replace(g, "throw.spin_rev_s", "stone.shape"), "bad.toml:12: vary[2].key: \"stone.shape\" is not a numeric key"},
      {replace(g, "count = 3\n[[vary]]", "count = 0\n[[vary]]"), "bad.toml:10: vary[1].count: must be >= 1"},
      {replace(g, "to = 20.0\ncount = 3", "to = 20.0\ncount = 3\nscale = \"log\""), "bad.toml:13: vary[2].from: a log axis needs from > 0"},
      {replace(g, "from = 6.0\nto = 10.0\ncount = 3", "from = 6.0\nto = 2.0\ncount = 3\nscale = \"log\""),
       "bad.toml:9: vary[1].to: from (6) must not exceed to (2)"},
      {replace(g, "paper_8ms_spin.toml", "no_such_case.toml"), "bad.toml:1: base: the base case does not load"},
  };
  for (const auto& b : bad) {
    write(work() / "bad.toml", b.text);
    expect_bad_input(command("sweep " + (work() / "bad.toml").string() + " --out " + out.string()), {b.fragment}, out);
  }
  write(work() / "bad.toml", g);
  // A bad option, not read as its default (−1 once meant "every core").
  expect_bad_input(command("sweep " + (work() / "bad.toml").string() + " --out " + out.string() + " --threads -1"),
                   {"--threads: must be in [0, 256] (got -1)"}, out);
  // A chunk beyond 64 bits was read as 2⁶⁴ − 1 without a word.
  expect_bad_input(command("sweep " + (work() / "bad.toml").string() + " --out " + out.string() +
                           " --max-chunk 99999999999999999999"),
                   {"--max-chunk"}, out);
  const fs::path nowhere = work() / "no_such_folder" / "x.h5";
  expect_bad_input(command("sweep " + (work() / "bad.toml").string() + " --out " + nowhere.string()),
                   {nowhere.string(), "does not exist"}, nowhere);
}

BOOST_AUTO_TEST_CASE(a_second_sweep_into_a_running_one_is_told_it_is_running) {
  // Oracle: the journal's writer holds flock(LOCK_EX) while it runs (verification/sweep/journal.cpp);
  // a lock taken here stands for it. A second sweep, with or without --resume, is refused (exit 2,
  // one line) saying a sweep is running, not that one was interrupted; the journal is left alone.
  const fs::path sweep = setup("live", grid_sweep(2, 2, "[\"realtime\"]"));
  const fs::path out = work() / "live.h5", journal = out.string() + ".journal";
  fs::remove(out);
  { std::ofstream(journal) << "a running sweep's journal"; }
  const int fd = ::open(journal.c_str(), O_RDONLY);
  BOOST_REQUIRE(fd >= 0);
  BOOST_REQUIRE(::flock(fd, LOCK_EX | LOCK_NB) == 0);
  for (const char* resume : {"", " --resume"})
    expect_bad_input(command("sweep " + sweep.string() + " --out " + out.string() + resume), {"another sweep is running"}, out, true);
  ::close(fd);
  fs::remove(journal);
}

BOOST_AUTO_TEST_CASE(a_journal_name_that_is_a_link_or_a_folder_is_refused_as_such_first) {
  // main: a link at the journal's name (to someone's file) was first called "the journal of an
  // interrupted sweep: finish it with --resume", which then refused it as a link; a dangling link
  // gave "cannot create the sweep journal: File exists". Oracle: only a regular file can be a
  // journal (journal.hpp); with or without --resume the line says what is there, and nothing is
  // written through the link or into the folder.
  const fs::path sweep = setup("linked", grid_sweep(2, 2, "[\"realtime\"]"));
  const fs::path out = work() / "linked.h5", journal = out.string() + ".journal";
  const fs::path someones = work() / "someones.txt";
  fs::remove(out);
  { std::ofstream(someones) << "someone's words"; }
  struct Case {
    const char* what;
    std::function<void()> make;
  };
  const std::vector<Case> cases = {
      {"a symbolic link", [&] { fs::create_symlink(someones, journal); }},
      {"a symbolic link", [&] { fs::create_symlink(work() / "nowhere", journal); }},
      {"a folder", [&] { fs::create_directory(journal); }},
  };
  for (const Case& c : cases) {
    for (const char* resume : {"", " --resume"}) {
      c.make();
      const Outcome r = command("sweep " + sweep.string() + " --out " + out.string() + resume);
      BOOST_TEST(r.status == 2, "exit status " << r.status << ", stderr: " << r.err);
      BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1, "stderr must be one line: " << r.err);
      BOOST_TEST(r.err.find(journal.string() + ": is " + c.what + ", not a sweep journal") != std::string::npos, r.err);
      BOOST_TEST(!fs::exists(out));
      fs::remove(journal);
    }
  }
  std::ifstream in(someones);
  std::string text;
  std::getline(in, text);
  BOOST_TEST(text == "someone's words");
  fs::remove(someones);
}

BOOST_AUTO_TEST_CASE(a_killed_sweep_resumes_to_the_same_table_computing_only_what_is_missing) {
  // Oracle: the same sweep run without interruption.
  const fs::path sweep = setup("kill", grid_sweep(8, 5, "[\"reference\"]"));
  const fs::path whole = work() / "whole.h5", killed = work() / "killed.h5";
  const fs::path journal = killed.string() + ".journal";
  BOOST_REQUIRE(command("sweep " + sweep.string() + " --out " + whole.string() + " --quiet").status == 0);

  // 1. Start, wait for rows in the journal, SIGKILL.
  fs::remove(killed);
  fs::remove(journal);
  std::fflush(nullptr);  // the child must not print this process's buffered output again
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    ::execl(STONESKIP_EXE, STONESKIP_EXE, "sweep", sweep.c_str(), "--out", killed.c_str(), "--threads", "1", "--max-chunk", "2",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  std::uintmax_t first = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (std::chrono::steady_clock::now() < deadline) {
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(journal, ec);
    if (!ec && size > 0 && first == 0) first = size;  // the header
    if (!ec && first > 0 && size > first) break;       // and at least one record of rows
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  BOOST_REQUIRE_MESSAGE(WIFSIGNALED(status), "the sweep ended before it could be killed");
  BOOST_REQUIRE(fs::exists(journal));
  BOOST_REQUIRE(!fs::exists(killed));
  // A write torn by the kill: garbage after the last whole record is cut on resume.
  std::ofstream(journal, std::ios::app | std::ios::binary) << "SWJ1\x02torn";

  // 2. Without --resume the journal is protected; with it, only the missing throws run.
  expect_bad_input(command("sweep " + sweep.string() + " --out " + killed.string()), {"--resume"}, killed, true);
  const Outcome resumed = command("sweep " + sweep.string() + " --out " + killed.string() + " --resume --quiet");
  BOOST_REQUIRE_MESSAGE(resumed.status == 0, resumed.err);
  BOOST_TEST(!fs::exists(journal));
  expect_same_results(table_of(whole), table_of(killed), "resumed");
  stoneskip::Hdf5Reader r(killed);
  const stoneskip::H5Group run = r.root().open_group("run");
  const long long recovered = run.attr_int("throws_recovered"), computed = run.attr_int("throws_computed");
  BOOST_TEST(recovered >= 1);
  BOOST_TEST(recovered + computed == 40);
  // Resuming a finished file computes nothing.
  const Outcome again = command("sweep " + sweep.string() + " --out " + killed.string() + " --resume");
  BOOST_TEST(again.status == 0);
  BOOST_TEST(again.out.find("already complete") != std::string::npos, again.out);
}

BOOST_AUTO_TEST_CASE(a_journal_with_no_finished_work_does_not_block_resume) {
  // Oracle: the same sweep run afresh (bit for bit), and cases/README.md — "with --resume and
  // nothing to resume the sweep starts afresh, so a batch script can always pass it". A journal
  // left empty or with its header cut short (a kill inside SweepJournal::create) holds no throw:
  // --resume replaces it with a warning, where main refused it ("no header record", exit 2).
  const fs::path sweep = setup("torn", grid_sweep(2, 2, "[\"reference\"]"));
  const fs::path whole = work() / "torn_whole.h5", out = work() / "torn.h5", journal = out.string() + ".journal";
  BOOST_REQUIRE(command("sweep " + sweep.string() + " --out " + whole.string() + " --quiet").status == 0);
  for (const std::string& torn : {std::string(), std::string("SWJ1\x01\0\0\0\x40", 9)}) {
    fs::remove(out);
    std::ofstream(journal, std::ios::binary | std::ios::trunc) << torn;
    const Outcome resumed = command("sweep " + sweep.string() + " --out " + out.string() + " --resume --quiet");
    BOOST_REQUIRE_MESSAGE(resumed.status == 0, resumed.err);
    BOOST_TEST(resumed.err.find("warning: " + journal.string() + ": holds no finished throw") != std::string::npos, resumed.err);
    BOOST_TEST(!fs::exists(journal));
    expect_same_results(table_of(whole), table_of(out), "afresh after a torn header");
  }
  // Nothing at all to resume from: started afresh as promised, and said (main was silent).
  fs::remove(out);
  const Outcome fresh = command("sweep " + sweep.string() + " --out " + out.string() + " --resume --quiet");
  BOOST_REQUIRE_MESSAGE(fresh.status == 0, fresh.err);
  BOOST_TEST(fresh.err.find("warning: " + journal.string() + ": no journal and no result to resume from: the sweep starts afresh") !=
                 std::string::npos,
             fresh.err);
  expect_same_results(table_of(whole), table_of(out), "afresh with nothing to resume");
  // A foreign file in the journal's place is still refused.
  fs::remove(out);
  std::ofstream(journal, std::ios::binary | std::ios::trunc) << "not a journal";
  expect_bad_input(command("sweep " + sweep.string() + " --out " + out.string() + " --resume"), {"not a sweep journal"}, out, true);
  fs::remove(journal);
}

// The offsets of the whole records of a sweep journal (verification/sweep/journal.cpp: a frame of
// magic, type, payload length and checksum, 24 bytes, then the payload).
std::vector<std::size_t> journal_records(const fs::path& journal) {
  const std::string b = text_of(journal);
  std::vector<std::size_t> at;
  for (std::size_t pos = 0; b.size() - pos >= 24;) {
    if (b.compare(pos, 4, "SWJ1") != 0) break;
    std::uint64_t len = 0;
    std::memcpy(&len, b.data() + pos + 8, 8);
    if (len > b.size() - pos - 24) break;
    at.push_back(pos);
    pos += 24 + len;
  }
  return at;
}

// Starts `stoneskip sweep SWEEP --out OUT`, waits until its journal holds rows (at least
// `records` whole records, the header included, when given), SIGKILLs it. True when it was killed
// with rows journalled and no result written.
bool killed_with_rows(const fs::path& sweep, const fs::path& out, std::size_t records = 0) {
  const fs::path journal = out.string() + ".journal";
  std::fflush(nullptr);  // the child must not print this process's buffered output again
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    ::execl(STONESKIP_EXE, STONESKIP_EXE, "sweep", sweep.c_str(), "--out", out.c_str(), "--threads", "1", "--max-chunk", "1",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  std::uintmax_t first = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(journal, ec);
    if (!ec && size > 0 && first == 0) first = size;
    if (!ec && first > 0 && size > first && (records == 0 || journal_records(journal).size() >= records)) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFSIGNALED(status) && fs::exists(journal) && !fs::exists(out);
}

BOOST_AUTO_TEST_CASE(a_flipped_byte_mid_journal_is_reported_and_stored_not_dropped_silently) {
  // Oracle: the same sweep run without interruption (bit for bit), and the journal's own framing:
  // one byte flipped inside the first record of rows breaks its checksum while whole records follow
  // it, so the resume must say so on stderr (naming the records dropped) and store the same line
  // in the result's /run journal_damage — not drop them silently as a torn tail is.
  const fs::path sweep = setup("flip", grid_sweep(12, 10, "[\"reference\"]"));
  const fs::path whole = work() / "flip_whole.h5", out = work() / "flip.h5", journal = out.string() + ".journal";
  BOOST_REQUIRE(command("sweep " + sweep.string() + " --out " + whole.string() + " --quiet").status == 0);
  BOOST_REQUIRE(killed_with_rows(sweep, out, 4));
  const std::vector<std::size_t> at = journal_records(journal);
  BOOST_REQUIRE(at.size() >= 4u);  // the header, the record to damage, and whole records after it
  std::string bytes = text_of(journal);
  bytes[at[1] + 24 + 3] ^= 0x40;  // inside the first rows record's payload
  std::ofstream(journal, std::ios::binary | std::ios::trunc) << bytes;
  const Outcome resumed = command("sweep " + sweep.string() + " --out " + out.string() + " --resume --quiet");
  BOOST_REQUIRE_MESSAGE(resumed.status == 0, resumed.err);
  const std::string dropped = std::to_string(at.size() - 2) + " whole records after it dropped";
  BOOST_TEST(resumed.err.find("warning: ") != std::string::npos, resumed.err);
  BOOST_TEST(resumed.err.find(dropped) != std::string::npos, resumed.err);
  expect_same_results(table_of(whole), table_of(out), "resumed after damage");
  stoneskip::Hdf5Reader r(out);
  const std::string stored = r.root().open_group("run").attr_string("journal_damage");
  BOOST_TEST(stored.find(dropped) != std::string::npos, stored);
  BOOST_TEST(r.root().open_group("run").attr_int("throws_recovered") == 0);  // only the header was before the damage
  stoneskip::Hdf5Reader clean(whole);
  BOOST_TEST(clean.root().open_group("run").attr_string("journal_damage").empty());
}

BOOST_AUTO_TEST_CASE(a_resume_after_the_mesh_was_edited_is_refused) {
  // Oracle: the rows depend on the OBJ mesh, so the journal's identity holds its content hash;
  // after an edit between the kill and --resume the resume is refused (exit 2, one line naming
  // the identity field), and so is a finished result taken as complete after such an edit.
  const fs::path mesh = work() / "stone.obj", base = work() / "mesh_case.toml";
  fs::copy_file("cases/hard/asymmetric_stone.obj", mesh, fs::copy_options::overwrite_existing);
  std::string base_text = text_of("cases/hard/tumbling_asymmetric.toml");
  const std::string key = "mesh_file = \"asymmetric_stone.obj\"";
  BOOST_REQUIRE(base_text.find(key) != std::string::npos);
  base_text.replace(base_text.find(key), key.size(), "mesh_file = \"stone.obj\"");
  write(base, base_text);
  const fs::path sweep = setup("mesh", "base = \"" + base.string() + "\"\nset = [\"solver.t_max_s=0.5\"]\n[design]\nkind = \"grid\"\n"
                                       "[[vary]]\nkey = \"throw.speed_m_s\"\nfrom = 6.0\nto = 10.0\ncount = 60\n");
  const fs::path out = work() / "mesh.h5";
  BOOST_REQUIRE(killed_with_rows(sweep, out));
  const std::string original = text_of(mesh);
  write(mesh, original + "# edited\n");
  const Outcome edited = command("sweep " + sweep.string() + " --out " + out.string() + " --resume --quiet");
  BOOST_TEST(edited.status == 2, edited.err);
  BOOST_TEST(edited.err.find("input_files") != std::string::npos, edited.err);
  BOOST_TEST(std::count(edited.err.begin(), edited.err.end(), '\n') == 1, edited.err);
  BOOST_TEST(!fs::exists(out));
  // With the mesh as it was, the same resume finishes; after an edit it is no longer complete.
  write(mesh, original);
  const Outcome resumed = command("sweep " + sweep.string() + " --out " + out.string() + " --resume --quiet");
  BOOST_REQUIRE_MESSAGE(resumed.status == 0, resumed.err);
  write(mesh, original + "# edited\n");
  const Outcome complete = command("sweep " + sweep.string() + " --out " + out.string() + " --resume");
  BOOST_TEST(complete.status == 2, complete.out << complete.err);
  BOOST_TEST(complete.out.find("already complete") == std::string::npos, complete.out);
}

BOOST_AUTO_TEST_CASE(sweep_plot_maps_hold_the_tables_counts) {
  // Oracle: the result table: a map cell's value is the bounce count of the throw at that grid
  // point; the disagreement cell is real-time minus reference; a histogram sums to the samples.
  const fs::path sweep = setup("plot", grid_sweep()), out = work() / "plot.h5", dir = work() / "plot";
  BOOST_REQUIRE(command("sweep " + sweep.string() + " --out " + out.string() + " --quiet").status == 0);
  const Outcome p = command("sweep-plot " + out.string() + " --out " + dir.string() + " --no-render");
  BOOST_REQUIRE_MESSAGE(p.status == 0, p.err);
  const stoneskip::Table t = table_of(out);
  stoneskip::Hdf5Reader figs(dir / "data.h5");
  const stoneskip::H5Group f = figs.root().open_group("figures");
  const stoneskip::Table cells = f.open_group("sweep_bounces_realtime_0_1").read_table("sweep_bounces_realtime_0_1_cells");
  const stoneskip::Table diff = f.open_group("sweep_disagreement_0_1").read_table("sweep_disagreement_0_1_cells");
  BOOST_REQUIRE_EQUAL(cells.rows(), 9u);
  for (std::size_t c = 0; c < cells.rows(); ++c) {
    for (std::size_t r = 0; r < t.rows(); ++r) {
      if (at(t, r, "throw.speed_m_s") != at(cells, c, "x") || at(t, r, "throw.spin_rev_s") != at(cells, c, "y")) continue;
      BOOST_TEST(at(cells, c, "value") == at(t, r, "realtime_bounces"));
      BOOST_TEST(at(diff, c, "value") == at(t, r, "realtime_bounces") - at(t, r, "reference_bounces"));
    }
  }
  BOOST_TEST(text_of(dir / "index.md").find("grid design, 9 throws") != std::string::npos);

  const fs::path lhs = setup("lhs", base_lines() + "[design]\nkind = \"latin_hypercube\"\nsamples = 12\nseed = 5\n"
                                    "[[vary]]\nkey = \"throw.attack_angle_deg\"\nfrom = 0.0\nto = 30.0\n"
                                    "[[vary]]\nkey = \"stone.radius_m\"\nfrom = 0.02\nto = 0.05\nscale = \"log\"\n");
  const fs::path lout = work() / "lhs.h5", ldir = work() / "lhs";
  BOOST_REQUIRE(command("sweep " + lhs.string() + " --out " + lout.string() + " --quiet").status == 0);
  BOOST_REQUIRE(command("sweep-plot " + lout.string() + " --out " + ldir.string() + " --no-render").status == 0);
  stoneskip::Hdf5Reader lf(ldir / "data.h5");
  const stoneskip::Table h = lf.root().open_group("figures").open_group("sweep_bounce_histogram").read_table("sweep_bounce_histogram_0");
  double throws = 0;
  for (double n : h.column("throws")) throws += n;
  BOOST_TEST(throws == 12);

  // `report render` of a sweep-plot folder said only "not the data file of a stoneskip report":
  // it now says what the folder is and how to redraw it (exit 2, one line naming the sweep).
  const Outcome render = command("report render " + ldir.string());
  BOOST_TEST(render.status == 2);
  BOOST_TEST(render.err.find("the data file of a `sweep-plot` folder, not of a report: redraw it with `stoneskip sweep-plot " +
                             lout.string()) != std::string::npos,
             render.err);
}

BOOST_AUTO_TEST_SUITE_END()

// Run by ctest as `stoneskip_sweep_mpi` with what Open MPI needs to run as root (tools/CMakeLists.txt).
BOOST_AUTO_TEST_SUITE(sweep_mpi, *boost::unit_test::disabled() * boost::unit_test::fixture<RemoveScratch>())

BOOST_AUTO_TEST_CASE(one_two_and_three_ranks_give_the_table_of_a_threaded_run) {
  // Oracle: the same sweep on threads in one process, bit for bit but the cost_ columns.
  const fs::path sweep = setup("mpi", grid_sweep(4, 3));
  const fs::path threads = work() / "threads.h5";
  BOOST_REQUIRE(command("sweep " + sweep.string() + " --out " + threads.string() + " --quiet").status == 0);
  const stoneskip::Table reference = table_of(threads);
  for (int n : {1, 2, 3}) {
    const fs::path out = work() / ("mpi" + std::to_string(n) + ".h5");
    const Outcome r = command("sweep " + sweep.string() + " --out " + out.string() + " --quiet --max-chunk 2",
                                mpiexec() + " --oversubscribe -n " + std::to_string(n));
    BOOST_REQUIRE_MESSAGE(r.status == 0, "mpirun -n " << n << ": " << r.err);
    const stoneskip::Table t = table_of(out);
    expect_same_results(reference, t, std::to_string(n) + " ranks");
    std::set<double> ranks;
    for (double v : t.column("cost_rank")) ranks.insert(v);
    if (n > 1) BOOST_TEST(ranks.size() >= 2u, n << " ranks: all throws ran on one rank");
  }
}

BOOST_AUTO_TEST_CASE(a_bad_sweep_file_under_mpirun_fails_on_every_rank_with_one_message) {
  // Oracle: the file's broken line; the message printed once, whatever the number of ranks.
  const fs::path sweep = setup("mpibad", replace(grid_sweep(), "count = 3\n[[vary]]", "count = -1\n[[vary]]"));
  const fs::path out = work() / "mpibad.h5";
  const Outcome r = command("sweep " + sweep.string() + " --out " + out.string(), mpiexec() + " --oversubscribe -n 2");
  BOOST_TEST(r.status == 2, r.err);
  const std::string m = "mpibad.toml:10: vary[1].count: must be >= 1";
  const auto first = r.err.find(m);
  BOOST_TEST(first != std::string::npos, r.err);
  BOOST_TEST(r.err.find(m, first + 1) == std::string::npos, "printed more than once: " << r.err);
  BOOST_TEST(!fs::exists(out));
}

BOOST_AUTO_TEST_SUITE_END()
