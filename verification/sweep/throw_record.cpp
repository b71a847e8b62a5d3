#include "verification/sweep/throw_record.hpp"

#include <cmath>
#include <functional>
#include <limits>

#include "verification/stones/contact_comparison.hpp"

namespace stoneskip {

const char* to_string(SweepSolvers s) {
  switch (s) {
    case SweepSolvers::realtime: return "realtime";
    case SweepSolvers::reference: return "reference";
    case SweepSolvers::both: return "realtime,reference";
  }
  return "?";
}
bool runs_realtime(SweepSolvers s) { return s != SweepSolvers::reference; }
bool runs_reference(SweepSolvers s) { return s != SweepSolvers::realtime; }

std::vector<std::string> solver_names(SweepSolvers s) {
  std::vector<std::string> names;
  if (runs_realtime(s)) names.push_back("realtime");
  if (runs_reference(s)) names.push_back("reference");
  return names;
}

double outcome_code(Outcome o) {
  switch (o) {
    case Outcome::sank: return kOutcomeSank;
    case Outcome::time_limit: return kOutcomeTimeLimit;
    case Outcome::failed: return kOutcomeFailed;
  }
  return kOutcomeFailed;
}

bool is_outcome_column(const std::string& c) {
  static const std::string suffix = "_outcome";
  return c.size() > suffix.size() && c.compare(c.size() - suffix.size(), suffix.size(), suffix) == 0;
}

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using Extract = std::function<double(const ThrowResult&)>;
struct Field {
  const char* name;
  Extract value;
};

double first(const ThrowResult& r, double ContactRecord::*member) {
  return r.contacts.empty() ? kNaN : r.contacts.front().*member;
}

// Per-solver columns: "<solver>_<name>". One list for the names and the values.
const std::vector<Field>& solver_fields() {
  static const std::vector<Field> fields = {
      {"bounces", [](const ThrowResult& r) { return double(r.bounces); }},
      {"outcome", [](const ThrowResult& r) { return outcome_code(r.outcome); }},
      {"contacts", [](const ThrowResult& r) { return double(r.contacts.size()); }},
      {"distance_m", [](const ThrowResult& r) { return r.distance_m; }},
      {"lateral_m", [](const ThrowResult& r) { return r.lateral_m; }},
      {"end_time_s", [](const ThrowResult& r) { return r.end_time_s; }},
      {"max_energy_gain_J", [](const ThrowResult& r) { return r.max_energy_gain_J; }},
      {"first_contact_start_s", [](const ThrowResult& r) { return first(r, &ContactRecord::start_s); }},
      {"first_contact_end_s", [](const ThrowResult& r) { return first(r, &ContactRecord::end_s); }},
      {"first_contact_entry_speed_m_s", [](const ThrowResult& r) { return first(r, &ContactRecord::entry_speed_m_s); }},
      {"first_contact_exit_speed_m_s", [](const ThrowResult& r) { return first(r, &ContactRecord::exit_speed_m_s); }},
      {"first_contact_entry_path_angle_deg",
       [](const ThrowResult& r) { return first(r, &ContactRecord::entry_path_angle_deg); }},
      {"first_contact_entry_attack_angle_deg",
       [](const ThrowResult& r) { return first(r, &ContactRecord::entry_attack_angle_deg); }},
      {"steps", [](const ThrowResult& r) { return double(r.stats.steps); }},
      {"contact_steps", [](const ThrowResult& r) { return double(r.stats.contact_steps); }},
      {"rhs_evaluations", [](const ThrowResult& r) { return double(r.stats.rhs_evaluations); }},
      {"root_evaluations", [](const ThrowResult& r) { return double(r.stats.root_evaluations); }},
      {"error_test_failures", [](const ThrowResult& r) { return double(r.stats.error_test_failures); }},
      {"nonlinear_iterations", [](const ThrowResult& r) { return double(r.stats.nonlinear_iterations); }},
      {"segments", [](const ThrowResult& r) { return double(r.stats.segments); }},
  };
  return fields;
}

using Compare = std::function<double(const ThrowResult& rt, const ThrowResult& ref, const ContactComparison& c)>;
struct Disagreement {
  const char* name;
  Compare value;
};

// Real-time against reference, per throw (verification/stones/contact_comparison.hpp).
const std::vector<Disagreement>& disagreement_fields() {
  static const std::vector<Disagreement> fields = {
      {"bounces", [](const ThrowResult& a, const ThrowResult& b, const ContactComparison&) { return double(a.bounces - b.bounces); }},
      {"contacts", [](const ThrowResult& a, const ThrowResult& b, const ContactComparison&) {
         return double(a.contacts.size()) - double(b.contacts.size());
       }},
      {"distance_m", [](const ThrowResult& a, const ThrowResult& b, const ContactComparison&) { return a.distance_m - b.distance_m; }},
      {"lateral_m", [](const ThrowResult& a, const ThrowResult& b, const ContactComparison&) { return a.lateral_m - b.lateral_m; }},
      {"first_contact_start_s", [](const ThrowResult& a, const ThrowResult& b, const ContactComparison&) {
         return first(a, &ContactRecord::start_s) - first(b, &ContactRecord::start_s);
       }},
      {"missed_contacts", [](const ThrowResult&, const ThrowResult&, const ContactComparison& c) { return double(c.missed); }},
      {"spurious_contacts", [](const ThrowResult&, const ThrowResult&, const ContactComparison& c) { return double(c.spurious); }},
      {"max_start_error_s", [](const ThrowResult&, const ThrowResult&, const ContactComparison& c) { return c.max_start_error_s; }},
      {"max_exit_speed_error_m_s",
       [](const ThrowResult&, const ThrowResult&, const ContactComparison& c) { return c.max_exit_speed_error_m_s; }},
  };
  return fields;
}

const char* kCostPrefix = "cost_";

}  // namespace

ThrowRecord::ThrowRecord(std::vector<std::string> varied_keys, SweepSolvers solvers)
    : varied_(std::move(varied_keys)), solvers_(solvers) {
  columns_.push_back("throw");
  for (const auto& k : varied_) columns_.push_back(k);
  for (const auto& s : solver_names(solvers_)) {
    for (const auto& f : solver_fields()) columns_.push_back(s + "_" + f.name);
    columns_.push_back(s + "_bounces_before_short_flight");
  }
  columns_.push_back("shortest_resolved_flight_s");
  if (solvers_ == SweepSolvers::both)
    for (const auto& f : disagreement_fields()) columns_.push_back(std::string("disagreement_") + f.name);
  columns_.push_back("cost_setup_wall_s");
  for (const auto& s : solver_names(solvers_)) {
    columns_.push_back(std::string(kCostPrefix) + s + "_wall_s");
    columns_.push_back(std::string(kCostPrefix) + s + "_cpu_s");
  }
  columns_.push_back("cost_rank");
  columns_.push_back("cost_thread");
  columns_.push_back("cost_start_unix_s");
}

std::vector<std::string> ThrowRecord::columns_without_short_flights() const {
  std::vector<std::string> c;
  for (const auto& name : columns_)
    if (name != "shortest_resolved_flight_s" && name.find("_bounces_before_short_flight") == std::string::npos) c.push_back(name);
  return c;
}

bool ThrowRecord::is_cost_column(std::size_t c) const { return columns_.at(c).rfind(kCostPrefix, 0) == 0; }

std::vector<double> ThrowRecord::row(std::uint64_t throw_index, const std::vector<double>& point, const ThrowResult* rt,
                                     const ThrowResult* ref, const SweepThrowCost& cost, double shortest_resolved_flight_s,
                                     std::vector<ThrowNote>& notes) const {
  std::vector<double> r;
  r.reserve(columns_.size());
  r.push_back(static_cast<double>(throw_index));
  r.insert(r.end(), point.begin(), point.end());
  const std::vector<std::pair<const char*, const ThrowResult*>> runs = {{"realtime", rt}, {"reference", ref}};
  for (const auto& [name, result] : runs) {
    if (!result) continue;
    for (const auto& f : solver_fields()) r.push_back(f.value(*result));
    r.push_back(std::isnan(shortest_resolved_flight_s)
                    ? kNaN
                    : double(bounces_before_flight_shorter_than(result->contacts, shortest_resolved_flight_s)));
    if (result->outcome == Outcome::failed) notes.push_back({throw_index, name, result->outcome_detail});
  }
  r.push_back(shortest_resolved_flight_s);
  if (rt && ref) {
    // A failed run's counts and end are those at its failure, not its result: no disagreement
    // (NaN), as `run` says "not compared" for it.
    const bool failed = rt->outcome == Outcome::failed || ref->outcome == Outcome::failed;
    const ContactComparison c = compare_contacts(*rt, *ref);
    for (const auto& f : disagreement_fields())
      r.push_back(failed ? std::numeric_limits<double>::quiet_NaN() : f.value(*rt, *ref, c));
  }
  r.push_back(cost.setup_wall_s);
  // cost_<solver>_wall_s: the solve's own wall clock (SolverStats::wall_s); _cpu_s: the sweep's
  // thread CPU around it. Until December 5 the wall column held the solve's CPU time.
  if (rt) r.insert(r.end(), {rt->stats.wall_s, cost.realtime_cpu_s});
  if (ref) r.insert(r.end(), {ref->stats.wall_s, cost.reference_cpu_s});
  r.insert(r.end(), {double(cost.rank), double(cost.thread), cost.start_unix_s});
  return r;
}

std::vector<double> ThrowRecord::not_run_row(std::uint64_t throw_index, const std::vector<double>& point,
                                             const SweepThrowCost& cost) const {
  std::vector<double> r(columns_.size(), kNaN);
  r[0] = static_cast<double>(throw_index);
  for (std::size_t k = 0; k < point.size(); ++k) r[1 + k] = point[k];
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    if (is_outcome_column(columns_[c])) r[c] = kOutcomeNotRun;
    if (columns_[c] == "cost_setup_wall_s") r[c] = cost.setup_wall_s;
  }
  r[columns_.size() - 3] = cost.rank;
  r[columns_.size() - 2] = cost.thread;
  r[columns_.size() - 1] = cost.start_unix_s;
  return r;
}

}  // namespace stoneskip
