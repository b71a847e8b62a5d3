#pragma once
// Where a study puts its findings, section by section, as each finishes: a report's work folder
// (reports/common/report_build.hpp) stores each section at once, so a run killed late keeps what
// it finished, and a later run with the same settings resumes from it; a test keeps them in memory.
// Studies (verification/) see only this interface: they never know about folders or files.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "verification/study/progress.hpp"
#include "verification/study/record.hpp"

namespace stoneskip {

class StudySink {
 public:
  virtual ~StudySink() = default;
  // The record of a section that an earlier run with the same settings finished, if any.
  virtual std::optional<Record> resume(const std::string& section) = 0;
  virtual void store(const std::string& section, const Record& record) = 0;
  // How long work is shown (may be empty).
  virtual const ProgressFactory& progress() const = 0;
};

// Keeps sections in memory (tests, and studies run inside other studies).
class MemorySink : public StudySink {
 public:
  explicit MemorySink(ProgressFactory progress = {}) : progress_(std::move(progress)) {}
  std::optional<Record> resume(const std::string&) override { return std::nullopt; }
  void store(const std::string& section, const Record& record) override;
  const ProgressFactory& progress() const override { return progress_; }
  const Record& section(const std::string& name) const;  // RecordError if it was never stored
  const std::vector<std::string>& order() const { return order_; }

 private:
  ProgressFactory progress_;
  std::map<std::string, Record> sections_;
  std::vector<std::string> order_;
};

// Runs `compute` for section `name` unless the sink resumes it, adds the section's cost (child
// "cost": wall_s, and cpu_s = the process's CPU time, every thread of it, over the section) and
// stores it. Returns the record (computed or resumed).
Record run_section(StudySink& sink, const std::string& name, const std::function<Record()>& compute);

}  // namespace stoneskip
