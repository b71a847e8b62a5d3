#include "verification/study/study_sink.hpp"

#include <chrono>
#include <ctime>

namespace stoneskip {

namespace {
double process_cpu_s() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}
}  // namespace

void MemorySink::store(const std::string& section, const Record& record) {
  if (!sections_.count(section)) order_.push_back(section);
  sections_[section] = record;
}

const Record& MemorySink::section(const std::string& name) const {
  auto it = sections_.find(name);
  if (it == sections_.end()) throw RecordError("no section '" + name + "' was stored");
  return it->second;
}

Record run_section(StudySink& sink, const std::string& name, const std::function<Record()>& compute) {
  if (auto done = sink.resume(name)) return *done;
  const auto wall0 = std::chrono::steady_clock::now();
  const double cpu0 = process_cpu_s();
  Record r = compute();
  Record& cost = r.child("cost");
  cost.set("wall_s", std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count());
  cost.set("cpu_s", process_cpu_s() - cpu0);
  sink.store(name, r);
  return r;
}

}  // namespace stoneskip
