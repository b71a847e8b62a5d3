// SIGINT and SIGTERM at random moments: main left partial report and
// capture folders (a data.h5 and figures without index.md, or an empty folder) and `run --out big.h5` left
// big.h5.tmp-PID. Oracle: the folder afterwards. A command stopped by the signal exits 128 +
// signal and leaves nothing partial there (tools/io/signal_cleanup.hpp: every temporary is
// registered and removed), only a report's work folder once it holds finished sections, which the
// same command then resumes; one that finished first exits 0 and leaves exactly the finished output. The moments are drawn from a seeded generator (the seed is printed) over the
// command's own measured duration, so every phase — sections, data.h5, figures, the final
// rename — gets hit across runs.
#include <boost/test/unit_test.hpp>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace fs = std::filesystem;

namespace {

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("stoneskip_signal_" + std::to_string(::getpid()));
  fs::path out = dir / "out";  // what the commands write into: nothing else lives here
  Scratch() {
    fs::remove_all(dir);
    fs::create_directories(out);
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

// Starts the executable with stdout and stderr to files in `logs`.
pid_t start(const std::vector<std::string>& args, const fs::path& logs) {
  std::vector<std::string> all = {STONESKIP_EXE};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, (logs / "stdout").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 2, (logs / "stderr").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  BOOST_REQUIRE(rc == 0);
  return pid;
}

struct Ended {
  int status = -1;      // exit status, or -1 if killed
  double wall_s = 0;
};

Ended finish(pid_t pid, std::chrono::steady_clock::time_point t0) {
  int raw = 0;
  ::waitpid(pid, &raw, 0);
  Ended e;
  e.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  e.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return e;
}

// Whether the process catches `sig` yet (Linux: the SigCgt mask of /proc/PID/status), or has
// ended (a zombie, or gone): then waiting longer is pointless.
bool catches_or_ended(pid_t pid, int sig) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  if (!status) return true;
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("State:", 0) == 0 && line.find('Z') != std::string::npos) return true;
    if (line.rfind("SigCgt:", 0) == 0) {
      const unsigned long long mask = std::stoull(line.substr(7), nullptr, 16);
      return (mask >> (sig - 1)) & 1ULL;
    }
  }
  return true;
}

// Runs the command, sends `sig` `delay_s` after the start (if it is still running), and returns
// how it ended. The signal is held back until stoneskip has installed its handler, the first thing
// main does: before that the dynamic loader is still mapping the libraries (tens of milliseconds on
// a loaded 2-core machine), nothing can have been written, and the default action of the signal,
// which no program can change before it runs, is what would be tested.
Ended interrupt(const std::vector<std::string>& args, const fs::path& logs, int sig, double delay_s) {
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = start(args, logs);
  const auto give_up = t0 + std::chrono::seconds(10);
  while (!catches_or_ended(pid, sig) && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  std::this_thread::sleep_until(t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                         std::chrono::duration<double>(delay_s)));
  ::kill(pid, sig);
  return finish(pid, t0);
}

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> n;
  for (const auto& e : fs::directory_iterator(dir)) n.push_back(e.path().filename().string());
  std::sort(n.begin(), n.end());
  return n;
}

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : " ") + x;
  return s;
}

// Exit 128 + sig and nothing left; or exit 0 and only the finished output.
void check_left(const Ended& e, int sig, const fs::path& out, const std::vector<std::string>& finished, const fs::path& logs) {
  const std::vector<std::string> left = names_in(out);
  std::ifstream err(logs / "stderr");
  const std::string stderr_text((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
  BOOST_TEST_MESSAGE("  exit " << e.status << " after " << e.wall_s << " s");
  BOOST_TEST((e.status == 128 + sig || e.status == 0), "exit " << e.status << "; stderr: " << stderr_text);
  if (e.status == 128 + sig) {
    // A signal that lands after the output was renamed into place (and before exit) leaves the
    // finished output, which is kept work, never a partial file.
    BOOST_TEST((left.empty() || joined(left) == joined(finished)), "left behind: " << joined(left));
    BOOST_TEST(stderr_text.find("interrupted by") != std::string::npos, stderr_text);
  } else {
    BOOST_TEST(joined(left) == joined(finished), "left: " << joined(left));
  }
}

// A report build stopped by the signal may also keep its work folder "<name>.partial", once it
// holds finished sections (reports/common/report_build.hpp): then it holds whole section files and
// no temporary, and stderr says where. Returns whether it was kept.
bool check_report_left(const Ended& e, int sig, const fs::path& out, const std::string& name, const fs::path& logs) {
  const fs::path partial = out / (name + ".partial");
  if (e.status != 128 + sig || !fs::exists(partial)) {
    check_left(e, sig, out, {name}, logs);
    return false;
  }
  std::ifstream err(logs / "stderr");
  const std::string stderr_text((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
  BOOST_TEST(joined(names_in(out)) == name + ".partial");
  BOOST_TEST(stderr_text.find("finished sections kept in " + partial.string()) != std::string::npos, stderr_text);
  BOOST_TEST(!fs::is_empty(partial / "sections"));
  for (const auto& f : fs::recursive_directory_iterator(partial))
    BOOST_TEST(f.path().filename().string().find(".tmp-") == std::string::npos, "temporary left: " << f.path());
  return true;
}

unsigned seed() {
  const unsigned s = static_cast<unsigned>(std::chrono::system_clock::now().time_since_epoch().count() % 1000003);
  BOOST_TEST_MESSAGE("signal moments drawn with seed " << s);
  return s;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(signals)

BOOST_AUTO_TEST_CASE(an_interrupted_report_leaves_nothing_partial_and_keeps_its_finished_sections) {
  Scratch s;
  std::mt19937 rng(seed());
  // The whole run once: how long it takes here, and what a finished one leaves.
  const std::vector<std::string> waves = {"report", "waves", "--quick", "--out", (s.out / "waves").string()};
  const auto t0 = std::chrono::steady_clock::now();
  const Ended whole = finish(start(waves, s.dir), t0);
  BOOST_REQUIRE(whole.status == 0);
  BOOST_REQUIRE(joined(names_in(s.out)) == "waves");
  BOOST_TEST(joined(names_in(s.out / "waves")) == "data.h5 figures index.html index.md stoneskip-manifest.txt");
  fs::remove_all(s.out / "waves");
  std::uniform_real_distribution<double> moment(0.02, 1.05);
  for (int i = 0; i < 4; ++i) {
    const int sig = i % 2 ? SIGTERM : SIGINT;
    const double at = moment(rng) * whole.wall_s;
    BOOST_TEST_CONTEXT("report waves, " << (sig == SIGINT ? "SIGINT" : "SIGTERM") << " at " << at << " s of " << whole.wall_s) {
      const Ended e = interrupt(waves, s.dir, sig, at);
      if (check_report_left(e, sig, s.out, "waves", s.dir)) {
        // The same command resumes the kept sections and finishes.
        const Ended again = finish(start(waves, s.dir), std::chrono::steady_clock::now());
        std::ifstream out(s.dir / "stdout");
        const std::string said((std::istreambuf_iterator<char>(out)), std::istreambuf_iterator<char>());
        BOOST_TEST(again.status == 0);
        BOOST_TEST(said.find("resumed from an earlier run") != std::string::npos, said);
        BOOST_TEST(joined(names_in(s.out)) == "waves");
      }
      if (fs::exists(s.out / "waves"))
        BOOST_TEST(joined(names_in(s.out / "waves")) == "data.h5 figures index.html index.md stoneskip-manifest.txt");
      fs::remove_all(s.out / "waves");
    }
  }
  // The stones report runs its sections on two worker threads: stopped while they work.
  const std::vector<std::string> stones = {"report", "stones", "--quick", "--workers", "2", "--out", (s.out / "stones").string()};
  std::uniform_real_distribution<double> early(0.3, 6.0);
  for (int sig : {SIGTERM, SIGINT}) {
    const double at = early(rng);
    BOOST_TEST_CONTEXT("report stones, signal " << sig << " at " << at << " s") {
      check_report_left(interrupt(stones, s.dir, sig, at), sig, s.out, "stones", s.dir);
      fs::remove_all(s.out / "stones");
      fs::remove_all(s.out / "stones.partial");
    }
  }
}

BOOST_AUTO_TEST_CASE(an_interrupted_run_leaves_no_temporary_file) {
  // A throw that records 300 000 samples (a stone in free flight without gravity, 1 µs steps,
  // every step kept) and writes a 41 MB result file.
  Scratch s;
  const fs::path c = s.dir / "long.toml";
  std::ofstream(c) << R"([stone]
shape = "prism"
radius_m = 0.03
thickness_m = 0.008
density_kg_m3 = 2500.0
[environment]
gravity_m_s2 = 0.0
[throw]
speed_m_s = 8.0
path_angle_deg = 0.0
attack_angle_deg = 0.0
height_m = 1.0
[solver]
dt_s = 1.0e-6
contact_dt_s = 1.0e-6
t_max_s = 0.3
output_dt_s = 0.0
)";
  const std::vector<std::string> run = {"run", c.string(), "--out", (s.out / "big.h5").string()};
  const auto t0 = std::chrono::steady_clock::now();
  const Ended whole = finish(start(run, s.dir), t0);
  BOOST_REQUIRE(whole.status == 0);
  BOOST_REQUIRE(joined(names_in(s.out)) == "big.h5");
  fs::remove(s.out / "big.h5");
  std::mt19937 rng(seed());
  std::uniform_real_distribution<double> moment(0.02, 1.05);
  for (int i = 0; i < 6; ++i) {
    const int sig = i % 2 ? SIGINT : SIGTERM;
    const double at = moment(rng) * whole.wall_s;
    BOOST_TEST_CONTEXT("run --out, signal " << sig << " at " << at << " s of " << whole.wall_s) {
      check_left(interrupt(run, s.dir, sig, at), sig, s.out, {"big.h5"}, s.dir);
      fs::remove(s.out / "big.h5");
    }
  }
}

BOOST_AUTO_TEST_CASE(an_interrupted_capture_validation_leaves_no_folder) {
  // main left a data.h5 and figures without index.md, or an empty folder (item 8).
  Scratch s;
  const std::vector<std::string> validate = {"capture", "validate", "cases/captures/gentle_sidearm.log",
                                             "cases/captures/lossy_sidearm.log", "--out", (s.out / "cv").string()};
  const auto t0 = std::chrono::steady_clock::now();
  const Ended whole = finish(start(validate, s.dir), t0);
  BOOST_REQUIRE(whole.status == 0);
  BOOST_REQUIRE(joined(names_in(s.out)) == "cv");
  fs::remove_all(s.out / "cv");
  std::mt19937 rng(seed());
  std::uniform_real_distribution<double> moment(0.02, 1.05);
  for (int i = 0; i < 3; ++i) {
    const int sig = i % 2 ? SIGINT : SIGTERM;
    const double at = moment(rng) * whole.wall_s;
    BOOST_TEST_CONTEXT("capture validate --out, signal " << sig << " at " << at << " s of " << whole.wall_s) {
      // Its sections are never resumed (tools/capture/README.md): nothing of them stays.
      check_left(interrupt(validate, s.dir, sig, at), sig, s.out, {"cv"}, s.dir);
      fs::remove_all(s.out / "cv");
    }
  }
}

BOOST_AUTO_TEST_CASE(a_movie_interrupted_while_gnuplot_draws_leaves_no_frames_and_no_gnuplot) {
  // main left the frames' temporary folder (91 MB) and an orphaned gnuplot drawing into it
  // Oracle: the temporary folder (TMPDIR is pointed at an empty scratch
  // folder for the command) and /proc: after exit 143 no folder is left there and no process has
  // its working folder inside it (gnuplot runs in the frames' folder).
  Scratch s;
  const fs::path tmp = s.dir / "tmp";
  fs::create_directories(tmp);
  const std::vector<std::string> movie = {"scene", "cases/scenes/seed_8ms.toml", "--set", "water.nx=60", "--set", "water.ny=60",
                                          "--set", "scene.duration_s=3", "--movie", (s.out / "m.mp4").string(),
                                          "--movie-size", "320x160"};
  const char* old_tmpdir = std::getenv("TMPDIR");
  const std::string saved = old_tmpdir ? old_tmpdir : "";
  ::setenv("TMPDIR", tmp.c_str(), 1);
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = start(movie, s.dir);
  if (old_tmpdir) ::setenv("TMPDIR", saved.c_str(), 1);
  else ::unsetenv("TMPDIR");
  // Wait until gnuplot has drawn its first frame in the frames' folder (or the command ended).
  auto drawing = [&] {
    for (const auto& d : fs::directory_iterator(tmp))
      if (fs::exists(d.path() / "seq_00001.png")) return true;  // the first picture drawn
    return false;
  };
  int raw = 0;
  bool ended = false;
  for (int i = 0; i < 1200 && !(ended = ::waitpid(pid, &raw, WNOHANG) == pid) && !drawing(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  BOOST_REQUIRE_MESSAGE(!ended, "the scene ended before gnuplot drew a frame");
  ::kill(pid, SIGTERM);
  const Ended e = finish(pid, t0);
  BOOST_TEST(e.status == 128 + SIGTERM);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  BOOST_TEST(fs::is_empty(tmp), "left behind in TMPDIR: " << joined(names_in(tmp)));
  BOOST_TEST(fs::is_empty(s.out), "left behind: " << joined(names_in(s.out)));
  const std::string inside = fs::canonical(tmp).string();
  for (const auto& p : fs::directory_iterator("/proc")) {
    std::error_code ec;
    const fs::path cwd = fs::read_symlink(p.path() / "cwd", ec);
    if (!ec) BOOST_TEST(cwd.string().rfind(inside, 0) != 0, "process " << p.path().filename().string() << " still works in " << cwd);
  }
}

BOOST_AUTO_TEST_CASE(an_interrupted_regress_keeps_the_line_it_printed_before_its_sweeps) {
  // Oracle: what regress had printed when the signal came. Its first line ("regress: N
  // baselines") is printed before the sweeps; with stdout a file, stdio holds it in a buffer that
  // the signal's exit does not flush, so it was lost. The signal is sent once stderr shows the
  // sweeps' progress, which comes after that line; the whole run takes about 30 s here.
  Scratch s;
  std::size_t baselines = 0;
  for (const auto& e : fs::directory_iterator("cases/baselines")) baselines += e.path().extension() == ".toml" ? 1 : 0;
  BOOST_REQUIRE(baselines > 1);
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = start({"regress"}, s.dir);
  const auto give_up = t0 + std::chrono::seconds(60);
  for (;;) {
    std::ifstream err(s.dir / "stderr");
    const std::string text((std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
    if (text.find("regress (") != std::string::npos || std::chrono::steady_clock::now() > give_up) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ::kill(pid, SIGINT);
  const Ended e = finish(pid, t0);
  BOOST_TEST(e.status == 128 + SIGINT);  // stopped in its sweeps, not finished
  std::ifstream out(s.dir / "stdout");
  const std::string text((std::istreambuf_iterator<char>(out)), std::istreambuf_iterator<char>());
  BOOST_TEST(text == "regress: " + std::to_string(baselines) + " baselines\n", "stdout: '" << text << "'");
}

BOOST_AUTO_TEST_SUITE_END()
