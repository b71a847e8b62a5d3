#include "verification/waves/forced_convergence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "solvers/realtime/clocks.hpp"
#include "solvers/spectral/forced_walled_wave.hpp"

namespace stoneskip {

bool ForcedConvergenceOptions::is_valid(std::string* why) const {
  auto fail = [&](const char* what) {
    if (why) *why = what;
    return false;
  };
  for (int n : space_grids)
    if (n < 4) return fail("forced convergence: space_grids must be >= 4");
  for (int n : both_grids)
    if (n < 4) return fail("forced convergence: both_grids must be >= 4");
  if (time_grid < 4) return fail("forced convergence: time_grid must be >= 4");
  for (long s : time_steps)
    if (s < 1) return fail("forced convergence: time_steps must be >= 1");
  if (!(both_sigma > 0)) return fail("forced convergence: both_sigma must be > 0");
  if (!(problem.wave.t_end_s > 0) || !(problem.wave.length_m > 0))
    return fail("forced convergence: t_end_s and length_m must be > 0");
  if (quadrature.intervals < 1 || quadrature.nodes < 1) return fail("forced convergence: quadrature needs intervals, nodes >= 1");
  if (fit_points < 2) return fail("forced convergence: fit_points must be >= 2");
  if (!walls.empty() && !(walls_t_end_s > 0)) return fail("forced convergence: walls_t_end_s must be > 0");
  for (const Boundary b : walls)
    if (b == Boundary::periodic) return fail("forced convergence: walls are reflecting or fixed");
  return true;
}

LeapfrogResult solve_forced_leapfrog(const ForcedWaveProblem& p, const Stencil& stencil, int n, long steps) {
  const HeightFieldOptions o = leapfrog_options(p.wave, stencil, n, steps);
  HeightField f(o);
  f.set_state(initial_surface(p.wave, n));  // at rest; the draught's envelope makes b(0) = 0
  DraughtPatch b;
  b.reset(0, 0, n, n);
  LeapfrogResult r;
  CpuTimer timer;
  for (long k = 0; k < steps; ++k) {
    p.draught.sample(k * o.dt_s, n, n, o.cell_m, b.b_m);  // b at the start of the step (model/README.md §2.4)
    f.step(b);
  }
  r.cpu_s = timer.seconds();
  r.steps = steps;
  r.dt_s = o.dt_s;
  r.t_s = f.time_s();
  f.heights(r.z);
  return r;
}

std::vector<double> solve_forced_reference(const ForcedWaveProblem& p, int n, SpectralSymbol symbol, const Stencil& stencil,
                                           const DuhamelQuadrature& quadrature, long* transforms) {
  const SpectralWaveOptions o = spectral_options(p.wave, n, symbol, stencil);
  ForcedSpectralWave w(o, p.draught.on_grid(n, n, o.cell_m), quadrature);
  w.set_initial(initial_surface(p.wave, n));
  std::vector<double> z;
  w.evaluate(p.wave.t_end_s, z);
  if (transforms) *transforms += w.draught_transforms();
  return z;
}

namespace {

ConvergencePoint point_of(int n, long steps, double h, double sigma, const std::vector<double>& z,
                          const std::vector<double>& reference, double cpu_s) {
  ConvergencePoint pt;
  pt.n = n;
  pt.steps = steps;
  pt.h = h;
  pt.sigma = sigma;
  const FieldError e = field_error(z, reference);
  pt.l2_m = e.l2_m;
  pt.max_m = e.max_m;
  pt.cpu_s = cpu_s;
  pt.point_m = z[static_cast<std::size_t>(n / 2) * n + 3 * n / 4];  // (3/4, 1/2) L, as the free study
  return pt;
}

// The walled runs' quadrature: the study's sub-interval length over their own span.
DuhamelQuadrature walled_quadrature(const ForcedConvergenceOptions& o) {
  DuhamelQuadrature q = o.quadrature;
  q.intervals = std::max(1, static_cast<int>(std::ceil(q.intervals * o.walls_t_end_s / o.problem.wave.t_end_s - 1e-9)));
  return q;
}

// One point of a walled sequence: the forced leapfrog with the boundary's ghost cells against the
// forced walled reference, the square's walls at 0 and L (convergence_study.cpp's walled points).
ConvergencePoint forced_walled_point(const ForcedConvergenceOptions& o, const Stencil& stencil, Boundary b, int n, long& transforms) {
  const WaveProblem& wp = o.problem.wave;
  const WalledSquareGrid g = walled_square_grid(wp.length_m, b, n);
  const double d = g.cell_m, offset = g.first_m;  // point 0 stands at x = offset
  const int m = g.points;
  const long steps = std::max(1L, std::lround(o.walls_t_end_s * wp.wave_speed_m_s / (o.both_sigma * d)));
  HeightFieldOptions h = leapfrog_options(wp, stencil, m, steps);
  h.cell_m = d;
  h.dt_s = o.walls_t_end_s / steps;
  h.boundary = b;
  Disturbance initial = wp.initial;
  initial.x_m -= offset;
  initial.y_m -= offset;
  std::vector<double> z0, z;
  sample_disturbance(initial, m, m, d, z0);
  HeightField f(h);
  f.set_state(z0);
  const MovingGaussianDraught draught = o.problem.draught;
  DraughtPatch patch;
  CpuTimer timer;
  for (long k = 0; k < steps; ++k) {
    patch.reset(0, 0, m, m);
    draught.sample_walled(k * h.dt_s, m, m, d, offset, offset, patch.b_m);  // b at the start of the step
    f.step(patch);
  }
  const double cpu_s = timer.seconds();
  f.heights(z);
  ForcedWalledWave ref(walled_wave_options(h, SpectralSymbol::continuum),
                       [draught, m, d, offset](double t, std::vector<double>& head) { draught.sample_walled(t, m, m, d, offset, offset, head); },
                       walled_quadrature(o));
  ref.set_initial(z0);
  std::vector<double> zr;
  ref.evaluate(f.time_s(), zr);
  transforms += ref.draught_transforms();
  ConvergencePoint pt = point_of(m, steps, d, wp.wave_speed_m_s * h.dt_s / d, z, zr, cpu_s);
  pt.n = n;                                               // the grid's cells, as in the free study's walled points
  pt.point_m = std::numeric_limits<double>::quiet_NaN();  // no GCI on these sequences
  return pt;
}

}  // namespace

ForcedConvergenceStudy run_forced_convergence(const Stencil& stencil, const ForcedConvergenceOptions& o) {
  std::string why;
  if (!o.is_valid(&why)) throw std::invalid_argument(why);
  const ForcedWaveProblem& p = o.problem;
  const WaveProblem& wp = p.wave;
  ForcedConvergenceStudy study;
  study.stencil = stencil.name;
  long& transforms = study.reference_transforms;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Space alone: semi-discrete exact vs continuum exact.
  study.space.kind = "space";
  for (int n : o.space_grids) {
    const auto semi = solve_forced_reference(p, n, SpectralSymbol::stencil, stencil, o.quadrature, &transforms);
    const auto cont = solve_forced_reference(p, n, SpectralSymbol::continuum, stencil, o.quadrature, &transforms);
    study.space.points.push_back(point_of(n, 0, wp.length_m / n, nan, semi, cont, 0));
  }
  fit_sequence(study.space, o.fit_points, o.judgement);
  // Time alone: forced leapfrog vs the stencil's semi-discrete forced solution on one grid.
  study.time.kind = "time";
  {
    const int n = o.time_grid;
    const auto semi = solve_forced_reference(p, n, SpectralSymbol::stencil, stencil, o.quadrature, &transforms);
    for (long steps : o.time_steps) {
      const LeapfrogResult r = solve_forced_leapfrog(p, stencil, n, steps);
      study.time.points.push_back(
          point_of(n, steps, r.dt_s, wp.wave_speed_m_s * r.dt_s / (wp.length_m / n), r.z, semi, r.cpu_s));
    }
  }
  fit_sequence(study.time, o.fit_points, o.judgement);
  // Both at fixed σ: forced leapfrog vs the continuum forced solution.
  study.both.kind = "both";
  for (int n : o.both_grids) {
    const double d = wp.length_m / n;
    const long steps = std::max(1L, std::lround(wp.t_end_s * wp.wave_speed_m_s / (o.both_sigma * d)));
    const LeapfrogResult r = solve_forced_leapfrog(p, stencil, n, steps);
    const auto cont = solve_forced_reference(p, n, SpectralSymbol::continuum, stencil, o.quadrature, &transforms);
    study.both.points.push_back(point_of(n, steps, d, wp.wave_speed_m_s * r.dt_s / d, r.z, cont, r.cpu_s));
    study.both.point_exact_m = cont[static_cast<std::size_t>(n / 2) * n + 3 * n / 4];
  }
  fit_sequence(study.both, o.fit_points, o.judgement);
  attach_gci(study.both, o.judgement);
  for (const Boundary b : o.walls) {
    ConvergenceSequence& s = study.walls.emplace_back();
    s.kind = std::string("walls_") + to_string(b);
    for (int n : o.both_grids) s.points.push_back(forced_walled_point(o, stencil, b, n, transforms));
    fit_sequence(s, o.fit_points, o.judgement);
  }
  // The reference's own error: halve the sub-intervals' length on the finest grid used.
  int finest = o.time_grid;
  for (int n : o.space_grids) finest = std::max(finest, n);
  for (int n : o.both_grids) finest = std::max(finest, n);
  DuhamelQuadrature finer = o.quadrature;
  finer.intervals *= 2;
  const auto ref = solve_forced_reference(p, finest, SpectralSymbol::continuum, stencil, o.quadrature, &transforms);
  const auto ref2 = solve_forced_reference(p, finest, SpectralSymbol::continuum, stencil, finer, &transforms);
  study.reference_quadrature_m = field_error(ref, ref2).max_m;
  study.smallest_error_m = std::numeric_limits<double>::infinity();
  for (const auto* s : {&study.space, &study.time, &study.both})
    for (const auto& pt : s->points) study.smallest_error_m = std::min(study.smallest_error_m, pt.max_m);
  for (const auto& s : study.walls)
    for (const auto& pt : s.points) study.smallest_error_m = std::min(study.smallest_error_m, pt.max_m);
  return study;
}

}  // namespace stoneskip
