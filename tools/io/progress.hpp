#pragma once
// Progress for long runs: a single updating line on stderr when it is a terminal, a line per
// 10 % otherwise (so CI logs stay short), with the time left at the mean rate so far.
// Thread-safe: workers call tick().
#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

namespace stoneskip {

class Progress {
 public:
  Progress(std::string label, std::size_t total);
  ~Progress();
  void tick(std::size_t n = 1);
  void done();

 private:
  void print(std::size_t k);
  std::string left(std::size_t k, double elapsed_s) const;
  std::string label_;
  std::size_t total_;
  std::atomic<std::size_t> count_{0};
  std::mutex mutex_;
  bool tty_;
  bool finished_ = false;
  int last_decile_ = -1;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
};

}  // namespace stoneskip
