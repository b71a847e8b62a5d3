#pragma once
// What the end-to-end tests of the command share: running the built executable and reading files.
#include <sys/wait.h>

#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace stoneskip::test {

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

struct Ran {
  int status = -1;
  std::string out;
};

// Runs the executable with arguments (stderr folded into stdout, or dropped); its exit status.
inline Ran run_stoneskip(const std::string& args, bool keep_stderr = true) {
  Ran r;
  const std::string cmd = std::string(STONESKIP_EXE) + " " + args + (keep_stderr ? " 2>&1" : " 2>/dev/null");
  FILE* p = popen(cmd.c_str(), "r");
  if (!p) return r;
  std::array<char, 4096> buf{};
  while (std::fgets(buf.data(), buf.size(), p)) r.out += buf.data();
  const int st = pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}

// A run with stdout and stderr apart, its wall time, under a time limit (`timeout`: status 124
// when the command ran past it).
struct RanApart {
  int status = -1;
  std::string out, err;
  double wall_s = 0;
};

inline std::string read_file(const std::filesystem::path& p);

inline RanApart run_apart(const std::string& args, int timeout_s = 60) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("stoneskip_apart_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string cmd = "timeout " + std::to_string(timeout_s) + " " + std::string(STONESKIP_EXE) + " " + args + " >" +
                          (dir / "o").string() + " 2>" + (dir / "e").string();
  RanApart r;
  const auto t0 = std::chrono::steady_clock::now();
  const int raw = std::system(cmd.c_str());
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = read_file(dir / "o");
  r.err = read_file(dir / "e");
  std::filesystem::remove_all(dir);
  return r;
}

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
