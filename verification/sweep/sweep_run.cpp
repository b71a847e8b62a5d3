#include "verification/sweep/sweep_run.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <thread>

#include "stoneskip_version.hpp"
#include "tools/io/atomic_file.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/usable_cores.hpp"

namespace stoneskip {

namespace fs = std::filesystem;

ThrowRecord sweep_record(const SweepDesign& design, SweepSolvers solvers) {
  std::vector<std::string> keys;
  for (const auto& a : design.axes) keys.push_back(a.key);
  return ThrowRecord(keys, solvers);
}

namespace {

std::string joined(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
  return s;
}

// FNV-1a of this process's executable: the build that computes the rows (the git version is
// taken when CMake configures, so it misses a rebuild after an edit; the bytes do not).
std::string executable_fingerprint() {
  std::ifstream f("/proc/self/exe", std::ios::binary);
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  char hex[20];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a64(bytes.data(), bytes.size())));
  return hex;
}

// The build that computes the rows: its version and its executable's bytes.
std::string build_of_this_process() {
  return std::string(kVersion) + " (git " + kGitDescribe + "), executable " + executable_fingerprint();
}

// What a journal must match to be resumed: everything that decides a row's bits.
JournalIdentity identity_of(const SweepData& d) {
  return {{"sweep_text", d.provenance.sweep_text},
          {"base_case_text", d.provenance.base_case_text},
          {"base_overrides", joined(d.provenance.base_overrides, "\n")},
          {"code_version", std::string(kVersion) + " (git " + kGitDescribe + ")"},
          {"executable", executable_fingerprint()},
          {"input_files", d.provenance.input_files},
          {"columns", joined(d.throws.columns, ",")},
          {"throws", std::to_string(d.design.size())}};
}

bool same_sweep(const SweepData& a, const SweepData& b) {
  return a.provenance.sweep_text == b.provenance.sweep_text && a.provenance.base_case_text == b.provenance.base_case_text &&
         a.provenance.input_files == b.provenance.input_files && a.provenance.build == b.provenance.build &&
         a.provenance.base_overrides == b.provenance.base_overrides && a.throws.columns == b.throws.columns &&
         a.throws.rows() == b.design.size();
}

}  // namespace

std::string SweepSummary::brief() const {
  std::ostringstream s;
  if (was_complete) {
    s << out.string() << " is already complete (" << throws << " throws): nothing to compute";
    return s.str();
  }
  s << "wrote " << out.string() << ": " << throws << (throws == 1 ? " throw (" : " throws (") << computed << " computed";
  if (recovered) s << ", " << recovered << " recovered from the journal";
  s << ")";
  if (failed_solves) s << ", " << failed_solves << " failed solves";
  if (not_run) s << ", " << not_run << " throws whose case could not be built";
  if (noted) s << ", " << noted << (noted == 1 ? " throw" : " throws") << " with notes (sweep-plot lists them)";
  s.precision(3);
  s << "; " << schedule.ranks << (schedule.ranks == 1 ? " rank" : " ranks") << ", " << schedule.master_threads
    << " compute thread" << (schedule.master_threads == 1 ? "" : "s") << " on rank 0, " << schedule.wall_s << " s wall";
  if (schedule.wall_s > 0 && computed) s << ", " << computed / schedule.wall_s << " throws/s";
  return s.str();
}

SweepPlan SweepPlan::prepare(const SweepData& spec, const SweepRunOptions& options) {
  { AtomicOutput check(options.out); }  // the folder exists and is writable; out is not a folder
  SweepPlan plan;
  plan.data_ = spec;
  plan.data_.provenance.build = build_of_this_process();
  plan.options_ = options;
  const ThrowRecord record = sweep_record(spec.design, spec.solvers);
  const std::size_t total = spec.design.size(), width = record.width();
  plan.data_.throws.columns = record.columns();
  plan.data_.throws.values.assign(total * width, std::numeric_limits<double>::quiet_NaN());
  plan.data_.notes.clear();
  plan.have_.assign(total, false);
  const fs::path jp = journal_path_for(options.out);
  const JournalIdentity identity = identity_of(plan.data_);
  std::error_code ec;
  // Only a regular file can be a journal: a link (to anything, or dangling), a folder or a FIFO at
  // its name is nobody's interrupted sweep, and stoneskip writes through no link. Said first, so
  // that neither the "interrupted" advice nor --resume's refusal comes before it.
  struct stat jst {};
  if (::lstat(jp.c_str(), &jst) == 0 && !S_ISREG(jst.st_mode))
    throw_input_error(jp.string(), 0, "",
                      "is " + file_type_words(jst.st_mode) + ", not a sweep journal: move it away and run again");
  bool journal_exists = fs::exists(jp, ec);
  const bool journal_found = journal_exists;
  if (journal_exists && journal_in_use(jp))
    throw_input_error(jp.string(), 0, "",
                      "another sweep is running into this file now (it holds the journal's lock): wait for it to finish, "
                      "or stop it and run again with --resume");
  // A journal whose header was never completed holds no finished throw (a sweep killed as it
  // started): with --resume it is replaced, and the sweep starts afresh as with no journal.
  if (options.resume && journal_exists && remove_journal_with_torn_header(jp)) {
    plan.warnings_.push_back(jp.string() + ": holds no finished throw (empty, or its header cut short by a sweep "
                             "killed as it started): replaced, and the sweep starts afresh");
    journal_exists = false;
  }
  if (!options.resume && journal_exists)
    throw_input_error(jp.string(), 0, "",
                      "the journal of an interrupted sweep is here: finish it with --resume, or delete it to start again");
  if (options.resume && journal_exists) {
    JournalRecovery rec;
    plan.journal_ = std::make_unique<SweepJournal>(SweepJournal::resume(jp, identity, options.sync_interval_s, rec));
    if (rec.rows.rows() > 0 && rec.rows.width != width)
      throw_input_error(jp.string(), 0, "", "its rows do not have this sweep's columns");
    plan.take(rec.rows);
    if (rec.damaged_records > 0) {
      plan.warnings_.push_back(jp.string() + ": a damaged record (" + std::to_string(rec.dropped_bytes) + " bytes cut, " +
                               std::to_string(rec.damaged_records) +
                               " whole records after it dropped): their throws are computed again");
      plan.data_.run.journal_damage = plan.warnings_.back();  // stored with the result, /run
    }
    plan.recovered_ = static_cast<std::size_t>(std::count(plan.have_.begin(), plan.have_.end(), true));
  } else if (options.resume && fs::exists(options.out, ec)) {
    const SweepData old = read_sweep_file(options.out);
    if (old.provenance.build != plan.data_.provenance.build && same_sweep(old, [&] {
          SweepData d = plan.data_;
          d.provenance.build = old.provenance.build;
          return d;
        }()))
      throw_input_error(options.out.string(), 0, "",
                        "was computed by another build (" + (old.provenance.build.empty() ? std::string("unrecorded") : old.provenance.build) +
                            "): run without --resume to compute it with this one");
    if (!same_sweep(old, plan.data_))
      throw_input_error(options.out.string(), 0, "",
                        "exists, has no journal and is not this sweep's result: nothing to resume (run without --resume to replace it)");
    plan.was_complete_ = true;
    plan.have_.assign(total, true);
    return plan;
  } else {
    // --resume with nothing to resume from (no journal, no result): said, then started afresh.
    if (options.resume && !journal_found)
      plan.warnings_.push_back(jp.string() + ": no journal and no result to resume from: the sweep starts afresh");
    plan.journal_ = std::make_unique<SweepJournal>(SweepJournal::create(jp, identity, options.sync_interval_s));
  }
  for (std::size_t i = 0; i < total; ++i)
    if (!plan.have_[i]) plan.pending_.push_back(i);
  return plan;
}

void SweepPlan::take(const RowBatch& b) {
  const std::size_t width = data_.throws.columns.size();
  for (std::size_t r = 0; r < b.rows(); ++r) {
    const std::uint64_t i = b.throw_index(r);
    if (i >= have_.size()) throw std::runtime_error("sweep: a row for throw " + std::to_string(i) + " beyond the design");
    if (have_[i]) continue;
    std::copy_n(b.values.begin() + static_cast<std::ptrdiff_t>(r * width), width,
                data_.throws.values.begin() + static_cast<std::ptrdiff_t>(i * width));
    have_[i] = true;
  }
  data_.notes.insert(data_.notes.end(), b.notes.begin(), b.notes.end());
}

SweepSummary SweepPlan::run(const ThrowEvaluator& evaluate, MpiSession& mpi) {
  SweepSummary summary;
  summary.out = options_.out;
  summary.throws = data_.design.size();
  summary.recovered = recovered_;
  summary.was_complete = was_complete_;
  summary.warnings = warnings_;
  std::unique_ptr<ProgressTicker> progress;
  if (!pending_.empty()) progress = start_progress(options_.progress, "sweep", pending_.size());
  const BatchSink sink = [&](const RowBatch& b) {
    journal_->append(b);
    take(b);
    if (progress) progress->tick(b.rows());
  };
  ScheduleOptions so;
  so.max_chunk = options_.max_chunk;
  so.master_threads = options_.master_threads >= 0 ? options_.master_threads
                      : mpi.size() > 1              ? 1
                                                    : usable_cores();
  summary.schedule = run_master(pending_, data_.throws.columns.size(), evaluate, sink, so, mpi);
  progress.reset();
  summary.computed = summary.schedule.throws;
  if (was_complete_) return summary;

  const auto missing = std::count(have_.begin(), have_.end(), false);
  if (missing) throw std::runtime_error("sweep: " + std::to_string(missing) + " throws missing at the end");
  // Notes in throw order, whatever order they arrived in (a throw's own notes in the order made).
  std::stable_sort(data_.notes.begin(), data_.notes.end(), [](const ThrowNote& a, const ThrowNote& b) {
    return a.throw_index != b.throw_index ? a.throw_index < b.throw_index : a.solver < b.solver;
  });
  journal_->sync();
  data_.run.schedule = summary.schedule;
  data_.run.throws_recovered = recovered_;
  data_.run.journal_wall_s = journal_->write_wall_s();
  data_.run.max_chunk = options_.max_chunk;
  write_sweep_file(options_.out, data_);
  journal_->close_and_remove();
  const Table& t = data_.throws;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    bool not_run = false;
    for (std::size_t c = 0; c < t.columns.size(); ++c) {
      if (!is_outcome_column(t.columns[c])) continue;
      const double v = t.values[r * t.columns.size() + c];
      summary.failed_solves += v == kOutcomeFailed ? 1 : 0;
      not_run = not_run || v == kOutcomeNotRun;
    }
    summary.not_run += not_run ? 1 : 0;
  }
  for (std::size_t k = 0; k < data_.notes.size(); ++k)
    summary.noted += k == 0 || data_.notes[k].throw_index != data_.notes[k - 1].throw_index ? 1 : 0;
  return summary;
}

}  // namespace stoneskip
