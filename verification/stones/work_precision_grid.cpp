#include "verification/stones/work_precision_grid.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

#include "verification/stones/contact_comparison.hpp"
#include "verification/stones/parallel_runs.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {

namespace {

struct Job {
  std::size_t throw_index;
  GridRun run;
  SolverChoice choice;
};

ReferenceOptions cvode_at(const ThrowProblem& p, ReferenceMethod m, double rtol, double atol_ratio) {
  ReferenceOptions r = p.reference;
  r.method = m;
  r.rtol = rtol;
  r.atol = atol_ratio * rtol;
  r.record_trajectory = false;
  return r;
}

}  // namespace

bool WorkPrecisionGridOptions::valid(std::string* why) const {
  auto fail = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (spins_rev_s.empty() || attack_angles_deg.empty()) return fail("the grid needs spins and attack angles");
  if (adaptive_rtol.empty()) return fail("the grid needs the adaptive family's tolerances");
  for (Scheme s : fixed_schemes)
    if (is_adaptive(s)) return fail(std::string("fixed_schemes: ") + to_string(s) + " is adaptive");
  if (!fixed_schemes.empty() && dt_s.empty()) return fail("fixed schemes need flight steps dt_s");
  if (!(contact_ratio > 0 && contact_ratio <= 1)) return fail("contact_ratio must be in (0, 1]");
  if (!(truth_rtol > 0) || !(truth_check_factor > 0) || !(atol_ratio > 0)) return fail("truth tolerances must be > 0");
  if (!(agreement_target > 0 && agreement_target <= 1)) return fail("agreement_target must be in (0, 1]");
  if (!(contact_time_threshold_s > 0)) return fail("contact_time_threshold_s must be > 0");
  for (long n : budget_rhs_per_frame)
    if (n < 4) return fail("budget_rhs_per_frame: a budget must allow at least 4 right-hand sides per frame");
  if (!(budget_frame_dt_s > 0)) return fail("budget_frame_dt_s must be > 0");
  if (workers < 1) return fail("workers must be >= 1");
  return true;
}

std::string adaptive_family_name(Scheme s) { return std::string(to_string(s)) + " (adaptive)"; }

std::string fixed_family_name(Scheme s, double contact_ratio) {
  return std::string(to_string(s)) + " (contact dt/" + std::to_string(static_cast<int>(std::lround(1 / contact_ratio))) + ")";
}

std::string cvode_family_name(ReferenceMethod m) { return std::string("CVODE ") + to_string(m); }

std::string budget_family_name(Scheme s, double frame_dt_s) {
  return std::string(to_string(s)) + " (budget per " + num(1e3 * frame_dt_s) + " ms frame)";
}

WorkPrecisionGridResult run_work_precision_grid(const ThrowProblem& base, const WorkPrecisionGridOptions& o) {
  std::string why;
  if (!o.valid(&why)) throw std::invalid_argument("work-precision grid: " + why);
  if (!base.from_parameters) throw std::invalid_argument("work-precision grid: the base case must give throw parameters");
  if (base.environment.convention != Convention::physical)
    throw std::invalid_argument("work-precision grid: the base throw must be in the physical convention");
  WorkPrecisionGridResult res;
  res.base_label = base.label;
  res.adaptive_family = adaptive_family_name(Scheme::bs32);
  if (!o.budget_rhs_per_frame.empty()) res.budget_family = budget_family_name(Scheme::bs32, o.budget_frame_dt_s);

  // 1. The grid's throws, spin-major.
  std::vector<ThrowProblem> problems;
  for (double spin : o.spins_rev_s)
    for (double attack : o.attack_angles_deg) {
      ThrowParameters tp = base.parameters;
      tp.spin_rev_s = spin;
      tp.attack_angle_deg = attack;
      problems.push_back(with_parameters(base, tp));
      GridThrow t;
      t.spin_rev_s = spin;
      t.attack_angle_deg = attack;
      t.label = num(spin) + " rev/s, α " + num(attack) + "°";
      problems.back().label = base.label + ", " + t.label;
      res.throws.push_back(t);
    }

  // 2. Two truths per throw (CVODE restarting at every event, as the work-precision study's truth).
  std::vector<ThrowResult> truths(problems.size()), checks(problems.size());
  {
    std::vector<std::function<void()>> jobs;
    for (std::size_t k = 0; k < problems.size(); ++k)
      for (int c = 0; c < 2; ++c)
        jobs.push_back([&, k, c] {
          ReferenceOptions r = cvode_at(problems[k], ReferenceMethod::bdf,
                                        o.truth_rtol * (c ? o.truth_check_factor : 1.0), o.atol_ratio);
          r.restart = RestartStrategy::every_event;
          (c ? checks[k] : truths[k]) = solve(problems[k], reference_choice(r));
        });
    run_jobs(jobs, ParallelOptions{o.workers, "stones: work-precision grid truths", o.progress});
  }
  for (std::size_t k = 0; k < problems.size(); ++k) {
    GridThrow& t = res.throws[k];
    t.truth_bounces = truths[k].bounces;
    t.check_bounces = checks[k].bounces;
    t.truth_rhs_evaluations = truths[k].stats.rhs_evaluations;
    t.truth_cpu_s = truths[k].stats.cpu_s;
    if (truths[k].outcome == Outcome::failed || checks[k].outcome == Outcome::failed) {
      t.set_aside = true;
      t.set_aside_reason = "truth failed: " + (truths[k].outcome == Outcome::failed ? truths[k] : checks[k]).outcome_detail;
      ++res.truth_failed;
    } else if (t.truth_bounces != t.check_bounces) {
      t.set_aside = true;
      t.set_aside_reason = "chaotic: the truth makes " + std::to_string(t.truth_bounces) + " bounces, its check " +
                           std::to_string(t.check_bounces);
      ++res.chaotic;
    }
  }

  // 3. Every family at every setting on every throw kept.
  std::vector<Job> jobs;
  for (std::size_t k = 0; k < problems.size(); ++k) {
    if (res.throws[k].set_aside) continue;
    auto add = [&](const std::string& family, double setting, const SolverChoice& choice) {
      Job j;
      j.throw_index = k;
      j.run.family = family;
      j.run.setting = setting;
      j.run.throw_label = res.throws[k].label;
      j.choice = choice;
      jobs.push_back(j);
    };
    for (double tol : o.adaptive_rtol) {
      RealtimeOptions ro = problems[k].realtime;
      ro.scheme = Scheme::bs32;
      ro.rtol = ro.atol_m = tol;
      ro.record_trajectory = false;
      add(res.adaptive_family, tol, realtime_choice(ro));
    }
    for (long n : o.budget_rhs_per_frame) {
      RealtimeOptions ro = problems[k].realtime;
      ro.scheme = Scheme::bs32;
      ro.rtol = ro.atol_m = kDefaultAdaptiveTolerance;
      ro.rhs_per_frame = n;
      ro.frame_dt_s = o.budget_frame_dt_s;
      ro.record_trajectory = false;
      add(res.budget_family, double(n), realtime_choice(ro));
    }
    for (Scheme s : o.fixed_schemes)
      for (double dt : o.dt_s) {
        RealtimeOptions ro = problems[k].realtime;
        ro.scheme = s;
        ro.dt_s = dt;
        ro.contact_dt_s = o.contact_ratio * dt;
        ro.record_trajectory = false;
        add(fixed_family_name(s, o.contact_ratio), dt, realtime_choice(ro));
      }
    for (double rtol : o.cvode_rtol)
      add(cvode_family_name(o.method), rtol, reference_choice(cvode_at(problems[k], o.method, rtol, o.atol_ratio)));
  }
  parallel_for(
      jobs.size(),
      [&](std::size_t i) {
        Job& j = jobs[i];
        const ThrowResult r = solve(problems[j.throw_index], j.choice);
        const ThrowResult& truth = truths[j.throw_index];
        GridRun& g = j.run;
        g.rhs_evaluations = r.stats.rhs_evaluations;
        g.cpu_s = r.stats.cpu_s;
        if (j.choice.kind == SolverKind::realtime && is_adaptive(j.choice.realtime.scheme)) {
          g.steps = r.stats.steps;
          g.forced_steps = r.stats.budget_forced_steps;
          g.max_error_ratio = r.stats.max_error_ratio;
        }
        g.ok = r.outcome != Outcome::failed;
        if (!g.ok) {
          g.problem = r.outcome_detail;
          return;
        }
        const ContactComparison c = compare_contacts(r, truth);
        g.bounces = r.bounces;
        g.truth_bounces = truth.bounces;
        g.same_count = r.bounces == truth.bounces;
        g.same_contacts = c.same_contacts();
        g.contact_time_error_s =
            g.same_contacts ? std::max(c.max_start_error_s, c.max_end_error_s) : std::numeric_limits<double>::quiet_NaN();
      },
      ParallelOptions{o.workers, "stones: work-precision grid runs", o.progress});
  for (const Job& j : jobs) res.runs.push_back(j.run);

  // 4. The aggregates and the default they support.
  res.summaries = summarise_grid_runs(res.runs);
  GridDefaultRule rule;
  rule.family = res.adaptive_family;
  rule.agreement_target = o.agreement_target;
  rule.bound = o.agreement_bound;
  rule.contact_time_threshold_s = o.contact_time_threshold_s;
  res.choice = choose_grid_default(res.summaries, rule, kDefaultAdaptiveTolerance);
  if (!res.budget_family.empty()) {
    rule.family = res.budget_family;
    res.budget_choice = choose_grid_budget(res.summaries, rule);
  }
  return res;
}

}  // namespace stoneskip
