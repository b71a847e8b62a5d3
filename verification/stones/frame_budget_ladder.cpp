#include "verification/stones/frame_budget_ladder.hpp"

#include "verification/stones/work_precision_grid_stats.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "verification/stones/parallel_runs.hpp"

namespace stoneskip {

bool FrameBudgetLadderOptions::valid(std::string* why) const {
  auto fail = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (rhs_per_frame.empty()) return fail("the budget ladder needs at least one budget");
  for (long n : rhs_per_frame)
    if (n < 4) return fail("a budget must allow at least 4 right-hand sides per frame (one bs32 step and its retry)");
  if (!std::is_sorted(rhs_per_frame.begin(), rhs_per_frame.end())) return fail("the budgets must ascend");
  if (!(frame_dt_s > 0)) return fail("frame_dt_s must be > 0");
  if (workers < 1) return fail("workers must be >= 1");
  return true;
}

double FrameBudgetRung::match_fraction() const { return compared > 0 ? double(matched) / compared : std::nan(""); }

void count_budget_matches(FrameBudgetRung& rung, const std::vector<int>& reference) {
  rung.compared = rung.matched = 0;
  for (std::size_t i = 0; i < reference.size() && i < rung.bounces.size(); ++i) {
    // A rung's failed run (−1: a state that ran away under forced steps, say) did not give the
    // reference's count: compared, not matched.
    if (reference[i] < 0) continue;
    ++rung.compared;
    if (rung.bounces[i] == reference[i]) ++rung.matched;
  }
}

std::vector<FrameBudgetRung> run_frame_budget_ladder(const std::vector<ThrowProblem>& throws,
                                                     const std::vector<int>& reference_bounces,
                                                     const FrameBudgetLadderOptions& o) {
  std::string why;
  if (!o.valid(&why)) throw std::invalid_argument("frame budget ladder: " + why);
  std::vector<FrameBudgetRung> rungs;
  for (long n : o.rhs_per_frame) {
    FrameBudgetRung rung;
    rung.rhs_per_frame = n;
    std::vector<ThrowResult> results(throws.size());
    parallel_for(
        throws.size(),
        [&](std::size_t i) {
          RealtimeOptions ro = throws[i].realtime;
          if (!is_adaptive(ro.scheme)) ro.scheme = Scheme::bs32;  // the throw's own adaptive pair, else bs32
          ro.rhs_per_frame = n;
          ro.frame_dt_s = o.frame_dt_s;
          ro.record_trajectory = false;
          results[i] = solve(throws[i], realtime_choice(ro));
        },
        ParallelOptions{o.workers, "budget " + std::to_string(n) + " right-hand sides per frame", o.progress});
    for (const ThrowResult& r : results) {
      rung.bounces.push_back(r.outcome == Outcome::failed ? -1 : r.bounces);
      rung.rhs_evaluations += r.stats.rhs_evaluations;
      rung.steps += r.stats.steps;
      rung.forced_steps += r.stats.budget_forced_steps;
      rung.frames += static_cast<long>(std::ceil(r.end_time_s / o.frame_dt_s - 1e-9));
      rung.cpu_s += r.stats.cpu_s;
      rung.max_error_ratio = std::max(rung.max_error_ratio, r.stats.max_error_ratio);
      rung.max_energy_gain_J = std::max(rung.max_energy_gain_J, r.max_energy_gain_J);
      if (r.max_energy_gain_J > 0) ++rung.throws_gaining_energy;
    }
    count_budget_matches(rung, reference_bounces);
    rungs.push_back(rung);
  }
  return rungs;
}

long smallest_budget_meeting(const std::vector<FrameBudgetRung>& rungs, double target) {
  long found = -1;
  for (auto it = rungs.rbegin(); it != rungs.rend(); ++it) {
    // The 95 % Wilson interval's lower end, not the point estimate: 310 of 314 (0.987) does not
    // show 0.98 (its interval reaches 0.968). Nothing compared: [0, 1], which does not meet it.
    const double low = wilson_interval(static_cast<int>(it->matched), static_cast<int>(it->compared)).low;
    if (!(low >= target)) break;
    found = it->rhs_per_frame;
  }
  return found;
}

}  // namespace stoneskip
