#pragma once
// Progress for long runs, on stderr (results go to stdout): a single updating line when it is a
// terminal, erased when the work ends so that it never stays between results; otherwise a
// line per 10 % and at least one every 10 s (so CI logs stay short but a long step still shows it
// is alive), with the time left at the mean rate so far. A Progress made with quiet_s > 0 prints
// nothing until that much wall time has passed, so short runs stay silent. Thread-safe: workers
// call tick().
//
// Heartbeat is for work of unknown length (one solve): after quiet_s, a line every second on a
// terminal (every 10 s otherwise) with the wall time elapsed and what status() says.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace stoneskip {

class Progress {
 public:
  Progress(std::string label, std::size_t total, double quiet_s = 0);
  ~Progress();
  void tick(std::size_t n = 1);
  void done();

 private:
  void print(std::size_t k);
  std::string left(std::size_t k, double elapsed_s) const;
  std::string label_;
  std::size_t total_;
  double quiet_s_;
  std::atomic<std::size_t> count_{0};
  std::mutex mutex_;
  bool tty_;
  bool finished_ = false;
  bool printed_ = false;
  int last_decile_ = -1;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
};

class Heartbeat {
 public:
  explicit Heartbeat(std::string label, std::function<std::string()> status = {}, double quiet_s = 2);
  ~Heartbeat();
  Heartbeat(const Heartbeat&) = delete;
  Heartbeat& operator=(const Heartbeat&) = delete;

 private:
  void loop();
  std::string label_;
  std::function<std::string()> status_;
  double quiet_s_;
  bool tty_;
  bool stop_ = false;
  bool printed_ = false;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread thread_;
};

}  // namespace stoneskip
