#include "tools/io/isolated_read.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

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

// The child: quiet, killable, crashable; the read, then _exit (no atexit handlers, no destructors
// of the parent's objects: the HDF5 library's own cleanup would run on a copy of its state).
[[noreturn]] void child(const std::function<void()>& read) {
  // The default actions: a crash ends the child (no handler of the host's, a test framework's say,
  // turns it into an exception), and a signal to the process group ends it too.
  for (int s : {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) ::signal(s, SIG_DFL);
  const int null = ::open("/dev/null", O_RDWR);
  if (null >= 0) {
    ::dup2(null, STDOUT_FILENO);
    ::dup2(null, STDERR_FILENO);
  }
  try {
    read();
  } catch (...) {
    // An error the read reports: the caller's own read will report it in full.
  }
  ::_exit(0);
}

}  // namespace

void read_in_child_first(const std::filesystem::path& file, const std::function<void()>& read,
                         const IsolatedReadOptions& options) {
  const double timeout_s = options.timeout_s > 0 ? options.timeout_s : default_timeout_s(file);
  std::fflush(nullptr);  // nothing buffered is written twice
  const pid_t pid = ::fork();
  if (pid < 0) return;  // no child: the caller reads unprotected, as without this check
  if (pid == 0) child(read);
  RegisteredChild reg;
  with_registry_lock([&] { reg = RegisteredChild(pid); });
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  int status = 0;
  auto pause = std::chrono::microseconds(200);
  for (;;) {
    const pid_t w = ::waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    if (w < 0 && errno != EINTR) return;  // reaped elsewhere: nothing to say
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      reg.release();
      throw_input_error(file.string(), 0, "",
                        "is a damaged HDF5 file: reading it did not end within " + seconds_text(timeout_s) +
                            " (the HDF5 library loops on it); nothing was written");
    }
    std::this_thread::sleep_for(pause);
    if (pause < std::chrono::milliseconds(20)) pause *= 2;
  }
  reg.release();
  if (WIFSIGNALED(status)) {
    const int s = WTERMSIG(status);
    const char* name = ::sigabbrev_np(s);
    throw_input_error(file.string(), 0, "",
                      "is a damaged HDF5 file: reading it crashed the HDF5 library (signal " + std::to_string(s) +
                          (name ? std::string(", SIG") + name : std::string()) + "); nothing was written");
  }
  // The child ends with _exit(0) whether its read succeeded or threw: any other status is an exit
  // from inside the library (a memory checker's report, an exit on a failed assertion), not an end.
  if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
    throw_input_error(file.string(), 0, "",
                      "is a damaged HDF5 file: reading it ended the reading process with exit status " +
                          std::to_string(WEXITSTATUS(status)) + " (inside the HDF5 library); nothing was written");
}

}  // namespace stoneskip
