#pragma once
// CPU time of the calling thread, for the cost half of every error-vs-cost statement.
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
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
  }
  double start_;
};

}  // namespace stoneskip
