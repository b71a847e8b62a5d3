#pragma once
// Output files appear whole or not at all: everything is written to "<name>.tmp-<pid>" beside the
// final path and renamed over it on commit(). A writer destroyed before commit() (an exception, a
// bad input found late) removes its temporary file, and a signal removes it too
// (tools/io/signal_cleanup.hpp), so no partial output is ever left behind.
//
// Only a regular file is ever replaced: a destination that is a folder, a symbolic link, a FIFO, a
// device or a socket is refused (checked with lstat when the output is opened and again just before
// the rename), so `--out /dev/null` run as root cannot replace the device node.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>

#include "tools/io/signal_cleanup.hpp"

namespace stoneskip {

// `final_path` with `suffix` added to its name, the name shortened first (cut at a character's
// start) where the two together would pass the file system's 255 bytes: the temporaries and
// companions of an output whose name is near that limit ("<name>.tmp-PID", "<name>.journal").
std::filesystem::path name_beside(const std::filesystem::path& final_path, const std::string& suffix);

class AtomicOutput {
 public:
  // Checks the destination (see above) and creates the empty temporary file, so an unwritable
  // place (a read-only folder, /proc, a missing folder) is found before any work: InputError
  // naming the path and the reason.
  explicit AtomicOutput(std::filesystem::path final_path);
  ~AtomicOutput();
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;

  const std::filesystem::path& temporary_path() const { return tmp_; }
  const std::filesystem::path& final_path() const { return final_; }
  void commit();  // checks the destination again, renames temporary -> final

 private:
  std::filesystem::path final_;
  std::filesystem::path tmp_;
  RegisteredTemporary registered_;
  bool committed_ = false;
};

// An output folder that appears whole or not at all (`capture validate --out`, `sweep-plot`):
// everything is written into "<DIR>.partial-<pid>" beside it, registered with the signal cleanup,
// and renamed to DIR on commit(). Destroyed before commit() (an error) or stopped by a signal, the
// work folder is removed. An existing DIR is replaced only if it is an empty folder or
// `replaceable(DIR)` says stoneskip made it; anything else (a file, a link, a device, someone's
// folder) is refused with an InputError before any work, and again at commit(), whose move is
// atomic against a change after that check (move_folder_into_place).
class AtomicFolder {
 public:
  AtomicFolder(std::filesystem::path final_dir, const std::function<bool(const std::filesystem::path&)>& replaceable);
  ~AtomicFolder();
  AtomicFolder(const AtomicFolder&) = delete;
  AtomicFolder& operator=(const AtomicFolder&) = delete;

  const std::filesystem::path& work_dir() const { return work_; }
  const std::filesystem::path& final_dir() const { return final_; }
  void commit();

 private:
  std::filesystem::path final_;
  std::filesystem::path work_;
  std::function<bool(const std::filesystem::path&)> replaceable_;
  RegisteredTemporary registered_;
  bool committed_ = false;
  void check_destination() const;
};

// Throws InputError unless `path` may be written: a non-empty name, in an existing folder, and
// either absent or a regular file (never a folder, link, FIFO, device or socket).
void check_output_destination(const std::filesystem::path& path);

// Writes a whole text file atomically.
void write_text_file(const std::filesystem::path& path, const std::string& text);

// Reads a whole text file (a shipped "cases/..." file from any working directory: locate_input,
// tools/io/shipped_files.hpp); InputError naming the file if it is missing, is not a regular file (a
// folder, a FIFO, a device: refused without opening it), is larger than max_bytes, or cannot be read.
std::string read_text_file(const std::filesystem::path& path,
                           std::size_t max_bytes = std::numeric_limits<std::size_t>::max());

// Throws InputError unless `path` names an existing regular file (same words as read_text_file).
void require_regular_file(const std::filesystem::path& path);

// "a folder", "a FIFO", "a character device", ... for the file type of an lstat/stat mode.
std::string file_type_words(unsigned mode);

// Moves the finished file `tmp` to `final_path`, atomic against a destination that changes after
// it was checked (Linux renameat2): where the check found no file (`replacing` false) the name is
// taken only while it is free (RENAME_NOREPLACE); where it found a regular file the two are swapped
// (RENAME_EXCHANGE) and what came back is looked at: anything but a regular file is swapped back.
// A file system without these flags gets a plain rename. InputError naming `final_path` when
// something else is there now; `tmp` is then left for its owner to remove.
void move_into_place(const std::filesystem::path& tmp, const std::filesystem::path& final_path, bool replacing);

// How move_folder_into_place left things.
enum class FolderMove {
  placed,      // the name was free and is now the new folder's
  swapped,     // the folder that was there is now at `work`, for the caller to remove
  unsupported  // the file system has no renameat2 flags: nothing moved, the caller renames
};

// Moves the finished folder `work` to `final_dir`, atomic against a destination changed after it
// was checked (Linux renameat2): a free name is taken only while it is still free
// (RENAME_NOREPLACE); a folder there is swapped with `work` (RENAME_EXCHANGE) and what came back
// is looked at again: unless it is a folder that is empty or `replaceable`, it is swapped back.
// Anything else at the name (a file, a link, a device) is refused without a move. InputError naming
// `final_dir` when refused; `work` then holds the new folder still, for its owner to remove.
FolderMove move_folder_into_place(const std::filesystem::path& work, const std::filesystem::path& final_dir,
                                  const std::function<bool(const std::filesystem::path&)>& replaceable);

}  // namespace stoneskip
