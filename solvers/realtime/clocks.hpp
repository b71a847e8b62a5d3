#pragma once
// The two clocks behind every cost figure, one helper for the whole project (STYLE.md: "CPU"
// means thread CPU time; wall-clock time is called wall):
//   CpuTimer  — CPU time of the calling thread (CLOCK_THREAD_CPUTIME_ID): what one solve or one
//               study step costs, unaffected by other threads or jobs sharing the cores;
//   WallTimer — elapsed wall-clock time (steady clock): what a user waits.
// It lives beside SolverStats (solvers/realtime/throw_result.hpp), the lowest file that both
// solvers share; verification and the command line include it from here.
#include <chrono>
#include <ctime>

namespace stoneskip {

class CpuTimer {
 public:
  CpuTimer() : start_(now()) {}
  double seconds() const { return now() - start_; }

 private:
  static double now() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  }
  double start_;
};

class WallTimer {
 public:
  WallTimer() : start_(std::chrono::steady_clock::now()) {}
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

 private:
  std::chrono::steady_clock::time_point start_;
};

}  // namespace stoneskip
