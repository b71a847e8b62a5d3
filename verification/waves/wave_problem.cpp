#include "verification/waves/wave_problem.hpp"

#include <algorithm>
#include <cmath>

#include "solvers/realtime/clocks.hpp"

namespace stoneskip {

FieldError field_error(const std::vector<double>& a, const std::vector<double>& b) {
  FieldError e;
  for (std::size_t k = 0; k < a.size(); ++k) e.max_m = std::max(e.max_m, std::abs(a[k] - b[k]));
  e.l2_m = root_mean_square(a.size(), [&](std::size_t k) { return a[k] - b[k]; });
  return e;
}

std::vector<double> initial_surface(const WaveProblem& p, int n) {
  std::vector<double> z;
  sample_disturbance(p.initial, n, n, p.length_m / n, z);
  return z;
}

HeightFieldOptions leapfrog_options(const WaveProblem& p, const Stencil& stencil, int n, long steps) {
  HeightFieldOptions o;
  o.nx = o.ny = n;
  o.cell_m = p.length_m / n;
  o.wave_speed_m_s = p.wave_speed_m_s;
  o.damping_per_s = p.damping_per_s;
  o.dt_s = p.t_end_s / steps;
  o.stencil = stencil;
  o.boundary = Boundary::periodic;
  return o;
}

SpectralWaveOptions spectral_options(const WaveProblem& p, int n, SpectralSymbol symbol, const Stencil& stencil) {
  SpectralWaveOptions o;
  o.nx = o.ny = n;
  o.cell_m = p.length_m / n;
  o.wave_speed_m_s = p.wave_speed_m_s;
  o.damping_per_s = p.damping_per_s;
  o.symbol = symbol;
  o.stencil = stencil;
  return o;
}

LeapfrogResult solve_leapfrog(const WaveProblem& p, const Stencil& stencil, int n, long steps) {
  const HeightFieldOptions o = leapfrog_options(p, stencil, n, steps);
  HeightField f(o);
  f.set_state(initial_surface(p, n));
  LeapfrogResult r;
  CpuTimer timer;
  f.advance(steps);
  r.cpu_s = timer.seconds();
  r.steps = steps;
  r.dt_s = o.dt_s;
  r.t_s = f.time_s();
  f.heights(r.z);
  return r;
}

std::vector<double> solve_spectral(const WaveProblem& p, int n, SpectralSymbol symbol, const Stencil& stencil) {
  SpectralWave w(spectral_options(p, n, symbol, stencil));
  w.set_initial(initial_surface(p, n));
  std::vector<double> z;
  w.evaluate(p.t_end_s, z);
  return z;
}

}  // namespace stoneskip
