#pragma once
// A file whose parser is not ours to harden is read first in a forked child. The HDF5 library
// checks the metadata of its newer objects but not its global heap, where variable-length strings
// live: one flipped byte there can crash it (a segfault in H5HG_read) or send it into an endless
// loop (H5HG__protect), and no check of ours runs before it reads. So the read runs once in a
// child process (fork, no exec: the same code on the same bytes), with stdout and stderr sent to
// /dev/null and the default action for SIGINT, SIGTERM, SIGHUP and the crash signals (SIGSEGV,
// SIGBUS, SIGFPE, SIGILL, SIGABRT: no handler of the host's catches them there):
//   * the child ends by a signal (a crash), exits with a status other than its own 0 (an exit from
//     inside the library: a memory checker such as ASan reporting a heap overflow in it), or runs
//     past its time: the file is refused in one line
//     (InputError: "<file>: is a damaged HDF5 file: …", exit 2) and the caller never reads it;
//   * the child finishes (the read succeeded or threw): the caller reads the file in-process and
//     gets the same result, its own error message included.
// The child is registered with the signal cleanup (tools/io/signal_cleanup.hpp) while it runs. If
// fork fails (no memory, no process slots), the file is read in-process, unprotected, as before.
// Cost: the file is read twice (a report's data.h5 or a sweep table: milliseconds to seconds).
// A damaged heap can also overflow a buffer without a crash, which this test cannot see: so no
// Hdf5Reader reads a variable-length string in-process at all (hdf5_strings_apart.hpp, through the
// output variant below).
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

namespace stoneskip {

struct IsolatedReadOptions {
  // The child's time; ≤ 0: 10 s plus 1 s per 10 MB of the file (the HDF5 reads here take well
  // under a second per 10 MB on a 2-core machine: a loop, not a slow read, runs past it).
  double timeout_s = 0;
};

// Runs read() in a child first (see above), then returns; the caller then reads the file itself.
// `read` must only read (the child's writes, its memory and its files' state are thrown away) and
// must not wait for other threads (the child has only the calling thread).
void read_in_child_first(const std::filesystem::path& file, const std::function<void()>& read,
                         const IsolatedReadOptions& options = {});

// As read_in_child_first, and what the child writes to the file descriptor it is given (a pipe)
// comes back: all of it, once the child has finished. Beyond max_output_bytes the child is killed
// and the file refused (InputError: "<file>: is a damaged HDF5 file: …"). A read that throws ends
// the child as one that finishes; what it wrote before comes back. nullopt where no child could be
// made (fork or pipe failed): the caller then reads in-process, unprotected.
std::optional<std::string> read_in_child_first(const std::filesystem::path& file,
                                               const std::function<void(int out_fd)>& read,
                                               std::size_t max_output_bytes,
                                               const IsolatedReadOptions& options = {});

// Whether this process is the child of one of the reads above (a read there needs no child of its own).
bool in_isolated_child();

}  // namespace stoneskip
