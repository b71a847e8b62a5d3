#pragma once
// A report folder being built. Everything goes into a work folder beside the destination,
// `<DIR>.partial/`; the destination appears only when the report is whole (rename at commit()),
// so a report folder is never half written.
//
//   <DIR>.partial/manifest         kind and settings key of the build (text)
//   <DIR>.partial/sections/<s>.h5  one file per finished section, written atomically
//   <DIR>.partial/data.h5          assembled at the end: root attributes + /sections/<s>
//
// Sections are stored as each finishes (StudySink), so a run that dies late (a crash, SIGKILL, a
// node lost) keeps them: the next run with the same report kind, settings and code version
// finds `<DIR>.partial` and reuses every finished section. A work folder built with other
// settings is discarded. Only one process may build a folder at a time (a lock file).
// An existing <DIR> is replaced only if it is a report folder stoneskip made (it holds nothing but
// what its manifest, `stoneskip-manifest.txt`, lists, unchanged, and a data.h5 with a `report`
// attribute) or an empty folder; anything else is refused with an InputError, when the build
// starts and again at commit(), whose move is atomic against a change after that check
// (tools/io/atomic_file.hpp, move_folder_into_place).
//
// What stops a build, and what it leaves:
//  * an error (bad input found late, an internal error): the work folder stays if it holds
//    finished sections (to be resumed); one this run made and stored nothing in is removed;
//  * SIGINT, SIGTERM, SIGHUP: while the work folder holds no finished section it is registered
//    with tools/io/signal_cleanup.hpp and removed whole (temporaries being written are removed in
//    any case); from the first finished section on it stays, as after SIGKILL, and the cleanup's
//    line on stderr says where — finished work is never thrown away by an interruption;
//  * a crash, SIGKILL, a lost node: the work folder stays and the next run resumes it.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tools/io/signal_cleanup.hpp"
#include "verification/study/study_sink.hpp"

namespace stoneskip {

struct ReportBuildOptions {
  std::filesystem::path out_dir;
  std::string kind;           // "waves", "stones", "captures", "scene"
  std::string settings_text;  // what the sections were computed from (study files, options)
  std::string command_line;   // stored with the data
  ProgressFactory progress;
  // Whether a signal leaves finished sections for a resume (below). A command that never resumes
  // them (`capture validate`: a capture takes seconds) sets false: a signal then removes it all.
  bool keep_sections_on_signal = true;
};

class ReportBuild : public StudySink {
 public:
  explicit ReportBuild(ReportBuildOptions options);
  ~ReportBuild() override;
  ReportBuild(const ReportBuild&) = delete;
  ReportBuild& operator=(const ReportBuild&) = delete;

  std::optional<Record> resume(const std::string& section) override;
  void store(const std::string& section, const Record& record) override;
  const ProgressFactory& progress() const override { return options_.progress; }

  // Writes <DIR>.partial/data.h5: provenance, kind, settings and command as root attributes,
  // `root` (numbers and texts of the whole report) beside them, and every stored section under
  // /sections in the order stored. Returns the work folder, where the caller renders.
  std::filesystem::path assemble(const Record& root);
  // Moves the work folder into place (the sections' files and the lock are removed first).
  void commit();

  const std::filesystem::path& work_dir() const { return work_; }
  int resumed_sections() const { return resumed_; }

 private:
  void keep_on_signal();  // unregisters the work folder once it holds a finished section
  ReportBuildOptions options_;
  std::filesystem::path work_;
  std::string key_;
  std::vector<std::string> order_;
  int lock_fd_ = -1;
  int resumed_ = 0;
  int stored_ = 0;             // sections stored by this run
  bool created_work_ = false;  // the work folder did not exist before this run
  bool committed_ = false;
  RegisteredTemporary registered_;  // the work folder, while it is one
};

// True if `dir` is a folder this program made: it holds nothing but what its manifest lists
// (tools/io/folder_manifest.hpp, written at commit) and its data.h5 has a `report` attribute.
bool is_report_folder(const std::filesystem::path& dir);

}  // namespace stoneskip
