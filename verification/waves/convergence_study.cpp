#include "verification/waves/convergence_study.hpp"

#include <cmath>
#include <limits>

#include "solvers/realtime/clocks.hpp"
#include "solvers/spectral/walled_wave.hpp"
#include "verification/study/progress.hpp"

namespace stoneskip {

namespace {
// Index of the GCI point (3/4, 1/2) L on an n × n grid (n divisible by 4).
double point_value(const std::vector<double>& z, int n) { return z[static_cast<std::size_t>(n / 2) * n + 3 * n / 4]; }

long walled_steps(const ConvergenceStudyOptions& o, int n) {
  return std::max(1L, std::lround(o.walls_t_end_s * o.problem.wave_speed_m_s * n / (o.both_sigma * o.problem.length_m)));
}

// One point of a walled sequence: the leapfrog with the boundary's ghost cells against the walled
// continuum reference, on the points where those walls stand at 0 and L.
ConvergencePoint walled_point(const Stencil& stencil, const ConvergenceStudyOptions& o, Boundary b, int n) {
  const WaveProblem& p = o.problem;
  const WalledSquareGrid g = walled_square_grid(p.length_m, b, n);
  const double d = g.cell_m;
  // Point i stands at first + i·d; sample_disturbance puts it at i·d: shift the centre.
  Disturbance shifted = p.initial;
  shifted.x_m -= g.first_m;
  shifted.y_m -= g.first_m;
  std::vector<double> z0, z, zr;
  sample_disturbance(shifted, g.points, g.points, d, z0);
  HeightFieldOptions h;
  h.nx = h.ny = g.points;
  h.cell_m = d;
  h.wave_speed_m_s = p.wave_speed_m_s;
  h.damping_per_s = p.damping_per_s;
  const long steps = walled_steps(o, n);
  h.dt_s = o.walls_t_end_s / steps;
  h.stencil = stencil;
  h.boundary = b;
  HeightField f(h);
  f.set_state(z0);
  CpuTimer timer;
  f.advance(steps);
  ConvergencePoint pt;
  pt.cpu_s = timer.seconds();
  f.heights(z);
  WalledWave ref(walled_wave_options(h, SpectralSymbol::continuum));
  ref.set_initial(z0);
  ref.evaluate(f.time_s(), zr);
  pt.n = n;
  pt.steps = steps;
  pt.h = d;
  pt.sigma = p.wave_speed_m_s * h.dt_s / d;
  const FieldError e = field_error(z, zr);
  pt.l2_m = e.l2_m;
  pt.max_m = e.max_m;
  pt.point_m = std::numeric_limits<double>::quiet_NaN();  // no GCI on these sequences
  return pt;
}

}  // namespace

WalledSquareGrid walled_square_grid(double length_m, Boundary b, int n) {
  const double d = length_m / n;
  return b == Boundary::reflecting ? WalledSquareGrid{n, d, 0.5 * d} : WalledSquareGrid{n - 1, d, d};
}

void fit_sequence(ConvergenceSequence& s, int fit_points, const OrderJudgement& judgement) {
  std::vector<double> h, e, em;
  const std::size_t first =
      fit_points > 0 && s.points.size() > static_cast<std::size_t>(fit_points) ? s.points.size() - fit_points : 0;
  for (std::size_t i = first; i < s.points.size(); ++i) {
    h.push_back(s.points[i].h);
    e.push_back(s.points[i].l2_m);
    em.push_back(s.points[i].max_m);
  }
  s.fit = fit_order(h, e);
  s.fit_max = fit_order(h, em);
  s.verdict = judge_order(s.fit, judgement).verdict;
}

void attach_gci(ConvergenceSequence& s, const OrderJudgement& judgement) {
  const auto& b = s.points;
  if (b.size() < 3) return;
  const std::size_t k = b.size();
  // An apparent order outside the order verdict's band is not reasonable (gci.hpp, Roache 2011).
  GciOptions go;
  go.formal_order = judgement.expected_order;
  go.order_band = judgement.tolerance;
  s.gci = grid_convergence_index(b[k - 1].point_m, b[k - 2].point_m, b[k - 3].point_m, b[k - 1].h, b[k - 2].h,
                                 b[k - 3].h, go);
}

std::size_t convergence_study_work(const ConvergenceStudyOptions& o) {
  std::size_t w = 0;
  for (int n : o.space_grids) w += static_cast<std::size_t>(n) * n * 20;  // two FFT solves
  for (long s : o.time_steps) w += static_cast<std::size_t>(o.time_grid) * o.time_grid * s;
  for (int n : o.both_grids) {
    const double steps = o.problem.t_end_s * o.problem.wave_speed_m_s / (o.both_sigma * o.problem.length_m / n);
    w += static_cast<std::size_t>(n) * n * static_cast<std::size_t>(std::ceil(steps));
  }
  for (int n : o.both_grids) w += o.walls.size() * static_cast<std::size_t>(n) * n * static_cast<std::size_t>(walled_steps(o, n));
  return w;
}

ConvergenceStudy run_convergence_study(const Stencil& stencil, const ConvergenceStudyOptions& o, ProgressTicker* progress) {
  const WaveProblem& p = o.problem;
  ConvergenceStudy study;
  study.stencil = stencil.name;
  auto tick = [&](std::size_t n) {
    if (progress) progress->tick(n);
  };
  // Space alone: semi-discrete exact vs continuum exact.
  study.space.kind = "space";
  for (int n : o.space_grids) {
    auto semi = solve_spectral(p, n, SpectralSymbol::stencil, stencil);
    auto cont = solve_spectral(p, n, SpectralSymbol::continuum);
    ConvergencePoint pt;
    pt.n = n;
    pt.h = p.length_m / n;
    pt.sigma = std::numeric_limits<double>::quiet_NaN();
    FieldError e = field_error(semi, cont);
    pt.l2_m = e.l2_m;
    pt.max_m = e.max_m;
    pt.point_m = point_value(semi, n);
    study.space.points.push_back(pt);
    tick(static_cast<std::size_t>(n) * n * 20);
  }
  fit_sequence(study.space, o.fit_points, o.judgement);
  // Time alone: leapfrog vs semi-discrete exact on one grid.
  study.time.kind = "time";
  {
    const int n = o.time_grid;
    auto semi = solve_spectral(p, n, SpectralSymbol::stencil, stencil);
    for (long steps : o.time_steps) {
      LeapfrogResult r = solve_leapfrog(p, stencil, n, steps);
      ConvergencePoint pt;
      pt.n = n;
      pt.steps = steps;
      pt.h = r.dt_s;
      pt.sigma = p.wave_speed_m_s * r.dt_s / (p.length_m / n);
      FieldError e = field_error(r.z, semi);
      pt.l2_m = e.l2_m;
      pt.max_m = e.max_m;
      pt.cpu_s = r.cpu_s;
      pt.point_m = point_value(r.z, n);
      study.time.points.push_back(pt);
      tick(static_cast<std::size_t>(n) * n * steps);
    }
  }
  fit_sequence(study.time, o.fit_points, o.judgement);
  // Both at fixed σ: leapfrog vs continuum exact.
  study.both.kind = "both";
  for (int n : o.both_grids) {
    const long steps = std::lround(p.t_end_s * p.wave_speed_m_s / (o.both_sigma * p.length_m / n));
    LeapfrogResult r = solve_leapfrog(p, stencil, n, steps);
    auto cont = solve_spectral(p, n, SpectralSymbol::continuum);
    ConvergencePoint pt;
    pt.n = n;
    pt.steps = steps;
    pt.h = p.length_m / n;
    pt.sigma = p.wave_speed_m_s * r.dt_s / pt.h;
    FieldError e = field_error(r.z, cont);
    pt.l2_m = e.l2_m;
    pt.max_m = e.max_m;
    pt.cpu_s = r.cpu_s;
    pt.point_m = point_value(r.z, n);
    study.both.points.push_back(pt);
    study.both.point_exact_m = point_value(cont, n);
    tick(static_cast<std::size_t>(n) * n * steps);
  }
  fit_sequence(study.both, o.fit_points, o.judgement);
  attach_gci(study.both, o.judgement);
  for (const Boundary b : o.walls) {
    ConvergenceSequence& s = study.walls.emplace_back();
    s.kind = std::string("walls_") + to_string(b);
    for (int n : o.both_grids) {
      s.points.push_back(walled_point(stencil, o, b, n));
      tick(static_cast<std::size_t>(n) * n * static_cast<std::size_t>(walled_steps(o, n)));
    }
    fit_sequence(s, o.fit_points, o.judgement);
  }
  return study;
}

}  // namespace stoneskip
