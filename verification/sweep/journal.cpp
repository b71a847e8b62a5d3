#include "verification/sweep/journal.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <system_error>

#include "tools/io/atomic_file.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/signal_cleanup.hpp"

namespace stoneskip {

namespace fs = std::filesystem;

namespace {

constexpr std::uint32_t kMagic = 0x314a5753;  // "SWJ1" little-endian
constexpr std::uint32_t kHeader = 1, kRows = 2;
constexpr std::size_t kFrame = 4 + 4 + 8 + 8;  // magic, type, length, checksum

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string byte_order() {
  const std::uint32_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first ? "little-endian, 8-byte doubles" : "big-endian, 8-byte doubles";
}

JournalIdentity with_byte_order(const JournalIdentity& id) {
  JournalIdentity out = id;
  out.emplace_back("byte_order", byte_order());
  return out;
}

std::vector<unsigned char> encode_identity(const JournalIdentity& id) {
  // Reuses the batch encoding: one note per field (solver = name, detail = value).
  RowBatch b;
  for (const auto& [name, value] : id) b.notes.push_back({0, name, value});
  return encode(b);
}

int lock_or_fail(const fs::path& path, int fd) {
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd);
    throw_input_error(path.string(), 0, "", "another sweep is writing this journal (it is locked)");
  }
  return fd;
}

}  // namespace

bool journal_in_use(const fs::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return false;
  const bool held = ::flock(fd, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK;
  ::close(fd);  // releases the lock this probe may have taken
  return held;
}

namespace {

// Reads records from the start; returns the offset just past the last good record.
std::size_t read_records(const std::vector<unsigned char>& bytes, std::vector<std::pair<std::uint32_t, std::vector<unsigned char>>>& out) {
  std::size_t pos = 0;
  while (bytes.size() - pos >= kFrame) {
    std::uint32_t magic = 0, type = 0;
    std::uint64_t len = 0, sum = 0;
    std::memcpy(&magic, &bytes[pos], 4);
    std::memcpy(&type, &bytes[pos + 4], 4);
    std::memcpy(&len, &bytes[pos + 8], 8);
    if (magic != kMagic || (type != kHeader && type != kRows) || len > bytes.size() - pos - kFrame) break;
    const unsigned char* payload = &bytes[pos + 16];
    std::memcpy(&sum, payload + len, 8);
    if (sum != fnv1a64(payload, len)) break;
    out.emplace_back(type, std::vector<unsigned char>(payload, payload + len));
    pos += kFrame + len;
  }
  return pos;
}

// A header's payload is the texts of a sweep file and a base case and a few names: a length past
// this is not one of ours, whatever the bytes before it say.
constexpr std::uint64_t kMaxHeaderPayload = std::uint64_t{1} << 30;

// True when `bytes` are a strict prefix of a header record (see remove_journal_with_torn_header).
bool is_torn_header(const std::vector<unsigned char>& bytes) {
  unsigned char start[8];
  std::memcpy(start, &kMagic, 4);
  std::memcpy(start + 4, &kHeader, 4);
  // An empty file is the shortest prefix (and memcmp is not given the null data() of an empty vector).
  if (!bytes.empty() && std::memcmp(bytes.data(), start, std::min<std::size_t>(bytes.size(), 8)) != 0) return false;
  if (bytes.size() < 16) return true;  // the length not yet whole
  std::uint64_t len = 0;
  std::memcpy(&len, &bytes[8], 8);
  return len <= kMaxHeaderPayload && bytes.size() < kFrame + len;
}

}  // namespace

bool remove_journal_with_torn_header(const fs::path& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return false;  // resume() says what it is
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
  if (fd < 0) return false;
  lock_or_fail(path, fd);  // a sweep still creating it holds the lock: refused, never removed under it
  std::vector<unsigned char> bytes;
  bool torn = false;
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && static_cast<std::uint64_t>(st.st_size) < kFrame + kMaxHeaderPayload) {
    bytes.resize(static_cast<std::size_t>(st.st_size));
    torn = ::pread(fd, bytes.data(), bytes.size(), 0) == static_cast<ssize_t>(bytes.size()) && is_torn_header(bytes);
  }
  // Removed while still locked, so no other run can take it up in between.
  if (torn && ::unlink(path.c_str()) != 0) torn = false;
  ::close(fd);
  return torn;
}

fs::path journal_path_for(const fs::path& result_file) {
  // Shortened where "<name>.journal" would pass 255 bytes (the same name every time: --resume finds it).
  return name_beside(result_file, ".journal");
}

SweepJournal::SweepJournal(fs::path path, int fd, double sync_interval_s)
    : path_(std::move(path)), fd_(fd), sync_interval_s_(sync_interval_s), last_sync_s_(now_s()) {}

// Moved only before the first append (create/resume return it by value): no sync thread yet.
SweepJournal::SweepJournal(SweepJournal&& o) noexcept
    : path_(std::move(o.path_)), fd_(o.fd_), sync_interval_s_(o.sync_interval_s_), last_sync_s_(o.last_sync_s_),
      write_wall_s_(o.write_wall_s_) {
  o.fd_ = -1;
}

SweepJournal::~SweepJournal() {
  stop_syncing();
  if (fd_ >= 0) {
    ::fdatasync(fd_);
    ::close(fd_);
  }
}

void SweepJournal::request_sync() {
  if (!syncer_.joinable()) {
    const auto syncer = [this] {
      std::unique_lock<std::mutex> lock(sync_mutex_);
      for (;;) {
        sync_wanted_.wait(lock, [this] { return sync_pending_ || stopping_; });
        if (stopping_) return;
        sync_pending_ = false;
        lock.unlock();
        sync_or_record();
        lock.lock();
      }
    };
    try {
      syncer_ = std::thread(syncer);
    } catch (const std::system_error&) {
      sync();  // no thread to spare (the system would not start one): the sync is done here
      return;
    }
  }
  std::lock_guard<std::mutex> lock(sync_mutex_);
  sync_pending_ = true;
  sync_wanted_.notify_one();
}

void SweepJournal::stop_syncing() {
  if (!syncer_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(sync_mutex_);
    stopping_ = true;
    sync_wanted_.notify_one();
  }
  syncer_.join();
}

// The journal is made whole before it has its name: created, locked and given its header under a
// temporary name of this process, then linked to `path` (link(2) fails where `path` exists, as
// O_EXCL did) and the temporary name removed. Created at `path` itself, it was there for a moment
// empty and unlocked, and a `sweep --resume` started then took it for a journal whose header a kill
// had torn, removed it, and ran into the same output. Where the file system has no hard links,
// the journal is created at `path` as before.
SweepJournal SweepJournal::create(const fs::path& path, const JournalIdentity& identity, double sync_interval_s) {
  // A journal named `path` on the open file `fd` at `at`, locked and given its header.
  auto written = [&](const fs::path& at, int fd) {
    SweepJournal j(path, lock_or_fail(at, fd), sync_interval_s);
    j.write_record(kHeader, encode_identity(with_byte_order(identity)));
    j.sync();
    return j;
  };
  auto cannot = [&](int e) {
    throw_input_error(path.string(), 0, "", std::string("cannot create the sweep journal: ") + std::strerror(e));
  };
  const fs::path tmp = name_beside(path, ".tmp-" + std::to_string(::getpid()));
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) cannot(errno);
  // Ours from here: removed on every way out of this function, and by a signal meanwhile.
  RegisteredTemporary registered(tmp, TemporaryKind::file);
  struct RemoveTemporary {
    const fs::path& tmp;
    RegisteredTemporary& registered;
    ~RemoveTemporary() {
      ::unlink(tmp.c_str());
      registered.release();
    }
  };
  int linked = -1, link_errno = 0;
  std::optional<SweepJournal> j;
  {
    const RemoveTemporary remove{tmp, registered};
    j.emplace(written(tmp, fd));
    linked = ::link(tmp.c_str(), path.c_str());
    link_errno = errno;
  }
  if (linked == 0) return std::move(*j);
  j.reset();  // closes the temporary journal (already unlinked)
  if (link_errno != EPERM && link_errno != EOPNOTSUPP && link_errno != ENOSYS) cannot(link_errno);
  // No hard links here: created in place (the moment without a header remains on such a file system).
  const int fd2 = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_APPEND | O_CLOEXEC, 0644);
  if (fd2 < 0) cannot(errno);
  return written(path, fd2);
}

SweepJournal SweepJournal::resume(const fs::path& path, const JournalIdentity& identity, double sync_interval_s,
                                  JournalRecovery& recovered) {
  // A journal is a regular file: a FIFO would block or read forever, a device is not ours to append to.
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
    throw_input_error(path.string(), 0, "", "is " + file_type_words(st.st_mode) + ", not a sweep journal: delete it and run without --resume");
  const int fd = ::open(path.c_str(), O_RDWR | O_APPEND | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
  if (fd < 0) throw_input_error(path.string(), 0, "", std::string("cannot open the sweep journal: ") + std::strerror(errno));
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw_input_error(path.string(), 0, "", "is not a regular file: not a sweep journal");
  }
  SweepJournal j(path, lock_or_fail(path, fd), sync_interval_s);
  std::vector<unsigned char> bytes(static_cast<std::size_t>(::lseek(fd, 0, SEEK_END)));
  if (::pread(fd, bytes.data(), bytes.size(), 0) != static_cast<ssize_t>(bytes.size()))
    throw_input_error(path.string(), 0, "", "cannot read the sweep journal");
  std::vector<std::pair<std::uint32_t, std::vector<unsigned char>>> records;
  const std::size_t good = read_records(bytes, records);
  // A damaged record with whole records after it is damage, not a torn tail: count what it costs.
  std::size_t later = 0;
  for (std::size_t at = good + 1; at + kFrame <= bytes.size() && later == 0; ++at) {
    if (std::memcmp(&bytes[at], &kMagic, 4) != 0) continue;
    std::vector<std::pair<std::uint32_t, std::vector<unsigned char>>> rest;
    read_records(std::vector<unsigned char>(bytes.begin() + static_cast<std::ptrdiff_t>(at), bytes.end()), rest);
    later = rest.size();
  }
  if (records.empty() || records.front().first != kHeader)
    throw_input_error(path.string(), 0, "", "not a sweep journal (no header record): delete it and run without --resume");
  RowBatch header;
  if (!decode(records.front().second.data(), records.front().second.size(), header))
    throw_input_error(path.string(), 0, "", "the journal's header is malformed: delete it and run without --resume");
  const JournalIdentity want = with_byte_order(identity);
  for (const auto& [name, value] : want) {
    const ThrowNote* have = nullptr;
    for (const auto& n : header.notes)
      if (n.solver == name) have = &n;
    if (!have || have->detail != value)
      throw_input_error(path.string(), 0, name,
                        "differs from this sweep's (the journal belongs to another sweep, file version or build): "
                        "delete it and run without --resume");
  }
  // Only this sweep's identity: a header naming anything else, or any field twice, is foreign.
  for (std::size_t i = 0; i < header.notes.size(); ++i) {
    const std::string& name = header.notes[i].solver;
    bool known = false, twice = false;
    for (const auto& w : want) known = known || w.first == name;
    for (std::size_t k = 0; k < i; ++k) twice = twice || header.notes[k].solver == name;
    if (!known || twice)
      throw_input_error(path.string(), 0, name,
                        std::string(twice ? "is given twice" : "is not a field of this sweep's identity") +
                            " in the journal's header (a foreign or edited journal): delete it and run without --resume");
  }
  for (std::size_t i = 1; i < records.size(); ++i) {
    if (records[i].first != kRows)
      throw_input_error(path.string(), 0, "",
                        "record " + std::to_string(i + 1) + " is a second header (another sweep's records appended): "
                        "delete the journal and run without --resume");
    RowBatch b;
    if (!decode(records[i].second.data(), records[i].second.size(), b))
      throw_input_error(path.string(), 0, "", "record " + std::to_string(i) + " is malformed despite its checksum");
    recovered.rows.append(b);
    ++recovered.records;
  }
  recovered.dropped_bytes = bytes.size() - good;
  recovered.damaged_records = later;
  if (recovered.dropped_bytes > 0 && ::ftruncate(fd, static_cast<off_t>(good)) != 0)
    throw_input_error(path.string(), 0, "", std::string("cannot cut the journal's torn tail: ") + std::strerror(errno));
  return j;
}

void SweepJournal::throw_if_sync_failed() const {
  // An fdatasync that failed (EIO: the device lost written pages; ENOSPC, EDQUOT: a delayed
  // allocation found no room) means records already appended may not be on the disk: the run stops
  // as for a failed append, exit 2, with the journal kept for --resume (which checks every record).
  if (const int e = sync_errno_.load(); e != 0)
    throw std::system_error(e, std::generic_category(), "cannot make the sweep journal " + path_.string() + " durable");
}

void SweepJournal::write_record(std::uint32_t type, const std::vector<unsigned char>& payload) {
  throw_if_sync_failed();
  const double start = now_s();
  std::vector<unsigned char> rec(kFrame + payload.size());
  const std::uint64_t len = payload.size(), sum = fnv1a64(payload.data(), payload.size());
  std::memcpy(&rec[0], &kMagic, 4);
  std::memcpy(&rec[4], &type, 4);
  std::memcpy(&rec[8], &len, 8);
  if (!payload.empty()) std::memcpy(&rec[16], payload.data(), payload.size());
  std::memcpy(&rec[16 + payload.size()], &sum, 8);
  std::size_t done = 0;
  while (done < rec.size()) {
    const ssize_t w = ::write(fd_, rec.data() + done, rec.size() - done);
    if (w < 0 && errno == EINTR) continue;
    // A system_error with the cause's errno: a full disk is the output place's fault, and the CLI
    // says so with exit 2 (tools/cli/main.cpp); the records already written stay for --resume.
    if (w <= 0) throw std::system_error(w < 0 ? errno : EIO, std::generic_category(), "cannot append to the sweep journal " + path_.string());
    done += static_cast<std::size_t>(w);
  }
  write_wall_s_ += now_s() - start;
  if (now_s() - last_sync_s_ >= sync_interval_s_) {
    last_sync_s_ = now_s();
    request_sync();
  }
}

void SweepJournal::append(const RowBatch& b) { write_record(kRows, encode(b)); }

void SweepJournal::sync_or_record() {
  // EINVAL, ENOSYS: the file system offers no sync (some FUSE and network ones), as before the
  // sync's result was checked; EINTR: tried again. Anything else (EIO, ENOSPC, EDQUOT) is kept.
  for (int tries = 0; tries < 3; ++tries) {
    if (::fdatasync(fd_) == 0) return;
    const int e = errno;
    if (e == EINVAL || e == ENOSYS) return;
    if (e != EINTR) {
      sync_errno_.store(e);
      return;
    }
  }
}

void SweepJournal::sync() {
  sync_or_record();
  last_sync_s_ = now_s();
  throw_if_sync_failed();
}

void SweepJournal::close_and_remove() {
  stop_syncing();
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  std::error_code ec;
  fs::remove(path_, ec);
}

}  // namespace stoneskip
