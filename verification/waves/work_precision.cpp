#include "verification/waves/work_precision.hpp"

#include <cmath>
#include <limits>

#include "verification/study/progress.hpp"

namespace stoneskip {

namespace {
long steps_for(const WaveProblem& p, int n, double sigma) {
  return std::max(1L, std::lround(std::ceil(p.t_end_s * p.wave_speed_m_s / (sigma * p.length_m / n))));
}
}  // namespace

std::size_t work_precision_work(const WaveWorkPrecisionOptions& o) {
  std::size_t w = 0;
  for (int n : o.grids)
    for (double f : o.sigma_fractions)
      w += static_cast<std::size_t>(n) * n * steps_for(o.problem, n, f * o.stability_limit);
  return w;
}

std::vector<WaveWorkPoint> run_work_precision(const Stencil& stencil, const WaveWorkPrecisionOptions& o, ProgressTicker* progress) {
  std::vector<WaveWorkPoint> out;
  for (int n : o.grids) {
    auto cont = solve_spectral(o.problem, n, SpectralSymbol::continuum);
    for (double f : o.sigma_fractions) {
      const long steps = steps_for(o.problem, n, f * o.stability_limit);  // ceil: σ ≤ f · limit
      LeapfrogResult r = solve_leapfrog(o.problem, stencil, n, steps);
      FieldError e = field_error(r.z, cont);
      // Short runs are repeated until they have used min_cpu_s, and the mean is kept, so that
      // microsecond runs are not timed by the clock's resolution and the scheduler's noise.
      double cpu = r.cpu_s;
      int reps = 1;
      while (cpu < o.min_cpu_s && reps < 1000) {
        cpu += solve_leapfrog(o.problem, stencil, n, steps).cpu_s;
        ++reps;
      }
      WaveWorkPoint w;
      w.n = n;
      w.steps = steps;
      w.sigma = o.problem.wave_speed_m_s * r.dt_s / (o.problem.length_m / n);
      w.l2_m = e.l2_m;
      w.max_m = e.max_m;
      w.cpu_s = cpu / reps;
      out.push_back(w);
      if (progress) progress->tick(static_cast<std::size_t>(n) * n * steps);
    }
  }
  return out;
}

double cpu_to_reach(const std::vector<WaveWorkPoint>& points, double target_m) {
  double best = std::numeric_limits<double>::quiet_NaN();
  for (const auto& p : points)
    if (p.l2_m <= target_m && (std::isnan(best) || p.cpu_s < best)) best = p.cpu_s;
  return best;
}

}  // namespace stoneskip
