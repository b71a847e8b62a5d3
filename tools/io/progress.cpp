#include "tools/io/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace stoneskip {

Progress::Progress(std::string label, std::size_t total)
    : label_(std::move(label)), total_(total), tty_(::isatty(STDERR_FILENO) != 0),
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
  int decile = total_ ? static_cast<int>(10 * k / total_) : 10;
  if (tty_) {
    if (now - last_print_ < std::chrono::milliseconds(100) && k < total_) return;
    last_print_ = now;
    std::fprintf(stderr, "\r%s: %zu/%zu (%.0f s%s)   ", label_.c_str(), k, total_, elapsed, left(k, elapsed).c_str());
  } else if (decile != last_decile_) {
    last_decile_ = decile;
    std::fprintf(stderr, "%s: %zu/%zu (%.0f s%s)\n", label_.c_str(), k, total_, elapsed, left(k, elapsed).c_str());
  }
  std::fflush(stderr);
}

void Progress::done() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (finished_) return;
  finished_ = true;
  if (tty_) std::fprintf(stderr, "\n");
}

}  // namespace stoneskip
