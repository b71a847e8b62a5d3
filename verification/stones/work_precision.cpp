#include "verification/stones/work_precision.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <sstream>

#include "verification/stones/contact_comparison.hpp"
#include "verification/stones/parallel_runs.hpp"

namespace stoneskip {

namespace {

struct Job {
  std::size_t throw_index;
  WorkPoint point;
  SolverChoice choice;
};

double headline_of(const ContactComparison& c, HeadlineError h) {
  return h == HeadlineError::bounce_position ? c.max_exit_position_error_m : c.max_sink_position_error_m;
}

// Each throw under each law of the study (or as given).
std::vector<ThrowProblem> studied_throws(const std::vector<ThrowProblem>& given, const WorkPrecisionOptions& o) {
  if (o.laws.empty()) return given;
  std::vector<ThrowProblem> out;
  for (const auto& t : given) {
    for (WaterLaw law : o.laws) {
      ThrowProblem p = t;
      set_water_law(p.environment, law);
      p.label += std::string(" (") + to_string(law) + ")";
      out.push_back(p);
    }
  }
  return out;
}

void summarise_restarts(WorkPrecisionResult& res, const WorkPrecisionOptions& o) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  std::vector<RestartSummary>& out = res.restarts;
  for (ReferenceMethod m : o.methods) {
    for (double rtol : o.rtol) {
      const std::size_t first = out.size();
      for (RestartStrategy rs : o.restarts) {
        RestartSummary sum;
        sum.method = m;
        sum.rtol = rtol;
        sum.restart = rs;
        bool any_ok = false;
        for (const auto& t : res.throws) {
          for (const auto& p : t.points) {
            if (p.realtime || p.method != m || p.restart != rs || p.setting != rtol) continue;
            ++sum.throws;
            sum.rhs_evaluations += p.rhs_evaluations;
            sum.steps += p.steps;
            sum.segments += p.segments;
            sum.cpu_s += p.cpu_s;
            if (!p.ok) {
              ++sum.failed;
              continue;
            }
            any_ok = true;
            sum.worst_contact_time_error_s = std::max(sum.worst_contact_time_error_s, p.contact_time_error_s);
          }
        }
        if (!any_ok) sum.worst_contact_time_error_s = kNaN;
        out.push_back(sum);
      }
      // The tolerance at this method and rtol: every_event's own error sets the scale.
      double every_event_worst = kNaN;
      for (std::size_t k = first; k < out.size(); ++k)
        if (out[k].restart == RestartStrategy::every_event) every_event_worst = out[k].worst_contact_time_error_s;
      for (std::size_t k = first; k < out.size(); ++k) {
        RestartSummary& sum = out[k];
        sum.tolerance_s = std::isfinite(every_event_worst)
                              ? std::max(o.restart_time_tolerance_s, o.restart_error_factor * every_event_worst)
                              : o.restart_time_tolerance_s;
        sum.keeps_contact_times = sum.failed == 0 && sum.throws > 0 && sum.worst_contact_time_error_s <= sum.tolerance_s;
      }
    }
  }
  // The verdict: the cheapest strategy (total right-hand sides) that keeps the contact times at
  // every method and rtol; ties go to the strategy listed first.
  RestartVerdict& v = res.restart_verdict;
  std::ostringstream why;
  for (RestartStrategy rs : o.restarts) {
    long rhs = 0;
    double cpu = 0;
    bool keeps = true;
    std::string first_miss;
    for (const auto& sum : out) {
      if (sum.restart != rs) continue;
      rhs += sum.rhs_evaluations;
      cpu += sum.cpu_s;
      if (!sum.keeps_contact_times && keeps) {
        keeps = false;
        std::ostringstream m;
        m << to_string(sum.method) << " rtol " << sum.rtol << ": "
          << (sum.failed ? std::to_string(sum.failed) + " failed or changed contact lists"
                         : "contact-time error " + std::to_string(sum.worst_contact_time_error_s) + " s > " +
                               std::to_string(sum.tolerance_s) + " s");
        first_miss = m.str();
      }
    }
    if (rs == RestartStrategy::every_event) {
      v.every_event_rhs_evaluations = rhs;
      v.every_event_cpu_s = cpu;
    }
    why << to_string(rs) << ": " << rhs << " right-hand sides, " << (keeps ? "keeps the contact times" : "does not (" + first_miss + ")")
        << "; ";
    if (keeps && (!v.found || rhs < v.rhs_evaluations)) {
      v.found = true;
      v.restart = rs;
      v.rhs_evaluations = rhs;
      v.cpu_s = cpu;
    }
  }
  v.reason = why.str();
  if (v.reason.size() >= 2) v.reason.resize(v.reason.size() - 2);
}

}  // namespace

AdaptiveToleranceChoice choose_adaptive_tolerance(const std::vector<WorkPrecisionThrow>& throws,
                                                  const std::vector<WorkPrecisionOptions::RealtimeFamily>& realtime,
                                                  const std::vector<double>& adaptive_rtol) {
  AdaptiveToleranceChoice a;
  a.default_tolerance = kDefaultAdaptiveTolerance;
  for (const auto& t : throws)
    if (t.convention == Convention::physical) ++a.throws;
    else a.set_aside.push_back(t.label);
  for (const auto& f : realtime)
    if (is_adaptive(f.scheme)) {
      a.studied = true;
      a.family = std::string("realtime ") + to_string(f.scheme) + " (adaptive)";
      break;
    }
  if (!a.studied || adaptive_rtol.empty()) return a;
  std::vector<double> tols = adaptive_rtol;
  std::sort(tols.begin(), tols.end());  // tightest first
  a.tolerances = tols;
  bool all_so_far = a.throws > 0;
  for (double tol : tols) {
    int keeping = 0;
    double worst_t = 0, worst_h = 0;
    long rhs = 0;
    for (const auto& t : throws) {
      if (t.convention != Convention::physical) continue;
      for (const auto& p : t.points)
        if (p.family == a.family && p.setting == tol && p.ok) {
          ++keeping;
          worst_t = std::max(worst_t, p.contact_time_error_s);
          worst_h = std::max(worst_h, p.headline_error_m);
          rhs += p.rhs_evaluations;
        }
    }
    a.throws_keeping_contacts.push_back(keeping);
    all_so_far = all_so_far && keeping == a.throws;
    if (all_so_far) {
      a.found = true;
      a.tolerance = tol;
      a.worst_contact_time_error_s = worst_t;
      a.worst_headline_error_m = worst_h;
      a.rhs_evaluations = rhs;
    }
  }
  return a;
}

const char* to_string(HeadlineError h) {
  switch (h) {
    case HeadlineError::bounce_position: return "bounce position";
    case HeadlineError::sink_position: return "sinking position";
  }
  return "?";
}

WorkPrecisionResult run_work_precision(const std::vector<ThrowProblem>& given, const WorkPrecisionOptions& o) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const std::vector<ThrowProblem> throws = studied_throws(given, o);
  WorkPrecisionResult res;
  res.throws.resize(throws.size());
  for (std::size_t k = 0; k < throws.size(); ++k) {
    res.throws[k].label = throws[k].label;
    res.throws[k].law = throws[k].environment.water_law;
    res.throws[k].convention = throws[k].environment.convention;
    // The fixed schemes below keep the throw's kinks, else a fixed scheme's default (none).
    res.throws[k].fixed_kinks = to_string(throws[k].realtime.kinks.value_or(default_kink_steps(Scheme::rk4)));
  }

  // 1. The truth for every throw, and a tighter check of it.
  {
    std::vector<ThrowResult> checks(throws.size());
    std::vector<std::function<void()>> jobs;
    for (std::size_t k = 0; k < throws.size(); ++k) {
      for (int c = 0; c < 2; ++c)
        jobs.push_back([&, k, c] {
          ReferenceOptions r = throws[k].reference;
          r.rtol = o.truth_rtol * (c ? o.truth_check_factor : 1.0);
          r.atol = o.atol_ratio * r.rtol;
          r.record_trajectory = false;
          r.restart = RestartStrategy::every_event;  // the truth restarts at every located event
          (c ? checks[k] : res.throws[k].truth) = solve(throws[k], reference_choice(r));
        });
    }
    run_jobs(jobs, ParallelOptions{o.workers, "", {}});
    for (std::size_t k = 0; k < throws.size(); ++k) {
      WorkPrecisionThrow& t = res.throws[k];
      t.headline = t.truth.bounces > 0 ? HeadlineError::bounce_position : HeadlineError::sink_position;
      const ContactComparison c = compare_contacts(t.truth, checks[k]);
      t.truth_uncertainty_m = c.same_contacts() ? headline_of(c, t.headline) : kNaN;
      if (!c.same_contacts()) res.throws[k].truth_check_problem = "the truth and its check differ: " + c.brief();
    }
  }

  // 2. Every setting of every family on every throw.
  std::vector<Job> jobs;
  for (std::size_t k = 0; k < throws.size(); ++k) {
    for (const auto& fam : o.realtime) {
      const Scheme sc = fam.scheme;
      if (is_adaptive(sc)) {
        for (double tol : o.adaptive_rtol) {
          Job j;
          j.throw_index = k;
          j.point.family = std::string("realtime ") + to_string(sc) + " (adaptive)";
          j.point.realtime = true;
          j.point.adaptive = true;
          j.point.setting = tol;
          RealtimeOptions ro = throws[k].realtime;
          ro.scheme = sc;
          ro.rtol = ro.atol_m = tol;
          ro.record_trajectory = false;
          j.choice = realtime_choice(ro);
          jobs.push_back(j);
        }
        continue;
      }
      for (double dt : o.dt_s) {
        Job j;
        j.throw_index = k;
        j.point.family = std::string("realtime ") + to_string(sc) + " (contact dt/" +
                         std::to_string(static_cast<int>(std::lround(1 / fam.contact_ratio))) + ")";
        j.point.realtime = true;
        j.point.setting = dt;
        RealtimeOptions ro = throws[k].realtime;
        ro.scheme = sc;
        ro.dt_s = dt;
        ro.contact_dt_s = fam.contact_ratio * dt;
        ro.record_trajectory = false;
        j.choice = realtime_choice(ro);
        jobs.push_back(j);
      }
    }
    for (ReferenceMethod m : o.methods) {
      for (RestartStrategy rs : o.restarts) {
        for (double rtol : o.rtol) {
          Job j;
          j.throw_index = k;
          j.point.family = std::string("CVODE ") + to_string(m) + ", restart " + to_string(rs);
          j.point.realtime = false;
          j.point.method = m;
          j.point.restart = rs;
          j.point.setting = rtol;
          ReferenceOptions r = throws[k].reference;
          r.method = m;
          r.restart = rs;
          r.rtol = rtol;
          r.atol = o.atol_ratio * rtol;
          r.record_trajectory = false;
          j.choice = reference_choice(r);
          jobs.push_back(j);
        }
      }
    }
  }
  parallel_for(
      jobs.size(),
      [&](std::size_t i) {
        Job& j = jobs[i];
        const ThrowResult& truth = res.throws[j.throw_index].truth;
        const HeadlineError headline = res.throws[j.throw_index].headline;
        const ThrowResult r = solve_min_cpu(throws[j.throw_index], j.choice, o.repeats);
        WorkPoint& p = j.point;
        p.bounces = r.bounces;
        p.cpu_s = r.stats.cpu_s;
        p.rhs_evaluations = r.stats.rhs_evaluations;
        p.steps = r.stats.steps;
        p.segments = r.stats.segments;
        const ContactComparison c = compare_contacts(r, truth);
        if (r.outcome == Outcome::failed) {
          p.problem = r.outcome_detail;
        } else if (truth.outcome == Outcome::failed) {
          p.problem = "the tight reference failed: " + truth.outcome_detail;
        } else if (!c.same_contacts()) {
          p.problem = "contact list differs: " + c.brief();
        } else {
          p.ok = true;
          p.headline_error_m = headline_of(c, headline);
          p.bounce_position_error_m = c.max_exit_position_error_m;
          p.sink_position_error_m = c.max_sink_position_error_m;
          p.touch_error_m = c.max_touch_error_m;
          p.contact_time_error_s = std::max(c.max_start_error_s, c.max_end_error_s);
        }
        if (!p.ok)
          p.headline_error_m = p.bounce_position_error_m = p.sink_position_error_m = p.touch_error_m =
              p.contact_time_error_s = kNaN;
      },
      ParallelOptions{o.workers, "stones: work-precision runs", o.progress});
  for (const Job& j : jobs) res.throws[j.throw_index].points.push_back(j.point);

  // 3. The cheapest setting of each family for each target error.
  for (auto& t : res.throws) {
    std::vector<std::string> families;
    for (const auto& p : t.points)
      if (families.empty() || families.back() != p.family) families.push_back(p.family);
    for (double target : o.target_errors_m) {
      for (const auto& fam : families) {
        CheapestSetting best;
        best.target_error_m = target;
        best.family = fam;
        for (const auto& p : t.points) {
          if (p.family != fam || !p.ok || !(p.headline_error_m <= target)) continue;
          if (!best.found || p.cpu_s < best.cpu_s) {
            best.found = true;
            best.setting = p.setting;
            best.cpu_s = p.cpu_s;
            best.rhs_evaluations = p.rhs_evaluations;
            best.error_m = p.headline_error_m;
          }
        }
        t.cheapest.push_back(best);
      }
    }
  }
  res.adaptive_choice = choose_adaptive_tolerance(res.throws, o.realtime, o.adaptive_rtol);
  if (!o.restarts.empty()) summarise_restarts(res, o);
  return res;
}

}  // namespace stoneskip
