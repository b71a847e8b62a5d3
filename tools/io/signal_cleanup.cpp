#include "tools/io/signal_cleanup.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace stoneskip {

namespace {

struct Entry {
  long id;
  std::string path;
  TemporaryKind kind;
};

struct Registry {
  std::recursive_mutex mutex;
  std::vector<Entry> entries;
  long next_id = 1;
};

// Never destroyed: the cleanup thread may use it while exit() runs static destructors.
Registry& registry() {
  static Registry* r = new Registry;
  return *r;
}

// --- Removal with system calls only (no allocation) -------------------------------------------

struct LinuxDirent64 {
  ino64_t d_ino;
  off64_t d_off;
  unsigned short d_reclen;
  unsigned char d_type;
  char d_name[1];  // NUL-terminated, d_reclen long in all
};

bool dot_or_dotdot(const char* n) { return n[0] == '.' && (n[1] == 0 || (n[1] == '.' && n[2] == 0)); }

// Removes `name` in the folder `parent_fd` (a file, a link, or a folder and everything in it).
// Returns true if something was removed.
bool remove_at(int parent_fd, const char* name, int depth) {
  if (::unlinkat(parent_fd, name, 0) == 0) return true;
  if (errno == ENOENT) return false;
  if (depth > 32) return false;
  for (int attempt = 0; attempt < 3; ++attempt) {
    const int fd = ::openat(parent_fd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) return false;
    alignas(8) char buf[4096];
    for (;;) {
      const long n = ::syscall(SYS_getdents64, fd, buf, sizeof buf);
      if (n <= 0) break;
      for (long off = 0; off < n;) {
        const auto* d = reinterpret_cast<const LinuxDirent64*>(buf + off);
        off += d->d_reclen;
        if (!dot_or_dotdot(d->d_name)) remove_at(fd, d->d_name, depth + 1);
      }
    }
    ::close(fd);
    if (::unlinkat(parent_fd, name, AT_REMOVEDIR) == 0 || errno == ENOENT) return true;
    if (errno != ENOTEMPTY && errno != EEXIST) return false;
  }
  return false;
}

int remove_entries(const std::vector<Entry>& entries) {
  int removed = 0;
  // Newest first: a file registered inside a registered folder goes before the folder.
  for (auto it = entries.rbegin(); it != entries.rend(); ++it)
    if (remove_at(AT_FDCWD, it->path.c_str(), 0)) ++removed;
  return removed;
}

// --- Stopping the other threads ----------------------------------------------------------------

std::atomic<int> g_stopped{0};

void stop_handler(int) {
  g_stopped.fetch_add(1);
  for (;;) ::pause();
}

void sleep_ms(long ms) {
  timespec ts{0, ms * 1000000L};
  ::nanosleep(&ts, nullptr);
}

// Sends SIGUSR2 to every other thread of the process (listed in /proc/self/task) and waits until
// each has entered the handler, or 500 ms.
void stop_other_threads() {
  constexpr int kMaxThreads = 4096;
  static pid_t signalled[kMaxThreads];  // static: no allocation, no large stack frame
  int count = 0;
  const pid_t pid = ::getpid();
  const pid_t self = static_cast<pid_t>(::syscall(SYS_gettid));
  for (int round = 0; round < 4; ++round) {
    const int fd = ::open("/proc/self/task", O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    bool found_new = false;
    alignas(8) char buf[4096];
    for (;;) {
      const long n = ::syscall(SYS_getdents64, fd, buf, sizeof buf);
      if (n <= 0) break;
      for (long off = 0; off < n;) {
        const auto* d = reinterpret_cast<const LinuxDirent64*>(buf + off);
        off += d->d_reclen;
        if (dot_or_dotdot(d->d_name)) continue;
        pid_t tid = 0;
        for (const char* c = d->d_name; *c >= '0' && *c <= '9'; ++c) tid = tid * 10 + (*c - '0');
        if (tid <= 0 || tid == self) continue;
        bool seen = false;
        for (int i = 0; i < count && !seen; ++i) seen = signalled[i] == tid;
        if (seen || count == kMaxThreads) continue;
        if (::syscall(SYS_tgkill, pid, tid, SIGUSR2) == 0) {
          signalled[count++] = tid;
          found_new = true;
        }
      }
    }
    ::close(fd);
    for (int waited = 0; g_stopped.load() < count && waited < 500; ++waited) sleep_ms(1);
    if (!found_new) break;
  }
}

// --- Child processes ------------------------------------------------------------------------------

// Fixed slots, so the cleanup reads them without allocating; 0 is a free slot.
constexpr int kMaxChildren = 64;
std::atomic<int> g_children[kMaxChildren];

void kill_children() {
  for (auto& c : g_children) {
    const int pid = c.load();
    if (pid <= 0) continue;
    ::kill(pid, SIGKILL);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
  }
}

// --- The signal handler and the cleanup thread -------------------------------------------------

int g_pipe_write = -1;

void on_signal(int sig) {
  const int saved = errno;
  if (::write(g_pipe_write, &sig, sizeof sig) < 0) {
  }
  errno = saved;
}

const char* signal_name(int sig) {
  switch (sig) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
  }
  return "a signal";
}

// set_interrupt_note's line (written by the cleanup without allocating).
char g_note[512];
std::size_t g_note_length = 0;

// "stoneskip: interrupted by SIGINT; removed N temporaries" without allocating, then the note.
void say_interrupted(int sig, int removed) {
  char line[160];
  std::size_t k = 0;
  auto put = [&](const char* s) {
    while (*s && k + 1 < sizeof line) line[k++] = *s++;
  };
  put("stoneskip: interrupted by ");
  put(signal_name(sig));
  put("; removed ");
  char digits[16];
  int nd = 0;
  unsigned v = static_cast<unsigned>(removed);
  do {
    digits[nd++] = static_cast<char>('0' + v % 10);
    v /= 10;
  } while (v && nd < 15);
  while (nd > 0 && k + 1 < sizeof line) line[k++] = digits[--nd];
  put(removed == 1 ? " temporary file or folder\n" : " temporary files and folders\n");
  if (::write(STDERR_FILENO, line, k) < 0) {
  }
  if (g_note_length > 0 && ::write(STDERR_FILENO, g_note, g_note_length) < 0) {
  }
}

void cleanup_thread(int read_fd) {
  int sig = 0;
  for (;;) {
    const ssize_t n = ::read(read_fd, &sig, sizeof sig);
    if (n == static_cast<ssize_t>(sizeof sig)) break;
    if (n < 0 && errno == EINTR) continue;
    return;
  }
  Registry& r = registry();
  r.mutex.lock();  // held until _exit: nothing is registered, created or renamed from here on
  stop_other_threads();
  kill_children();  // first: a child may still be writing into a registered folder
  const int removed = remove_entries(r.entries);
  say_interrupted(sig, removed);
  ::_exit(128 + sig);
}

}  // namespace

RegisteredTemporary::RegisteredTemporary(const std::filesystem::path& path, TemporaryKind kind) {
  Registry& r = registry();
  std::lock_guard<std::recursive_mutex> lock(r.mutex);
  id_ = r.next_id++;
  r.entries.push_back({id_, path.string(), kind});
}

RegisteredTemporary::~RegisteredTemporary() { release(); }

RegisteredTemporary::RegisteredTemporary(RegisteredTemporary&& o) noexcept : id_(o.id_) { o.id_ = 0; }

RegisteredTemporary& RegisteredTemporary::operator=(RegisteredTemporary&& o) noexcept {
  if (this != &o) {
    release();
    id_ = o.id_;
    o.id_ = 0;
  }
  return *this;
}

void RegisteredTemporary::release() {
  if (id_ == 0) return;
  Registry& r = registry();
  std::lock_guard<std::recursive_mutex> lock(r.mutex);
  for (auto it = r.entries.begin(); it != r.entries.end(); ++it)
    if (it->id == id_) {
      r.entries.erase(it);
      break;
    }
  id_ = 0;
}

RegisteredChild::RegisteredChild(int pid) {
  for (int i = 0; i < kMaxChildren; ++i) {
    int free_slot = 0;
    if (g_children[i].compare_exchange_strong(free_slot, pid)) {
      slot_ = i;
      return;
    }
  }
}

RegisteredChild::~RegisteredChild() { release(); }

RegisteredChild::RegisteredChild(RegisteredChild&& o) noexcept : slot_(o.slot_) { o.slot_ = -1; }

RegisteredChild& RegisteredChild::operator=(RegisteredChild&& o) noexcept {
  if (this != &o) {
    release();
    slot_ = o.slot_;
    o.slot_ = -1;
  }
  return *this;
}

void RegisteredChild::release() {
  if (slot_ < 0) return;
  g_children[slot_].store(0);
  slot_ = -1;
}

void with_registry_lock(const std::function<void()>& f) {
  std::lock_guard<std::recursive_mutex> lock(registry().mutex);
  f();
}

void set_interrupt_note(const std::string& line) {
  std::lock_guard<std::recursive_mutex> lock(registry().mutex);
  std::size_t n = std::min(line.size(), sizeof g_note - 2);
  std::copy(line.begin(), line.begin() + static_cast<long>(n), g_note);
  if (n > 0) g_note[n++] = '\n';
  g_note_length = n;
}

void install_signal_cleanup() {
  static bool installed = false;
  if (installed) return;
  installed = true;
  registry();
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) return;  // no cleanup on signals; nothing else changes
  g_pipe_write = fds[1];
  std::thread(cleanup_thread, fds[0]).detach();
  struct sigaction stop {};
  stop.sa_handler = stop_handler;
  sigemptyset(&stop.sa_mask);
  ::sigaction(SIGUSR2, &stop, nullptr);
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  for (int s : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(s, &sa, nullptr);
}

int remove_registered_temporaries() {
  Registry& r = registry();
  std::lock_guard<std::recursive_mutex> lock(r.mutex);
  return remove_entries(r.entries);
}

int registered_temporary_count() {
  Registry& r = registry();
  std::lock_guard<std::recursive_mutex> lock(r.mutex);
  return static_cast<int>(r.entries.size());
}

}  // namespace stoneskip
