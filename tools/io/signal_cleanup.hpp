#pragma once
// Temporaries that must not outlive an interrupted command. AtomicOutput's "<file>.tmp-PID" files
// and ReportBuild's "<DIR>.partial" work folders (until they hold a finished section, which is
// kept for a resume) register here while they exist; when SIGINT,
// SIGTERM or SIGHUP arrives, every registered path is removed and the process ends with status
// 128 + signal (130 for SIGINT, 143 for SIGTERM, 129 for SIGHUP). SIGKILL cannot be caught: a
// killed process leaves its temporaries (and a report build resumes from its work folder).
//
// How (install_signal_cleanup(), called first thing in main()):
//  1. The handler of the three signals only write()s the signal number to a pipe (async-signal-
//     safe). Handlers rather than a blocked mask and sigwait(): a blocked mask is inherited by the
//     children we start (gnuplot), handlers are reset by exec.
//  2. A cleanup thread blocked on the pipe wakes, takes the registry's mutex — so no registered
//     path is half created or half renamed — and stops every other thread of the process (a
//     SIGUSR2 whose handler never returns), so nothing can create a file behind it.
//  3. It kills and reaps the registered child processes (RegisteredChild: gnuplot, ffmpeg), removes
//     the registered paths with plain system calls (no allocation: a stopped thread may hold the
//     allocator's lock), writes one line on stderr (and the note of set_interrupt_note, if any)
//     and calls _exit(128 + signal).
// Registered paths are created, renamed into place and unregistered while holding the same mutex
// (with_registry_lock), so the cleanup sees each one either absent, whole at its temporary name,
// or already in place.
#include <filesystem>
#include <functional>
#include <string>

namespace stoneskip {

enum class TemporaryKind { file, folder };

// A registered path; unregistered when destroyed or released (it is then final, or removed by its
// owner). Registering takes the registry's mutex.
class RegisteredTemporary {
 public:
  RegisteredTemporary() = default;
  RegisteredTemporary(const std::filesystem::path& path, TemporaryKind kind);
  ~RegisteredTemporary();
  RegisteredTemporary(RegisteredTemporary&& o) noexcept;
  RegisteredTemporary& operator=(RegisteredTemporary&& o) noexcept;
  RegisteredTemporary(const RegisteredTemporary&) = delete;
  RegisteredTemporary& operator=(const RegisteredTemporary&) = delete;
  void release();
  bool registered() const { return id_ != 0; }

 private:
  long id_ = 0;
};

// A running child process (tools/io/subprocess.hpp): the cleanup kills it (SIGKILL) and reaps it
// before removing the temporaries it may be writing into. Up to 64 children are held; more run
// unregistered. Register while holding with_registry_lock, in the same step that starts the child.
class RegisteredChild {
 public:
  RegisteredChild() = default;
  explicit RegisteredChild(int pid);
  ~RegisteredChild();
  RegisteredChild(RegisteredChild&& o) noexcept;
  RegisteredChild& operator=(RegisteredChild&& o) noexcept;
  RegisteredChild(const RegisteredChild&) = delete;
  RegisteredChild& operator=(const RegisteredChild&) = delete;
  void release();

 private:
  int slot_ = -1;
};

// Runs f while holding the registry's mutex (recursive): create, rename or remove registered paths
// inside it. A signal's cleanup waits for f to return; f must be short.
void with_registry_lock(const std::function<void()>& f);

// A line the cleanup writes on stderr after its own when a signal ends the process: where finished
// work was kept for a resume (a report's sections in "<DIR>.partial"). Empty: none. The first
// 510 bytes are kept; set under the registry's lock, so the cleanup sees the old line or the new one.
void set_interrupt_note(const std::string& line);

// Installs the handlers and starts the cleanup thread; call once, before any other thread starts.
void install_signal_cleanup();

// What the cleanup thread does before _exit, without stopping threads or exiting: removes every
// registered path now. Returns how many were removed. For tests.
int remove_registered_temporaries();

// Number of registered paths (for tests).
int registered_temporary_count();

}  // namespace stoneskip
