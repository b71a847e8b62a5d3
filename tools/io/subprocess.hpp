#pragma once
// Starting another program (gnuplot, ffmpeg, ffprobe, the stoneskip executable in tests) without a
// shell: the program and its arguments are an argument vector handed to posix_spawnp, so a file
// name is always data, never a command (no quoting, no shell). The child reads /dev/null, may
// start in another working folder, and its output comes back as a string or line by line.
//
// While a child runs it is registered with the signal cleanup (tools/io/signal_cleanup.hpp): if
// SIGINT, SIGTERM or SIGHUP ends stoneskip, the child is killed and reaped first, so no gnuplot is
// left drawing into a removed folder.
//
// A name that starts with '-' would be read as an option by most programs: pass file names through
// safe_file_argument().
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace stoneskip {

struct SubprocessOptions {
  enum class Stderr { separate, merged, discarded };
  std::filesystem::path working_dir;  // empty: the caller's
  Stderr stderr_to = Stderr::separate;
  // Called with each line of stdout (without its '\n'); stdout is then not kept in `out`.
  std::function<void(const std::string&)> on_line;
  double timeout_s = 0;  // > 0: the child is killed (SIGKILL) when it runs longer
};

struct SubprocessResult {
  bool started = false;  // false: the program could not be started; `error` says why
  int exit_status = -1;  // the status it exited with, or -1 if it was killed by a signal
  int signal = 0;        // the signal that ended it, if any
  bool timed_out = false;
  std::string out, err;  // stdout (unless on_line) and stderr (if separate)
  std::string error;     // "gnuplot: not found" and the like
  bool ok() const { return started && exit_status == 0; }
};

// Runs argv[0] (searched in PATH when it has no '/') with argv[1..]; waits for it to end.
SubprocessResult run_program(const std::vector<std::string>& argv, const SubprocessOptions& options = {});

// True if `argv` starts and exits with status 0 (output discarded): `{"gnuplot", "--version"}`.
bool program_runs(const std::vector<std::string>& argv);

// A file name as an argument that no program can read as an option: a relative name starting with
// '-' gets "./" in front ("-x.gp" -> "./-x.gp"); any other name is returned as it is.
std::string safe_file_argument(const std::filesystem::path& file);

}  // namespace stoneskip
