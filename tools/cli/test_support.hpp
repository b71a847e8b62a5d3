#pragma once
// What the end-to-end tests of the command share: running the built executable and reading files.
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tools/io/scratch_dir.hpp"
#include "tools/io/subprocess.hpp"

namespace stoneskip::test {

// An empty folder under the temporary directory, named `stem`_<pid>, removed with the object.
using ScratchDir = stoneskip::ScratchDir;

// A good stone case: the paper's prism at 8 m/s with 10 rev/s of spin, 3 s.
inline constexpr const char* kGoodStoneCase = R"([stone]
shape = "prism"
radius_m = 0.03
thickness_m = 0.008
segments = 11
density_kg_m3 = 2500.0
[throw]
speed_m_s = 8.0
path_angle_deg = 10.0
attack_angle_deg = 10.0
spin_rev_s = 10.0
height_m = 0.1
[solver]
dt_s = 1.0e-3
contact_dt_s = 1.0e-5
t_max_s = 3.0
)";

// The executable's arguments, one string each: passed to it as they are (no shell reads them).
using Args = std::vector<std::string>;

// A command line of plain words ("run cases/x.toml --json") split at spaces, then `more` as they
// are; no quoting and no shell. An argument with a space or a quote in it, or an empty one, goes
// in `more` (or an Args) instead.
inline Args words(const std::string& line, const Args& more = {}) {
  Args a;
  std::istringstream in(line);
  for (std::string w; in >> w;) a.push_back(w);
  a.insert(a.end(), more.begin(), more.end());
  return a;
}

inline Args stoneskip_argv(const Args& args) {
  Args argv{STONESKIP_EXE};
  argv.insert(argv.end(), args.begin(), args.end());
  return argv;
}

struct Ran {
  int status = -1;
  std::string out;
};

// Runs the executable with arguments (stderr folded into stdout, or dropped); its exit status.
inline Ran run_stoneskip(const Args& args, bool keep_stderr = true) {
  SubprocessOptions o;
  o.stderr_to = keep_stderr ? SubprocessOptions::Stderr::merged : SubprocessOptions::Stderr::discarded;
  const SubprocessResult p = run_program(stoneskip_argv(args), o);
  return {p.exit_status, p.out};
}
inline Ran run_stoneskip(const std::string& line, bool keep_stderr = true) { return run_stoneskip(words(line), keep_stderr); }

// A run with stdout and stderr apart, its wall time, under a time limit (status 124, as
// timeout(1) gives, when the command ran past it).
struct RanApart {
  int status = -1;
  std::string out, err;
  double wall_s = 0;
};

inline RanApart run_apart(const Args& args, int timeout_s = 60) {
  SubprocessOptions o;
  o.timeout_s = timeout_s;
  RanApart r;
  const auto t0 = std::chrono::steady_clock::now();
  const SubprocessResult p = run_program(stoneskip_argv(args), o);
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.status = p.timed_out ? 124 : p.exit_status;
  r.out = p.out;
  r.err = p.err;
  return r;
}
inline RanApart run_apart(const std::string& line, int timeout_s = 60) { return run_apart(words(line), timeout_s); }

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// A fresh empty folder under the system's temporary folder, removed with the object.
class TempDir {
 public:
  explicit TempDir(const std::string& stem)
      : path_(std::filesystem::temp_directory_path() / (stem + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace stoneskip::test
