#pragma once
// The journal of a running sweep: "<result>.h5.journal", an append-only file of checksummed
// records beside the result file, written by rank 0 as throws finish. The result file itself is
// written whole (atomically) at the end; the journal is then removed.
//
// Why a journal and not an extendible HDF5 dataset: a process killed inside an HDF5 write can
// leave the file's metadata unreadable, while an append-only file killed at any byte keeps every
// record before the torn one, and each record carries its length and an FNV-1a checksum, so a
// torn or garbled tail is recognised and cut off on resume.
//
// Record: u32 magic "SWJ1", u32 type (1 header, 2 rows), u64 payload bytes, payload, u64 FNV-1a
// of the payload. The header's payload is a list of (name, value) strings — the sweep file's
// text, the base case's text, the code version and a fingerprint of the executable, the columns,
// the byte order — which a resume must match exactly; a rows payload is an encoded RowBatch.
//
// Durability: every append is one write(2) (a SIGKILL loses nothing already appended: the data is
// in the kernel's page cache); fdatasync(2) runs at most once per sync interval (a lost node or
// power cut loses at most that interval), on a thread of its own so that a slow disk never stalls
// the scheduler that appends. The file is locked (flock) while a sweep writes it, so two runs
// cannot interleave records.
#include <atomic>
#include <condition_variable>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "verification/sweep/row_batch.hpp"

namespace stoneskip {

using JournalIdentity = std::vector<std::pair<std::string, std::string>>;

std::filesystem::path journal_path_for(const std::filesystem::path& result_file);

struct JournalRecovery {
  RowBatch rows;                 // every complete record's rows and notes, in file order
  std::size_t records = 0;
  std::size_t dropped_bytes = 0; // a torn or corrupt tail that was cut off
  // Whole records found after the first bad one: the cut was damage mid-journal (a flipped byte),
  // not a torn tail, and these records' throws are computed again. 0 for a torn tail.
  std::size_t damaged_records = 0;
};

// For --resume: removes the journal at `path` and returns true when it holds no finished work
// because its header was never completed — the file is empty, or a strict prefix of a header
// record (the magic and type so far, then fewer bytes than the record's length says), as a kill
// left it in builds that created the journal at its name before writing the header (create() now
// links it whole; on a file system without hard links it still may). Anything else (a
// whole journal, a foreign or damaged file) is left for resume() to read or refuse: false.
// InputError if another sweep holds the journal's lock.
bool remove_journal_with_torn_header(const std::filesystem::path& path);

// True if a running sweep holds the journal at `path` (its writer's flock, as lock_or_fail takes
// it); false for a journal nobody writes (an interrupted sweep's) or a path that cannot be opened.
bool journal_in_use(const std::filesystem::path& path);

class SweepJournal {
 public:
  // A new journal, made whole and locked under "<path>.tmp-PID" and then linked to `path`; InputError
  // if `path` exists or the journal cannot be created or locked.
  static SweepJournal create(const std::filesystem::path& path, const JournalIdentity& identity, double sync_interval_s);
  // An existing journal, for --resume: checks it was written for the same identity (InputError
  // naming the first field that differs), reads every complete record, and truncates a torn tail
  // so that appends continue after the last good record.
  static SweepJournal resume(const std::filesystem::path& path, const JournalIdentity& identity, double sync_interval_s,
                             JournalRecovery& recovered);

  SweepJournal(SweepJournal&&) noexcept;
  SweepJournal& operator=(SweepJournal&&) = delete;
  SweepJournal(const SweepJournal&) = delete;
  ~SweepJournal();

  void append(const RowBatch& b);  // throws std::runtime_error on a failed write
  void sync();                      // fdatasync now, on the calling thread
  double write_wall_s() const { return write_wall_s_; }  // spent appending (the syncs run aside)
  const std::filesystem::path& path() const { return path_; }
  void close_and_remove();

 private:
  SweepJournal(std::filesystem::path path, int fd, double sync_interval_s);
  void write_record(std::uint32_t type, const std::vector<unsigned char>& payload);
  void request_sync();  // wakes the sync thread (started on first use, once the journal is in place)
  void stop_syncing();
  void throw_if_sync_failed() const;
  void sync_or_record();  // fdatasync; a failure that matters is kept in sync_errno_
  std::filesystem::path path_;
  int fd_ = -1;
  double sync_interval_s_ = 1;
  double last_sync_s_ = 0;
  double write_wall_s_ = 0;
  std::thread syncer_;
  std::mutex sync_mutex_;
  std::condition_variable sync_wanted_;
  bool sync_pending_ = false, stopping_ = false;
  // The errno of a failed fdatasync on the sync thread (0 while none failed): the next append or
  // sync throws it, so that an I/O error is not lost with the thread that met it.
  std::atomic<int> sync_errno_{0};
};

}  // namespace stoneskip
