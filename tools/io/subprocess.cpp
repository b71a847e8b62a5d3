#include "tools/io/subprocess.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>

#include "tools/io/signal_cleanup.hpp"

extern char** environ;

namespace stoneskip {

namespace {

// A file descriptor closed with the object.
class Fd {
 public:
  Fd() = default;
  explicit Fd(int fd) : fd_(fd) {}
  ~Fd() { reset(); }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }
  void reset(int fd = -1) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = fd;
  }

 private:
  int fd_ = -1;
};

bool make_pipe(Fd& read_end, Fd& write_end) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) return false;  // close-on-exec: no other child inherits them
  read_end.reset(fds[0]);
  write_end.reset(fds[1]);
  return true;
}

// The started child: killed and reaped if it is still running when this goes out of scope (an
// exception from a line callback), deregistered from the signal cleanup only once it has ended
// but before it is reaped, so the cleanup never signals a pid that could have been reused.
class Child {
 public:
  Child(pid_t pid, RegisteredChild reg) : pid_(pid), reg_(std::move(reg)) {}
  ~Child() {
    if (pid_ > 0) {
      ::kill(pid_, SIGKILL);
      wait();
    }
  }
  void kill() { ::kill(pid_, SIGKILL); }
  // Waits for the end; the raw status of waitpid.
  int wait() {
    siginfo_t info{};
    while (::waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOWAIT) != 0 && errno == EINTR) {
    }
    with_registry_lock([&] { reg_.release(); });
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    return status;
  }

 private:
  pid_t pid_;
  RegisteredChild reg_;
};

// Splits what arrives on a stream into lines for a callback (a last line without '\n' included).
class LineSplitter {
 public:
  explicit LineSplitter(const std::function<void(const std::string&)>& f) : f_(f) {}
  void add(const char* data, std::size_t n) {
    pending_.append(data, n);
    std::size_t start = 0;
    for (std::size_t nl; (nl = pending_.find('\n', start)) != std::string::npos; start = nl + 1) emit(pending_.substr(start, nl - start));
    pending_.erase(0, start);
  }
  void finish() {
    if (!pending_.empty()) emit(pending_);
    pending_.clear();
  }

 private:
  void emit(std::string line) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    f_(line);
  }
  const std::function<void(const std::string&)>& f_;
  std::string pending_;
};

// Reads the child's stdout and stderr until both close (or the deadline passes: returns false).
bool drain(Fd& out, Fd& err, const SubprocessOptions& o, SubprocessResult& r) {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.timeout_s));
  LineSplitter lines(o.on_line);
  char buf[4096];
  while (out.get() >= 0 || err.get() >= 0) {
    pollfd fds[2] = {{out.get(), POLLIN, 0}, {err.get(), POLLIN, 0}};
    int wait_ms = -1;
    if (o.timeout_s > 0) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) return false;
      wait_ms = static_cast<int>(std::min<long long>(left, 1000));
    }
    const int n = ::poll(fds, 2, wait_ms);
    if (n < 0 && errno != EINTR) return true;
    if (n <= 0) continue;
    for (int k = 0; k < 2; ++k) {
      if (fds[k].fd < 0 || fds[k].revents == 0) continue;
      const ssize_t got = ::read(fds[k].fd, buf, sizeof buf);
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) {
        (k == 0 ? out : err).reset();
        continue;
      }
      if (k == 1)
        r.err.append(buf, static_cast<std::size_t>(got));
      else if (o.on_line)
        lines.add(buf, static_cast<std::size_t>(got));
      else
        r.out.append(buf, static_cast<std::size_t>(got));
    }
  }
  if (o.on_line) lines.finish();
  return true;
}

// The file actions: stdin from /dev/null, stdout (and stderr) to the pipes, the working folder.
struct FileActions {
  posix_spawn_file_actions_t fa;
  FileActions() { posix_spawn_file_actions_init(&fa); }
  ~FileActions() { posix_spawn_file_actions_destroy(&fa); }
};

// Signals back at their defaults and none blocked in the child, whatever this thread has.
struct SpawnAttributes {
  posix_spawnattr_t attr;
  SpawnAttributes() {
    posix_spawnattr_init(&attr);
    sigset_t defaults, none;
    sigemptyset(&defaults);
    for (int s : {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGUSR2}) sigaddset(&defaults, s);
    sigemptyset(&none);
    posix_spawnattr_setsigdefault(&attr, &defaults);
    posix_spawnattr_setsigmask(&attr, &none);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  }
  ~SpawnAttributes() { posix_spawnattr_destroy(&attr); }
};

}  // namespace

SubprocessResult run_program(const std::vector<std::string>& argv, const SubprocessOptions& o) {
  SubprocessResult r;
  if (argv.empty() || argv[0].empty()) {
    r.error = "no program named";
    return r;
  }
  if (!o.working_dir.empty()) {
    struct stat st {};
    if (::stat(o.working_dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) {
      r.error = argv[0] + ": cannot start in '" + o.working_dir.string() + "': not a folder";
      return r;
    }
  }
  Fd out_r, out_w, err_r, err_w;
  if (!make_pipe(out_r, out_w) || (o.stderr_to == SubprocessOptions::Stderr::separate && !make_pipe(err_r, err_w))) {
    r.error = argv[0] + ": cannot make a pipe: " + std::strerror(errno);
    return r;
  }
  FileActions actions;
  posix_spawn_file_actions_t* fa = &actions.fa;
  posix_spawn_file_actions_addopen(fa, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(fa, out_w.get(), STDOUT_FILENO);
  switch (o.stderr_to) {
    case SubprocessOptions::Stderr::separate: posix_spawn_file_actions_adddup2(fa, err_w.get(), STDERR_FILENO); break;
    case SubprocessOptions::Stderr::merged: posix_spawn_file_actions_adddup2(fa, out_w.get(), STDERR_FILENO); break;
    case SubprocessOptions::Stderr::discarded: posix_spawn_file_actions_addopen(fa, STDERR_FILENO, "/dev/null", O_WRONLY, 0); break;
  }
  if (!o.working_dir.empty()) posix_spawn_file_actions_addchdir_np(fa, o.working_dir.c_str());  // glibc ≥ 2.29
  SpawnAttributes attributes;
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);

  // Started and registered in one step under the cleanup's lock: a signal finds it registered.
  pid_t pid = -1;
  int rc = 0;
  RegisteredChild reg;
  with_registry_lock([&] {
    rc = ::posix_spawnp(&pid, args[0], fa, &attributes.attr, args.data(), environ);
    if (rc == 0) reg = RegisteredChild(pid);
  });
  if (rc != 0) {
    r.error = rc == ENOENT ? argv[0] + ": not found" : argv[0] + ": cannot start: " + std::strerror(rc);
    return r;
  }
  r.started = true;
  Child child(pid, std::move(reg));
  out_w.reset();  // the parent's copies: the pipes close when the child's end
  err_w.reset();
  if (!drain(out_r, err_r, o, r)) {
    r.timed_out = true;
    child.kill();
  }
  out_r.reset();
  err_r.reset();
  const int status = child.wait();
  if (WIFEXITED(status)) r.exit_status = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  return r;
}

bool program_runs(const std::vector<std::string>& argv) {
  SubprocessOptions o;
  o.stderr_to = SubprocessOptions::Stderr::discarded;
  o.timeout_s = 30;  // a version query; a program that hangs is not one we can use
  return run_program(argv, o).ok();
}

std::string safe_file_argument(const std::filesystem::path& file) {
  const std::string s = file.string();
  if (file.is_relative() && !s.empty() && s[0] == '-') return "./" + s;
  return s;
}

}  // namespace stoneskip
