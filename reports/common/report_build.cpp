#include "reports/common/report_build.hpp"

#include <cerrno>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <functional>

#include "stoneskip_version.hpp"
#include "tools/io/atomic_file.hpp"
#include "tools/io/folder_manifest.hpp"
#include "tools/io/hdf5_file.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/signal_cleanup.hpp"

namespace stoneskip {

namespace fs = std::filesystem;

namespace {

constexpr const char* kManifest = "manifest";
constexpr const char* kLock = "lock";

std::string manifest_text(const std::string& kind, const std::string& key) {
  return "stoneskip report build\nkind " + kind + "\nkey " + key + "\n";
}

// The settings key: what a finished section was computed from. A hash keeps the manifest short;
// the settings themselves are stored in data.h5.
std::string settings_key(const ReportBuildOptions& o) {
  const std::string all = o.kind + "\n" + kGitDescribe + "\n" + o.settings_text;
  return std::to_string(std::hash<std::string>{}(all));
}

fs::path section_file(const fs::path& work, const std::string& section) { return work / "sections" / (section + ".h5"); }

}  // namespace

bool is_report_folder(const fs::path& dir) {
  std::error_code ec;
  const fs::path data = dir / "data.h5";
  if (!fs::is_regular_file(data, ec) || !holds_only_its_manifest(dir)) return false;
  try {
    Hdf5Reader r(data);
    return r.root().has_attr("report");
  } catch (const std::exception&) {
    return false;
  }
}

// The report's folder as named, without trailing "/" or "/.": `--out waves/` is the folder waves,
// whose work folder is its sibling waves.partial (main put it at waves/.partial, inside the
// report's own folder, and refused that folder as not empty after all the work). Only the end is
// trimmed: a ".." inside the name is left to the file system (after a link it is the link's target's
// parent, which lexical normalisation would get wrong). A name that ends in ".." or is "." names a
// folder that holds more than the report (a parent, the current one): refused, as is the root.
fs::path report_folder_name(const fs::path& given) {
  if (given.empty()) throw_input_error("--out", 0, "", "an output folder is required (got an empty name)");
  fs::path p = given;
  while (p.has_relative_path() && (p.filename().empty() || p.filename() == ".")) p = p.parent_path();
  const char* what = p.empty() ? "the current folder" : !p.has_relative_path() ? "the root" : p.filename() == ".." ? "a parent folder" : nullptr;
  if (what)
    throw_input_error(given.string(), 0, "",
                      std::string("names ") + what + ", not a folder of the report's own: give one inside it, such as " +
                          (p.empty()                ? fs::path(".") / "report"
                           : !p.has_relative_path() ? fs::path("/tmp/report")
                                                    : p / "report")
                              .string());
  return p;
}

ReportBuild::ReportBuild(ReportBuildOptions options) : options_(std::move(options)) {
  options_.out_dir = report_folder_name(options_.out_dir);
  const fs::path& out = options_.out_dir;
  std::error_code ec;
  fs::path parent = out.parent_path();
  if (parent.empty()) parent = ".";
  struct stat st {};
  // A missing parent chain is made (`--out elsewhere/waves` from a fresh folder): only folders that
  // do not exist are created, nothing is replaced.
  if (::stat(parent.c_str(), &st) != 0 && errno == ENOENT) fs::create_directories(parent, ec);
  if (::stat(parent.c_str(), &st) != 0)
    throw_input_error(out.string(), 0, "", "cannot write: folder '" + parent.string() + "' does not exist and cannot be made");
  if (!S_ISDIR(st.st_mode))
    throw_input_error(out.string(), 0, "", "cannot write: '" + parent.string() + "' is " + file_type_words(st.st_mode) + ", not a folder");
  if (::access(parent.c_str(), W_OK) != 0)
    throw_input_error(out.string(), 0, "", "cannot write: folder '" + parent.string() + "' is not writable");
  if (::lstat(out.c_str(), &st) == 0) {
    if (!S_ISDIR(st.st_mode))
      throw_input_error(out.string(), 0, "", "exists and is " + file_type_words(st.st_mode) + ", not a folder: refusing to replace it");
    if (!fs::is_empty(out, ec) && !is_report_folder(out))
      throw_input_error(out.string(), 0, "", "exists and is not a stoneskip report folder: refusing to replace it");
  }
  work_ = out;
  work_ += ".partial";
  key_ = settings_key(options_);

  // A work folder left by an earlier run: resume it if it was built with these settings.
  if (::lstat(work_.c_str(), &st) == 0) {
    if (!S_ISDIR(st.st_mode) || !fs::is_regular_file(work_ / kManifest, ec))
      throw_input_error(work_.string(), 0, "", "exists and is not a stoneskip work folder: remove it first");
  } else {
    // Made here: registered first, so that a signal removes it (tools/io/signal_cleanup.hpp).
    created_work_ = true;
  }
  registered_ = RegisteredTemporary(work_, TemporaryKind::folder);
  with_registry_lock([&] { fs::create_directories(work_ / "sections", ec); });
  if (ec) {
    if (created_work_) fs::remove_all(work_, ec);
    registered_.release();
    throw_input_error(work_.string(), 0, "", "cannot create the work folder: " + ec.message());
  }
  lock_fd_ = ::open((work_ / kLock).c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock_fd_ < 0 || ::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    registered_.release();  // another process's folder: not ours to remove
    throw_input_error(out.string(), 0, "", "another stoneskip process is building this report");
  }
  std::string old;
  if (fs::is_regular_file(work_ / kManifest, ec)) old = read_text_file(work_ / kManifest);
  if (old != manifest_text(options_.kind, key_)) {
    // Other settings or another kind: nothing in it can be reused.
    for (const auto& e : fs::directory_iterator(work_ / "sections", ec)) fs::remove_all(e.path(), ec);
    fs::remove(work_ / "data.h5", ec);
    fs::remove_all(work_ / "figures", ec);
    fs::remove(work_ / "index.md", ec);
    fs::remove(work_ / "index.html", ec);
    write_text_file(work_ / kManifest, manifest_text(options_.kind, key_));
  }
  if (!fs::is_empty(work_ / "sections", ec)) keep_on_signal();  // an earlier run's finished sections
}

void ReportBuild::keep_on_signal() {
  // From the first finished section on, a signal leaves the work folder as SIGKILL does, and the
  // cleanup's line says where: the same command resumes it.
  if (!registered_.registered() || !options_.keep_sections_on_signal) return;
  with_registry_lock([&] {  // a signal sees the folder registered, or kept and said where
    registered_.release();
    set_interrupt_note("stoneskip: finished sections kept in " + work_.string() + ": run the same command to resume");
  });
}

ReportBuild::~ReportBuild() {
  set_interrupt_note("");
  if (lock_fd_ >= 0) ::close(lock_fd_);
  // Stopped by an error before any section was finished: a work folder this run made holds
  // nothing worth resuming, so it goes (bad input leaves no folder behind). With finished
  // sections it stays for the next run to resume (reports/README.md, "Reports").
  if (!committed_ && created_work_ && stored_ == 0) {
    std::error_code ec;
    with_registry_lock([&] { fs::remove_all(work_, ec); });
  }
}

std::optional<Record> ReportBuild::resume(const std::string& section) {
  std::error_code ec;
  const fs::path f = section_file(work_, section);
  if (!fs::is_regular_file(f, ec)) return std::nullopt;
  try {
    Hdf5Reader r(f);
    if (!r.root().has_attr("key") || r.root().attr_string("key") != key_) return std::nullopt;
    Record rec = load_record(r.root().open_group("record"));
    if (std::find(order_.begin(), order_.end(), section) == order_.end()) order_.push_back(section);
    ++resumed_;
    return rec;
  } catch (const std::exception&) {
    return std::nullopt;  // unreadable (killed while written, before the rename): compute it again
  }
}

void ReportBuild::store(const std::string& section, const Record& record) {
  Hdf5Writer w(section_file(work_, section));
  w.root().set_attr("key", key_);
  w.root().set_attr("section", section);
  store_record(w.root().create_group("record"), record);
  w.commit();
  ++stored_;
  if (std::find(order_.begin(), order_.end(), section) == order_.end()) order_.push_back(section);
  keep_on_signal();
}

fs::path ReportBuild::assemble(const Record& root) {
  Hdf5Writer w(work_ / "data.h5");
  H5Group& g = w.root();
  stamp_provenance(g);
  g.set_attr("report", options_.kind);
  g.set_attr("settings", options_.settings_text);
  g.set_attr("command", options_.command_line);
  store_record(g.create_group("report"), root);
  H5Group sections = g.create_group("sections");
  for (const auto& s : order_) {
    Hdf5Reader r(section_file(work_, s));
    store_record(sections.create_group(s), load_record(r.root().open_group("record")));
  }
  std::string list;
  for (const auto& s : order_) list += (list.empty() ? "" : "\n") + s;
  sections.set_attr("_children", list);
  w.commit();
  return work_;
}

void ReportBuild::commit() {
  std::error_code ec;
  // What this build wrote, less the work files removed below: the folder may be replaced while it
  // holds only that.
  write_folder_manifest(work_, {"sections", kManifest, kLock});
  const fs::path& out = options_.out_dir;
  fs::path old;
  RegisteredTemporary old_registered;
  bool old_at_work = false;  // the replaced report, swapped to the work folder's name
  // Under the registry's lock: a signal sees the work folder whole (its sections resumable) or the
  // report in place, and the old report in place or already replaced, never moved aside with
  // nothing in its place.
  with_registry_lock([&] {
    fs::remove_all(work_ / "sections", ec);
    fs::remove(work_ / kManifest, ec);
    fs::remove(work_ / kLock, ec);
    struct stat st {};
    if (::lstat(out.c_str(), &st) == 0) {
      // Checked in the constructor; checked again, since time has passed.
      if (!S_ISDIR(st.st_mode) || (!fs::is_empty(out, ec) && !is_report_folder(out)))
        throw_input_error(out.string(), 0, "", "exists and is not a stoneskip report folder: refusing to replace it");
    }
    // Atomic against a change after that check: what is replaced is looked at again after the swap.
    const FolderMove m = move_folder_into_place(work_, out, [](const fs::path& d) { return is_report_folder(d); });
    if (m == FolderMove::swapped) {
      old_at_work = true;
      // Removed below; a signal meanwhile removes it too (it is no longer resumable work).
      if (!registered_.registered()) registered_ = RegisteredTemporary(work_, TemporaryKind::folder);
      committed_ = true;
      set_interrupt_note("");
      return;
    }
    if (m == FolderMove::unsupported) {
      // A file system without renameat2's flags: the old report moved aside, the new one renamed in.
      if (::lstat(out.c_str(), &st) == 0) {
        old = out;
        old += ".old-" + std::to_string(::getpid());
        old_registered = RegisteredTemporary(old, TemporaryKind::folder);
        fs::rename(out, old, ec);
        if (ec) throw_input_error(out.string(), 0, "", "cannot replace: " + ec.message());
      }
      fs::rename(work_, out, ec);
      if (ec) {
        if (!old.empty()) fs::rename(old, out, ec);
        old_registered.release();
        throw_input_error(out.string(), 0, "", "cannot move the finished report into place");
      }
    }
    registered_.release();
    committed_ = true;
    set_interrupt_note("");
  });
  if (!old.empty()) fs::remove_all(old, ec);
  if (old_at_work) {
    fs::remove_all(work_, ec);
    with_registry_lock([&] { registered_.release(); });
  }
}

}  // namespace stoneskip
