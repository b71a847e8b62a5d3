#include "verification/stones/bounce_sweep.hpp"

#include <atomic>
#include <cmath>
#include <functional>
#include <memory>
#include <mutex>

#include "verification/study/ensemble_difference.hpp"

namespace stoneskip {

const char* to_string(SweepParameter p) {
  switch (p) {
    case SweepParameter::spin_rev_s: return "spin_rev_s";
    case SweepParameter::speed_m_s: return "speed_m_s";
    case SweepParameter::attack_angle_deg: return "attack_angle_deg";
    case SweepParameter::path_angle_deg: return "path_angle_deg";
  }
  return "?";
}

const char* unit_of(SweepParameter p) {
  switch (p) {
    case SweepParameter::spin_rev_s: return "rev/s";
    case SweepParameter::speed_m_s: return "m/s";
    default: return "deg";
  }
}

bool parse_sweep_parameter(const std::string& s, SweepParameter& out) {
  for (SweepParameter p : {SweepParameter::spin_rev_s, SweepParameter::speed_m_s, SweepParameter::attack_angle_deg,
                           SweepParameter::path_angle_deg}) {
    if (s == to_string(p) || s == std::string("throw.") + to_string(p)) {
      out = p;
      return true;
    }
  }
  return false;
}

double& parameter_of(ThrowParameters& tp, SweepParameter p) {
  switch (p) {
    case SweepParameter::spin_rev_s: return tp.spin_rev_s;
    case SweepParameter::speed_m_s: return tp.speed_m_s;
    case SweepParameter::attack_angle_deg: return tp.attack_angle_deg;
    case SweepParameter::path_angle_deg: return tp.path_angle_deg;
  }
  return tp.spin_rev_s;
}

namespace {

struct Counter {
  explicit Counter(const ThrowProblem& b) : base(b) {}
  const ThrowProblem& base;
  std::atomic<long> runs{0};
  double cpu_s = 0;
  std::mutex mutex;
  // The bounce count of one throw (−1 with the reason when the solver fails).
  int count(const BounceSweepSpec& spec, double value, std::string* failure, double speed_factor = 1) {
    ThrowParameters tp = base.parameters;
    parameter_of(tp, spec.parameter) = value;
    tp.speed_m_s *= speed_factor;  // an ensemble member: the speed nudged, all else kept
    ThrowProblem p = with_convention(with_parameters(base, tp), spec.convention);
    SolverChoice s = spec.solver;
    s.realtime.record_trajectory = false;
    s.reference.record_trajectory = false;
    const ThrowResult r = solve(p, s);
    ++runs;
    {
      std::lock_guard<std::mutex> lock(mutex);
      cpu_s += r.stats.cpu_s;
    }
    if (r.outcome == Outcome::failed) {
      if (failure) *failure = r.outcome_detail;
      return -1;
    }
    return r.bounces;
  }
};

}  // namespace

CountThreshold bisect_threshold(CountThreshold t, double tolerance, const std::function<int(double)>& count) {
  while (t.hi - t.lo > tolerance) {
    const double mid = t.lo + 0.5 * (t.hi - t.lo);
    // No double strictly between the ends (a tolerance below the values' spacing, e.g. 1e-300):
    // the bracket is as narrow as the arithmetic allows. Stop, or it never would.
    if (!(mid > t.lo && mid < t.hi)) break;
    const int n = count(mid);
    if (n < 0) {  // a failed run is no count: it cannot say on which side of it the change lies
      t.failed_at = mid;
      return t;
    }
    if (n == t.count_below) {
      t.lo = mid;
    } else {
      t.hi = mid;
      t.count_above = n;  // the count just above the change (may differ from the grid's)
    }
  }
  t.bisected = true;
  return t;
}

std::vector<BounceSweepResult> run_bounce_sweeps(const std::vector<BounceSweepSpec>& specs,
                                                 const ParallelOptions& options) {
  std::vector<BounceSweepResult> out(specs.size());
  std::vector<std::unique_ptr<Counter>> counters;
  for (std::size_t k = 0; k < specs.size(); ++k) counters.push_back(std::make_unique<Counter>(specs[k].base));
  std::vector<std::function<void()>> grid_jobs;
  for (std::size_t k = 0; k < specs.size(); ++k) {
    out[k].spec = specs[k];
    out[k].counts.assign(specs[k].values.size(), 0);
    out[k].failures.assign(specs[k].values.size(), "");
    for (std::size_t i = 0; i < specs[k].values.size(); ++i)
      grid_jobs.push_back([&, k, i] {
        out[k].counts[i] = counters[k]->count(specs[k], specs[k].values[i], &out[k].failures[i]);
      });
    if (specs[k].ensemble_members > 0) {
      const std::vector<double> factors =
          perturbation_factors(specs[k].ensemble_members, specs[k].ensemble_smallest, specs[k].ensemble_largest);
      out[k].ensembles.assign(specs[k].values.size(), std::vector<int>(factors.size(), -1));
      for (std::size_t i = 0; i < specs[k].values.size(); ++i)
        for (std::size_t m = 0; m < factors.size(); ++m)
          grid_jobs.push_back([&, k, i, m, f = factors[m]] {
            out[k].ensembles[i][m] = counters[k]->count(specs[k], specs[k].values[i], nullptr, f);
          });
    }
  }
  ParallelOptions grid = options;
  if (!grid.label.empty()) grid.label += " (grid)";
  run_jobs(grid_jobs, grid);

  // Bisection of every change of the count between neighbouring grid values.
  std::vector<std::function<void()>> bisect_jobs;
  for (std::size_t k = 0; k < specs.size(); ++k) {
    const auto& v = specs[k].values;
    const auto& c = out[k].counts;
    for (std::size_t i = 0; i + 1 < v.size(); ++i) {
      if (c[i] == c[i + 1] || c[i] < 0 || c[i + 1] < 0) continue;
      CountThreshold t;
      t.lo = v[i];
      t.hi = v[i + 1];
      t.count_below = c[i];
      t.count_above = c[i + 1];
      t.count_at_cell_end = c[i + 1];
      out[k].thresholds.push_back(t);
    }
    for (std::size_t j = 0; j < out[k].thresholds.size() && static_cast<int>(j) < specs[k].max_thresholds; ++j)
      bisect_jobs.push_back([&, k, j] {
        CountThreshold& t = out[k].thresholds[j];
        std::string why;  // a failed run's reason (the run that stops the bisection is the last one)
        t = bisect_threshold(t, specs[k].threshold_tolerance,
                             [&](double x) { return counters[k]->count(specs[k], x, &why); });
        if (!std::isnan(t.failed_at)) t.failure = why;
      });
  }
  ParallelOptions bis = options;
  if (!bis.label.empty()) bis.label += " (bisection)";
  run_jobs(bisect_jobs, bis);
  for (std::size_t k = 0; k < specs.size(); ++k) {
    out[k].runs = counters[k]->runs;
    out[k].cpu_s = counters[k]->cpu_s;
  }
  return out;
}

}  // namespace stoneskip
