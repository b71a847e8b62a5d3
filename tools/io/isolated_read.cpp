#include "tools/io/isolated_read.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <sstream>
#include <string>
#include <system_error>
#include <thread>

#include "tools/io/input_error.hpp"
#include "tools/io/signal_cleanup.hpp"

namespace stoneskip {

namespace {

double default_timeout_s(const std::filesystem::path& file) {
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(file, ec);
  return 10.0 + (ec ? 0.0 : static_cast<double>(bytes) / 10e6);
}

std::string seconds_text(double s) {
  std::ostringstream o;
  o.precision(3);
  o << s << " s";
  return o.str();
}

bool g_in_isolated_child = false;

// The child: quiet, killable, crashable; the read, then _exit (no atexit handlers, no destructors
// of the parent's objects: the HDF5 library's own cleanup would run on a copy of its state).
[[noreturn]] void child(const std::function<void(int)>& read, int out_fd) {
  g_in_isolated_child = true;
  // The default actions: a crash ends the child (no handler of the host's, a test framework's say,
  // turns it into an exception), and a signal to the process group ends it too.
  for (int s : {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) ::signal(s, SIG_DFL);
  const int null = ::open("/dev/null", O_RDWR);
  if (null >= 0) {
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
  }
  try {
    read(out_fd);
  } catch (...) {
    // An error the read reports: the caller's own read will report it in full.
  }
  ::_exit(0);
}

[[noreturn]] void refuse(const std::filesystem::path& file, const std::string& why) {
  throw_input_error(file.string(), 0, "", "is a damaged HDF5 file: " + why + "; nothing was written");
}

// Runs read in a child and waits for it, collecting what it writes to `in` (the pipe's read end,
// or -1 for none) up to max_output bytes; refuses the file as read_in_child_first says. nullopt
// where fork failed.
std::optional<std::string> run_child_or_skip(const std::filesystem::path& file, const std::function<void(int)>& read,
                                             int in, int out, std::size_t max_output,
                                             const IsolatedReadOptions& options) {
  const double timeout_s = options.timeout_s > 0 ? options.timeout_s : default_timeout_s(file);
  std::fflush(nullptr);  // nothing buffered is written twice
  const pid_t pid = ::fork();
  if (pid < 0) {
    if (in >= 0) ::close(in);
    if (out >= 0) ::close(out);
    return std::nullopt;
  }
  if (pid == 0) {
    if (in >= 0) ::close(in);
    child(read, out);
  }
  if (out >= 0) ::close(out);
  RegisteredChild reg;
  with_registry_lock([&] { reg = RegisteredChild(pid); });
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  const auto give_up = [&](const std::string& why) {
    ::kill(pid, SIGKILL);
    int ignored = 0;
    while (::waitpid(pid, &ignored, 0) < 0 && errno == EINTR) {
    }
    reg.release();
    if (in >= 0) ::close(in);
    refuse(file, why);
  };
  std::string output;
  // What the child writes, to its end (EOF: it has exited, or closed the pipe).
  while (in >= 0) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) give_up("reading it did not end within " + seconds_text(timeout_s) + " (the HDF5 library loops on it)");
    pollfd p{in, POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 100)));
    if (ready < 0 && errno != EINTR) break;
    if (ready <= 0) continue;
    char buf[65536];
    const ssize_t n = ::read(in, buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    if (output.size() + static_cast<std::size_t>(n) > max_output)
      give_up("its strings come to more than " + std::to_string(max_output) + " bytes");
    output.append(buf, static_cast<std::size_t>(n));
  }
  if (in >= 0) ::close(in);
  int status = 0;
  auto pause = std::chrono::microseconds(200);
  for (;;) {
    const pid_t w = ::waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    if (w < 0 && errno != EINTR) {
      reg.release();
      return output;  // reaped elsewhere: nothing to say
    }
    if (std::chrono::steady_clock::now() > deadline) {
      in = -1;
      give_up("reading it did not end within " + seconds_text(timeout_s) + " (the HDF5 library loops on it)");
    }
    std::this_thread::sleep_for(pause);
    if (pause < std::chrono::milliseconds(20)) pause *= 2;
  }
  reg.release();
  if (WIFSIGNALED(status)) {
    const int s = WTERMSIG(status);
    const char* name = ::sigabbrev_np(s);
    refuse(file, "reading it crashed the HDF5 library (signal " + std::to_string(s) +
                     (name ? std::string(", SIG") + name : std::string()) + ")");
  }
  // The child ends with _exit(0) whether its read succeeded or threw: any other status is an exit
  // from inside the library (a memory checker's report, an exit on a failed assertion), not an end.
  if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
    refuse(file, "reading it ended the reading process with exit status " + std::to_string(WEXITSTATUS(status)) +
                     " (inside the HDF5 library)");
  return output;
}

}  // namespace

bool in_isolated_child() { return g_in_isolated_child; }

void read_in_child_first(const std::filesystem::path& file, const std::function<void()>& read,
                         const IsolatedReadOptions& options) {
  // No pipe: the child's fate is all there is to read. A failed fork leaves the caller to read
  // unprotected, as before.
  run_child_or_skip(file, [&](int) { read(); }, -1, -1, 0, options);
}

std::optional<std::string> read_in_child_first(const std::filesystem::path& file,
                                               const std::function<void(int out_fd)>& read,
                                               std::size_t max_output_bytes, const IsolatedReadOptions& options) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) return std::nullopt;
  return run_child_or_skip(file, read, fds[0], fds[1], max_output_bytes, options);
}

}  // namespace stoneskip
