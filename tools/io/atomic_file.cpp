#include "tools/io/atomic_file.hpp"
#include "tools/io/folder_manifest.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

#include "tools/io/input_error.hpp"
#include "tools/io/shipped_files.hpp"

namespace stoneskip {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void refuse(const fs::path& p, const std::string& what) { throw_input_error(p.string(), 0, "", what); }

std::string errno_words(int e) { return std::strerror(e); }

// `final_path` with `suffix` added to its name. A destination whose name is near the file system's
// limit (NAME_MAX, 255 bytes on Linux's file systems) has its name shortened first, cut at a
// character's start, so that a name the system accepts is not refused for the suffix ("File name
// too long" for a 250-byte name).
fs::path beside(const fs::path& final_path, const std::string& suffix) {
  std::string name = final_path.filename().string();
  const std::size_t name_max = 255;
  if (name.size() + suffix.size() > name_max) {
    std::size_t keep = name_max - suffix.size();
    while (keep > 0 && (static_cast<unsigned char>(name[keep]) & 0xC0) == 0x80) --keep;  // not inside a UTF-8 character
    name.resize(keep);
  }
  return final_path.parent_path() / (name + suffix);
}

// A name longer than the file system takes is refused before any work: shortened, its temporary
// would be made, the work done, and only the final rename fail ("File name too long").
void refuse_a_name_too_long(const fs::path& final_path) {
  fs::path dir = final_path.parent_path();
  if (dir.empty()) dir = ".";
  long name_max = ::pathconf(dir.c_str(), _PC_NAME_MAX);
  if (name_max <= 0) name_max = 255;
  const std::size_t length = final_path.filename().string().size();
  if (length > static_cast<std::size_t>(name_max))
    throw_input_error(final_path.string(), 0, "",
                      "cannot write: the name is " + std::to_string(length) + " bytes long, and this file system takes at most " +
                          std::to_string(name_max));
}

// A unique temporary name beside the destination: "<name>.tmp-PID", then "<name>.tmp-PID-N" if
// another writer of this process (or a file left by an earlier process with the same id) has it.
fs::path temporary_name(const fs::path& final_path, int attempt) {
  std::string suffix = ".tmp-" + std::to_string(::getpid());
  if (attempt > 0) suffix += "-" + std::to_string(attempt);
  return beside(final_path, suffix);
}

}  // namespace

fs::path name_beside(const fs::path& final_path, const std::string& suffix) { return beside(final_path, suffix); }

std::string file_type_words(unsigned mode) {
  switch (mode & S_IFMT) {
    case S_IFREG: return "a regular file";
    case S_IFDIR: return "a folder";
    case S_IFLNK: return "a symbolic link";
    case S_IFIFO: return "a FIFO";
    case S_IFCHR: return "a character device";
    case S_IFBLK: return "a block device";
    case S_IFSOCK: return "a socket";
  }
  return "not a regular file";
}

void check_output_destination(const fs::path& path) {
  if (path.empty()) throw_input_error("--out", 0, "", "an output file name is required (got an empty name)");
  fs::path dir = path.parent_path();
  if (dir.empty()) dir = ".";
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0) refuse(path, "cannot write: folder '" + dir.string() + "' does not exist");
  if (!S_ISDIR(st.st_mode)) refuse(path, "cannot write: '" + dir.string() + "' is " + file_type_words(st.st_mode) + ", not a folder");
  if (::lstat(path.c_str(), &st) == 0) {
    if (S_ISDIR(st.st_mode)) refuse(path, "cannot write: it is a folder");
    if (!S_ISREG(st.st_mode))
      refuse(path, "cannot write: it exists and is " + file_type_words(st.st_mode) +
                       ", not a regular file: refusing to replace it");
    // A file nobody may write (a baseline marked read-only) is kept as its owner marked it: the
    // move into place would replace it whatever its mode (rename needs only the folder's write
    // permission), and root may write anything, so the mode bits are read, not access().
    if ((st.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0) {
      char mode[8];
      std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(st.st_mode & 07777));
      refuse(path, std::string("cannot write: it is read-only (mode ") + mode +
                       "): refusing to replace it (make it writable to let it be rewritten)");
    }
  } else if (errno != ENOENT) {
    refuse(path, "cannot write: " + errno_words(errno));
  }
}

AtomicOutput::AtomicOutput(fs::path final_path) : final_(std::move(final_path)) {
  check_output_destination(final_);
  refuse_a_name_too_long(final_);
  // Create the temporary now (registered first, so a signal between the two finds it), so that a
  // place we cannot write is reported before any work.
  with_registry_lock([&] {
    for (int attempt = 0; attempt < 100; ++attempt) {
      fs::path t = temporary_name(final_, attempt);
      RegisteredTemporary reg(t, TemporaryKind::file);
      const int fd = ::open(t.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0644);
      if (fd >= 0) {
        ::close(fd);
        tmp_ = std::move(t);
        registered_ = std::move(reg);
        return;
      }
      if (errno != EEXIST) {
        const int e = errno;
        fs::path dir = final_.parent_path();
        if (dir.empty()) dir = ".";
        refuse(final_, "cannot write in folder '" + dir.string() + "': " + errno_words(e));
      }
    }
    refuse(final_, "cannot write: no free temporary name beside it");
  });
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) {
    with_registry_lock([&] {
      ::unlink(tmp_.c_str());
      registered_.release();
    });
  }
}

void move_into_place(const fs::path& tmp, const fs::path& final_path, bool replacing) {
  const char *from = tmp.c_str(), *to = final_path.c_str();
  auto unsupported = [](int e) { return e == EINVAL || e == ENOSYS || e == EOPNOTSUPP; };
  if (!replacing) {
    if (::renameat2(AT_FDCWD, from, AT_FDCWD, to, RENAME_NOREPLACE) == 0) return;
    const int e = errno;
    if (e == EEXIST) {
      struct stat now {};
      const std::string what = ::lstat(to, &now) == 0 ? file_type_words(now.st_mode) : std::string("something");
      refuse(final_path, "cannot write: " + what + " appeared at this name while the output was written: refusing to replace it");
    }
    if (!unsupported(e)) refuse(final_path, "cannot write: " + errno_words(e));
  } else {
    if (::renameat2(AT_FDCWD, from, AT_FDCWD, to, RENAME_EXCHANGE) == 0) {
      struct stat old {};
      if (::lstat(from, &old) == 0 && S_ISREG(old.st_mode)) {
        ::unlink(from);  // the file replaced, now under the temporary name
        return;
      }
      // Not the regular file that was checked: put it back, and keep ours under its temporary name.
      const std::string what = file_type_words(old.st_mode);
      ::renameat2(AT_FDCWD, from, AT_FDCWD, to, RENAME_EXCHANGE);
      refuse(final_path, "cannot write: it became " + what + " while the output was written: refusing to replace it");
    }
    const int e = errno;
    if (e == ENOENT) return move_into_place(tmp, final_path, false);  // removed meanwhile: a free name again
    if (!unsupported(e)) refuse(final_path, "cannot write: " + errno_words(e));
  }
  if (::rename(from, to) != 0) {
    const int e = errno;
    refuse(final_path, "cannot write: " + errno_words(e));
  }
}

void AtomicOutput::commit() {
  // Checked when opened; checked again, since time has passed (a FIFO may have appeared), and the
  // move itself is atomic against a change after this check (move_into_place).
  check_output_destination(final_);
  with_registry_lock([&] {
    // A file replaced keeps its permissions (a baseline made group-writable stays so).
    struct stat st {};
    const bool replacing = ::lstat(final_.c_str(), &st) == 0 && S_ISREG(st.st_mode);
    if (replacing) ::chmod(tmp_.c_str(), st.st_mode & 07777);
    move_into_place(tmp_, final_, replacing);
    registered_.release();
    committed_ = true;
  });
}

AtomicFolder::AtomicFolder(fs::path final_dir, const std::function<bool(const fs::path&)>& replaceable)
    : final_(std::move(final_dir)), replaceable_(replaceable) {
  if (final_.empty()) throw_input_error("--out", 0, "", "an output folder is required (got an empty name)");
  while (final_.has_parent_path() && !final_.has_filename()) final_ = final_.parent_path();  // "dir/" → "dir"
  check_destination();
  refuse_a_name_too_long(final_);
  work_ = beside(final_, ".partial-" + std::to_string(::getpid()));
  with_registry_lock([&] {
    RegisteredTemporary reg(work_, TemporaryKind::folder);
    if (::mkdir(work_.c_str(), 0755) != 0) {
      const int e = errno;
      refuse(final_, "cannot create the work folder '" + work_.string() + "': " + errno_words(e));
    }
    registered_ = std::move(reg);
  });
}

void AtomicFolder::check_destination() const {
  fs::path dir = final_.parent_path();
  if (dir.empty()) dir = ".";
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0) refuse(final_, "cannot write: folder '" + dir.string() + "' does not exist");
  if (!S_ISDIR(st.st_mode)) refuse(final_, "cannot write: '" + dir.string() + "' is " + file_type_words(st.st_mode) + ", not a folder");
  if (::access(dir.c_str(), W_OK) != 0) refuse(final_, "cannot write: folder '" + dir.string() + "' is not writable");
  if (::lstat(final_.c_str(), &st) == 0) {
    if (!S_ISDIR(st.st_mode))
      refuse(final_, "exists and is " + file_type_words(st.st_mode) + ", not a folder: refusing to replace it");
    std::error_code ec;
    if (!fs::is_empty(final_, ec) && !(replaceable_ && replaceable_(final_)))
      refuse(final_, "exists and is not a folder stoneskip made: refusing to replace it");
  }
}

AtomicFolder::~AtomicFolder() {
  if (committed_) return;
  std::error_code ec;
  with_registry_lock([&] {
    fs::remove_all(work_, ec);
    registered_.release();
  });
}

FolderMove move_folder_into_place(const fs::path& work, const fs::path& final_dir,
                                  const std::function<bool(const fs::path&)>& replaceable) {
  const char *from = work.c_str(), *to = final_dir.c_str();
  auto unsupported = [](int e) { return e == EINVAL || e == ENOSYS || e == EOPNOTSUPP; };
  // A few tries: what is at the name may go away between one call and the next.
  for (int attempt = 0; attempt < 3; ++attempt) {
    if (::renameat2(AT_FDCWD, from, AT_FDCWD, to, RENAME_NOREPLACE) == 0) return FolderMove::placed;
    int e = errno;
    if (unsupported(e)) return FolderMove::unsupported;
    if (e != EEXIST) refuse(final_dir, "cannot write: " + errno_words(e));
    struct stat st {};
    if (::lstat(to, &st) != 0) continue;  // gone again
    if (!S_ISDIR(st.st_mode))
      refuse(final_dir, "cannot write: " + file_type_words(st.st_mode) +
                            " appeared at this name while the output was written: refusing to replace it");
    if (::renameat2(AT_FDCWD, from, AT_FDCWD, to, RENAME_EXCHANGE) != 0) {
      e = errno;
      if (e == ENOENT) continue;
      if (unsupported(e)) return FolderMove::unsupported;
      refuse(final_dir, "cannot write: " + errno_words(e));
    }
    // What came back is what was at the name at the moment of the swap: look at it again.
    struct stat old {};
    const bool folder = ::lstat(from, &old) == 0 && S_ISDIR(old.st_mode);
    std::error_code ec;
    if (folder && (fs::is_empty(work, ec) || (replaceable && replaceable(work)))) return FolderMove::swapped;
    ::renameat2(AT_FDCWD, from, AT_FDCWD, to, RENAME_EXCHANGE);  // put it back; ours stays at `work`
    refuse(final_dir, folder ? std::string("cannot write: the folder now at this name is not one stoneskip made (it changed "
                                           "while the output was written): refusing to replace it")
                             : "cannot write: it became " + file_type_words(old.st_mode) +
                                   " while the output was written: refusing to replace it");
  }
  refuse(final_dir, "cannot write: the name keeps changing while the output is moved into place");
}

void AtomicFolder::commit() {
  write_folder_manifest(work_);  // what stoneskip wrote: the folder may be replaced while it holds only that
  check_destination();  // again: time has passed; the move itself is atomic against a later change
  std::error_code ec;
  fs::path old = final_;
  old += ".old-" + std::to_string(::getpid());
  RegisteredTemporary old_registered;
  bool old_at_work = false;
  // Under the registry's lock: a signal sees the old folder in place or already replaced.
  with_registry_lock([&] {
    const FolderMove m = move_folder_into_place(work_, final_, replaceable_);
    if (m == FolderMove::swapped) {
      old_at_work = true;  // the replaced folder, still registered under the work folder's name
      committed_ = true;
      return;
    }
    if (m == FolderMove::unsupported) {
      // No renameat2 flags: the old folder moved aside, then the new one renamed into place.
      if (fs::exists(fs::symlink_status(final_, ec))) {
        old_registered = RegisteredTemporary(old, TemporaryKind::folder);
        if (::rename(final_.c_str(), old.c_str()) != 0) refuse(final_, std::string("cannot replace: ") + errno_words(errno));
      }
      if (::rename(work_.c_str(), final_.c_str()) != 0) {
        const int e = errno;
        if (old_registered.registered()) ::rename(old.c_str(), final_.c_str());
        refuse(final_, "cannot write: " + errno_words(e));
      }
    }
    registered_.release();
    committed_ = true;
  });
  if (old_registered.registered()) fs::remove_all(old, ec);
  if (old_at_work) {
    fs::remove_all(work_, ec);
    with_registry_lock([&] { registered_.release(); });
  }
}

void write_text_file(const fs::path& path, const std::string& text) {
  AtomicOutput out(path);
  {
    std::ofstream f(out.temporary_path(), std::ios::binary | std::ios::trunc);
    f << text;
    f.close();
    if (!f) throw_input_error(path.string(), 0, "", "cannot write");
  }
  out.commit();
}

void require_regular_file(const fs::path& path) {
  if (path.empty()) throw_input_error("", 0, "", "an input file name is required (got an empty name)");
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    const int e = errno;
    throw_input_error(path.string(), 0, "", e == ENOENT ? "cannot read: no such file" : "cannot read: " + errno_words(e));
  }
  if (!S_ISREG(st.st_mode))
    throw_input_error(path.string(), 0, "", "cannot read: it is " + file_type_words(st.st_mode) + ", not a regular file");
}

std::string read_text_file(const fs::path& given, std::size_t max_bytes) {
  // A shipped case named "cases/..." is found from any working directory (shipped_files.hpp).
  const fs::path path = locate_input(given);
  require_regular_file(path);
  // Opened without blocking and checked again on the descriptor: the name may have been replaced
  // by a FIFO since the check.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    const int e = errno;
    throw_input_error(path.string(), 0, "", "cannot read: " + errno_words(e));
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw_input_error(path.string(), 0, "", "cannot read: not a regular file");
  }
  if (static_cast<unsigned long long>(st.st_size) > max_bytes) {
    ::close(fd);
    throw_input_error(path.string(), 0, "", "is " + std::to_string(st.st_size) + " bytes, larger than the limit of " +
                                                  std::to_string(max_bytes) + " bytes for this kind of file");
  }
  std::string text;
  text.reserve(static_cast<std::size_t>(st.st_size));
  char buf[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buf, sizeof buf);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR || errno == EAGAIN) continue;
      const int e = errno;
      ::close(fd);
      throw_input_error(path.string(), 0, "", "cannot read: " + errno_words(e));
    }
    text.append(buf, static_cast<std::size_t>(n));
    if (text.size() > max_bytes) {
      ::close(fd);
      throw_input_error(path.string(), 0, "", "is larger than the limit of " + std::to_string(max_bytes) + " bytes");
    }
  }
  ::close(fd);
  return text;
}

}  // namespace stoneskip
