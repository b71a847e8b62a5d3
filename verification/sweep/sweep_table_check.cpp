#include "verification/sweep/sweep_table_check.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "tools/io/input_error.hpp"

namespace stoneskip {

namespace {

std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// A count as the record writes it: a whole number, 0 or more, below 2⁵³ (exact in a double).
bool is_count(double v) { return v >= 0 && v < 9007199254740992.0 && v == std::floor(v); }

bool is_outcome_code(double v) {
  return v == kOutcomeSank || v == kOutcomeTimeLimit || v == kOutcomeFailed || v == kOutcomeNotRun;
}

}  // namespace

void check_sweep_table(const std::string& file, const SweepDesign& design, SweepSolvers solvers, const Table& t) {
  std::vector<std::string> keys;
  for (const auto& a : design.axes) keys.push_back(a.key);
  const ThrowRecord record(keys, solvers);
  // Tables written before 5 December 2026 lack the short-flight columns (throw_record.hpp): read
  // as they are, those columns unchecked.
  const std::vector<std::string> older = record.columns_without_short_flights();
  const bool is_older = t.columns == older;
  const std::vector<std::string>& want = is_older ? older : record.columns();
  if (t.columns.size() != want.size())
    throw_input_error(file, 0, "throws", "has " + std::to_string(t.columns.size()) + " columns; a sweep of these axes with solvers " +
                                             to_string(solvers) + " writes " + std::to_string(want.size()));
  for (std::size_t c = 0; c < want.size(); ++c)
    if (t.columns[c] != want[c])
      throw_input_error(file, 0, "throws", "column " + std::to_string(c) + " is '" + t.columns[c] + "' where a sweep writes '" +
                                               want[c] + "'");
  const std::size_t width = want.size(), rows = t.rows();
  auto column_of = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(want.begin(), want.end(), name) - want.begin());
  };
  struct SolverColumns {
    std::string name;
    std::size_t outcome, bounces, contacts, short_flights;  // short_flights: width in an older table
  };
  std::vector<SolverColumns> solver_columns;
  for (const auto& s : solver_names(solvers))
    solver_columns.push_back({s, column_of(s + "_outcome"), column_of(s + "_bounces"), column_of(s + "_contacts"),
                              column_of(s + "_bounces_before_short_flight")});
  const std::size_t tau = column_of("shortest_resolved_flight_s");
  const bool both = solvers == SweepSolvers::both;
  const std::size_t d_bounces = both ? column_of("disagreement_bounces") : 0;
  const std::size_t d_contacts = both ? column_of("disagreement_contacts") : 0;

  for (std::size_t i = 0; i < rows; ++i) {
    const double* row = t.values.data() + i * width;
    auto fail = [&](std::size_t c, const std::string& what) {
      throw_input_error(file, 0, "throws." + want[c], "throw " + std::to_string(i) + ": " + what);
    };
    if (row[0] != static_cast<double>(i))
      fail(0, "the row holds throw " + number(row[0]) + " (rows are in throw-index order)");
    const std::vector<double> p = design.point(i);
    for (std::size_t k = 0; k < p.size(); ++k) {
      // The value the throw used is the design's, written as computed; a relative 1e-12 leaves room
      // for another machine's rounding of a logarithmic axis, nothing for an edit.
      const double v = row[1 + k];
      if (!(std::abs(v - p[k]) <= 1e-12 * std::max({std::abs(p[k]), std::abs(design.axes[k].from), std::abs(design.axes[k].to)})))
        fail(1 + k, number(v) + " is not the design's value " + number(p[k]));
    }
    bool ran = true;
    for (const SolverColumns& s : solver_columns) {
      const double o = row[s.outcome], b = row[s.bounces], n = row[s.contacts];
      if (!is_outcome_code(o)) fail(s.outcome, number(o) + " is not an outcome code (" + kOutcomeCodes + ")");
      if (o == kOutcomeNotRun) {
        ran = false;
        if (!std::isnan(b)) fail(s.bounces, number(b) + " for a throw that did not run (NaN expected)");
        if (!std::isnan(n)) fail(s.contacts, number(n) + " for a throw that did not run (NaN expected)");
        if (s.short_flights < width && !std::isnan(row[s.short_flights]))
          fail(s.short_flights, number(row[s.short_flights]) + " for a throw that did not run (NaN expected)");
        continue;
      }
      if (!is_count(b)) fail(s.bounces, number(b) + " is not a count (a whole number, 0 or more)");
      if (!is_count(n)) fail(s.contacts, number(n) + " is not a count (a whole number, 0 or more)");
      if (b > n) fail(s.bounces, number(b) + " bounces in " + number(n) + " contacts (each bounce ends a contact)");
      if (s.short_flights < width) {
        // A subset of the bounces where the stone's τ_δ is assessed, NaN exactly where it is not.
        const double f = row[s.short_flights];
        if (std::isnan(row[tau]) != std::isnan(f))
          fail(s.short_flights, number(f) + " where shortest_resolved_flight_s is " + number(row[tau]) +
                                    " (NaN exactly where it is NaN)");
        if (!std::isnan(f) && !(is_count(f) && f <= b))
          fail(s.short_flights, number(f) + " is not a count of at most the " + number(b) + " bounces");
      }
    }
    if (both && ran) {
      const SolverColumns &rt = solver_columns[0], &ref = solver_columns[1];
      if (row[rt.outcome] == kOutcomeFailed || row[ref.outcome] == kOutcomeFailed) {
        // No disagreement for a failed solve: NaN (tables written before this rule hold the difference).
        const double bounces = row[rt.bounces] - row[ref.bounces], contacts = row[rt.contacts] - row[ref.contacts];
        if (!std::isnan(row[d_bounces]) && row[d_bounces] != bounces)
          fail(d_bounces, number(row[d_bounces]) + " for a throw whose solve failed (NaN expected)");
        if (!std::isnan(row[d_contacts]) && row[d_contacts] != contacts)
          fail(d_contacts, number(row[d_contacts]) + " for a throw whose solve failed (NaN expected)");
        continue;
      }
      if (row[d_bounces] != row[rt.bounces] - row[ref.bounces])
        fail(d_bounces, number(row[d_bounces]) + " is not realtime_bounces − reference_bounces (" +
                            number(row[rt.bounces] - row[ref.bounces]) + ")");
      if (row[d_contacts] != row[rt.contacts] - row[ref.contacts])
        fail(d_contacts, number(row[d_contacts]) + " is not realtime_contacts − reference_contacts (" +
                             number(row[rt.contacts] - row[ref.contacts]) + ")");
    }
  }
}

}  // namespace stoneskip
