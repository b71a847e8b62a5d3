#pragma once
// One throw of a sweep as one row of doubles: the columns of a sweep's /throws table and how a
// throw's results fill them. Everything in a row is a pure function of the throw (its index, its
// varied values, the solvers' results) except the columns whose names begin with "cost_" (what it
// cost, where it ran), so the table of a sweep is the same bits whatever ran it.
//
// Columns, in order:
//   throw                                  the throw's index in the design
//   <varied key> ...                       e.g. "throw.speed_m_s": the value the throw used
//   <solver>_bounces, _outcome, _contacts  per solver ("realtime", "reference"); outcome codes
//                                          below (kOutcomeCodes)
//   <solver>_distance_m, _lateral_m, _end_time_s, _max_energy_gain_J
//   <solver>_first_contact_start_s, _end_s, _entry_speed_m_s, _exit_speed_m_s,
//            _entry_path_angle_deg, _entry_attack_angle_deg        NaN when there was no contact
//   <solver>_steps, _contact_steps, _rhs_evaluations, _root_evaluations, _error_test_failures,
//            _nonlinear_iterations, _segments                       solver statistics
//   <solver>_bounces_before_short_flight   bounces followed by a flight shorter than
//                                          shortest_resolved_flight_s: those the stone's N-gon
//                                          rim may not resolve (model/README.md §1.8; counted
//                                          in _bounces all the same); NaN where not assessed
//   shortest_resolved_flight_s             τ_δ = 2 √(2δ/g), δ = R (1 − cos(π/N)) the rim's
//                                          sagitta (tools/scene/throw_output.hpp); NaN for an
//                                          OBJ mesh or without gravity
//   disagreement_*                         both solvers only: real-time minus reference
//                                          (bounces, contacts, distance_m, lateral_m,
//                                          first_contact_start_s) and the contact comparison
//                                          (missed_contacts, spurious_contacts,
//                                          max_start_error_s, max_exit_speed_error_m_s); NaN
//                                          where either solve failed (its counts are those at
//                                          the failure, not a result)
//   cost_setup_wall_s                      building the throw's case from the base + overrides
//   cost_<solver>_wall_s, cost_<solver>_cpu_s  the solve: wall, and CPU of the thread
//   cost_rank, cost_thread                 which process (MPI rank) and thread computed it
//   cost_start_unix_s                      when it started (seconds since 1970, system clock)
#include <cstdint>
#include <string>
#include <vector>

#include "solvers/realtime/throw_result.hpp"

namespace stoneskip {

enum class SweepSolvers { realtime, reference, both };
const char* to_string(SweepSolvers s);
bool runs_realtime(SweepSolvers s);
bool runs_reference(SweepSolvers s);
std::vector<std::string> solver_names(SweepSolvers s);  // {"realtime"}, {"reference"} or both, in column order

// Outcome codes of the <solver>_outcome columns; kOutcomeNotRun: the throw's case could not be
// built (its other columns are NaN and a note says why).
constexpr double kOutcomeSank = 0, kOutcomeTimeLimit = 1, kOutcomeFailed = 2, kOutcomeNotRun = 3;
constexpr const char* kOutcomeCodes = "0=sank,1=time_limit,2=failed,3=not_run";
double outcome_code(Outcome o);
// True for the <solver>_outcome columns.
bool is_outcome_column(const std::string& column);

// Where a throw ran and what it cost (not part of the result proper).
struct SweepThrowCost {
  double setup_wall_s = 0;
  double realtime_cpu_s = 0, reference_cpu_s = 0;
  int rank = 0, thread = 0;
  double start_unix_s = 0;  // when the throw started (system clock): a timeline of the run
};

// A throw that needs words: a failed solve, a case that could not be built, a contact begun off
// a walled pond.
struct ThrowNote {
  std::uint64_t throw_index = 0;
  std::string solver;     // "realtime", "reference" or "case"
  std::string detail;
};

class ThrowRecord {
 public:
  ThrowRecord(std::vector<std::string> varied_keys, SweepSolvers solvers);
  const std::vector<std::string>& columns() const { return columns_; }
  // The columns of a table written before the short-flight columns were added (5 December 2026):
  // columns() without <solver>_bounces_before_short_flight and shortest_resolved_flight_s.
  std::vector<std::string> columns_without_short_flights() const;
  std::size_t width() const { return columns_.size(); }
  bool is_cost_column(std::size_t c) const;

  // The row of a solved throw (rt / ref null when that solver did not run); appends notes for
  // failed solves. shortest_resolved_flight_s: the throw's stone's τ_δ (NaN: not assessed).
  std::vector<double> row(std::uint64_t throw_index, const std::vector<double>& point, const ThrowResult* rt,
                          const ThrowResult* ref, const SweepThrowCost& cost, double shortest_resolved_flight_s,
                          std::vector<ThrowNote>& notes) const;
  // The row of a throw whose case could not be built: outcome kOutcomeNotRun, NaN elsewhere.
  std::vector<double> not_run_row(std::uint64_t throw_index, const std::vector<double>& point, const SweepThrowCost& cost) const;

 private:
  std::vector<std::string> varied_;
  SweepSolvers solvers_;
  std::vector<std::string> columns_;
};

}  // namespace stoneskip
