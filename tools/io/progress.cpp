#include "tools/io/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace stoneskip {

namespace {
constexpr auto kTerminalPeriod = std::chrono::milliseconds(100);
constexpr auto kLogPeriod = std::chrono::seconds(10);  // at least one line this often off a terminal

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}
// On a terminal the updating line is erased when its work ends (carriage return, erase line), so
// the results printed next on stdout do not land beside or below stale progress.
void clear_line(bool printed_on_terminal) {
  if (!printed_on_terminal) return;
  std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
}
}  // namespace

Progress::Progress(std::string label, std::size_t total, double quiet_s)
    : label_(std::move(label)), total_(total), quiet_s_(quiet_s), tty_(::isatty(STDERR_FILENO) != 0),
      start_(std::chrono::steady_clock::now()), last_print_(start_) {}

Progress::~Progress() { done(); }

void Progress::tick(std::size_t n) {
  std::size_t k = count_.fetch_add(n) + n;
  std::lock_guard<std::mutex> lock(mutex_);
  print(k);
}

// The time left at the mean rate so far: ", about N s left" (nothing before the first tick or at the end).
std::string Progress::left(std::size_t k, double elapsed_s) const {
  if (k == 0 || k >= total_) return "";
  char b[48];
  std::snprintf(b, sizeof b, ", about %.0f s left", elapsed_s / static_cast<double>(k) * static_cast<double>(total_ - k));
  return b;
}

void Progress::print(std::size_t k) {
  if (finished_) return;
  auto now = std::chrono::steady_clock::now();
  double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < quiet_s_) return;
  int decile = total_ ? static_cast<int>(10 * k / total_) : 10;
  if (tty_) {
    if (now - last_print_ < kTerminalPeriod && k < total_) return;
    std::fprintf(stderr, "\r%s: %zu/%zu (%.0f s%s)   ", label_.c_str(), k, total_, elapsed, left(k, elapsed).c_str());
  } else {
    if (decile == last_decile_ && now - last_print_ < kLogPeriod) return;
    last_decile_ = decile;
    std::fprintf(stderr, "%s: %zu/%zu (%.0f s%s)\n", label_.c_str(), k, total_, elapsed, left(k, elapsed).c_str());
  }
  last_print_ = now;
  printed_ = true;
  std::fflush(stderr);
}

void Progress::done() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (finished_) return;
  finished_ = true;
  clear_line(tty_ && printed_);
}

Heartbeat::Heartbeat(std::string label, std::function<std::string()> status, double quiet_s)
    : label_(std::move(label)), status_(std::move(status)), quiet_s_(quiet_s), tty_(::isatty(STDERR_FILENO) != 0),
      thread_([this] { loop(); }) {}

Heartbeat::~Heartbeat() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
  clear_line(tty_ && printed_);
}

void Heartbeat::loop() {
  const auto start = std::chrono::steady_clock::now();
  std::unique_lock<std::mutex> lock(mutex_);
  auto next = start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(quiet_s_));
  for (;;) {
    if (wake_.wait_until(lock, next, [this] { return stop_; })) return;
    const double elapsed = seconds_since(start);
    const std::string status = status_ ? status_() : std::string();
    if (tty_)
      std::fprintf(stderr, "\r%s: %.0f s (wall)%s%s   ", label_.c_str(), elapsed, status.empty() ? "" : ", ", status.c_str());
    else
      std::fprintf(stderr, "%s: %.0f s (wall)%s%s\n", label_.c_str(), elapsed, status.empty() ? "" : ", ", status.c_str());
    std::fflush(stderr);
    printed_ = true;
    next = std::chrono::steady_clock::now() + (tty_ ? std::chrono::steady_clock::duration(std::chrono::seconds(1))
                                                     : std::chrono::steady_clock::duration(kLogPeriod));
  }
}

}  // namespace stoneskip
