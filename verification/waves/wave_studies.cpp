#include "verification/waves/wave_studies.hpp"

#include <cmath>
#include <cstdio>

#include "solvers/realtime/clocks.hpp"
#include "tools/io/progress.hpp"

namespace stoneskip {

namespace {

bool is_consistent(const WaveStudies& s, const std::string& name) {
  for (const auto& c : s.consistency)
    if (c.stencil == name) return c.consistent;
  return false;
}

void consistency(WaveStudies& s) {
  CpuTimer t;
  for (const auto& st : s.stencils) s.consistency.push_back(analyse_consistency(st));
  s.cpu_consistency_s = t.seconds();
}

void convergence(WaveStudies& s) {
  CpuTimer t;
  ConvergenceStudyOptions& o = s.convergence_options;
  o.problem = s.problem;
  if (s.options.quick) {
    o.space_grids = {64, 128, 256};
    o.time_steps = {64, 128, 256, 512};
    o.both_grids = {32, 64, 128};
  } else {
    o.space_grids = {32, 64, 128, 256, 512, 1024};
    o.time_grid = 64;
    o.time_steps = {64, 128, 256, 512, 1024, 2048};
    o.both_grids = {32, 64, 128, 256, 512};
  }
  Progress progress("convergence", convergence_study_work(o) * s.stencils.size());
  for (const auto& st : s.stencils) s.convergence.push_back(run_convergence_study(st, o, &progress));
  progress.done();
  s.cpu_convergence_s = t.seconds();
}

void isotropy(WaveStudies& s) {
  CpuTimer t;
  const std::vector<double> polar_kd{M_PI / 8, M_PI / 4, M_PI / 2};
  const int angles = 181;  // θ over [0, 2π] every 2°
  for (const auto& st : s.stencils) {
    if (!is_consistent(s, st.name)) continue;  // an inconsistent stencil has no meaningful phase speed
    for (double kd : polar_kd) {
      IsotropyCurve c{st.name, kd, {}, {}};
      for (int a = 0; a < angles; ++a) {
        const double th = 2 * M_PI * a / (angles - 1);
        c.theta_rad.push_back(th);
        c.error.push_back(phase_speed_error(st, kd, th));
      }
      s.isotropy_curves.push_back(c);
    }
    SpreadCurve sc{st.name, {}, {}};
    for (int i = 0; i <= 40; ++i) {
      const double kd = 0.02 * std::pow(M_PI / 0.02, i / 40.0);  // 0.02 … π, log-spaced
      sc.kd.push_back(kd);
      sc.spread.push_back(phase_error_spread(st, kd));
    }
    s.spread_curves.push_back(sc);
  }
  // Measured from simulations: single Fourier modes at angles 0 … 45°.
  if (s.options.quick) s.measured_steps = 200;
  const std::vector<double> kds{M_PI / 8, M_PI / 4};
  std::size_t runs = 0;
  for (const auto& st : s.stencils)
    if (is_consistent(s, st.name)) runs += kds.size() * 10;
  Progress progress("isotropy", runs + 3);
  for (const auto& st : s.stencils) {
    if (!is_consistent(s, st.name)) continue;
    for (double kd : kds) {
      MeasuredIsotropy m{st.name, kd, {}};
      for (int a = 0; a < 10; ++a) {
        m.points.push_back(measure_phase_speed(st, kd, M_PI / 4 * a / 9, s.measured_grid, s.measured_sigma, s.measured_steps));
        progress.tick();
      }
      s.measured_isotropy.push_back(m);
    }
  }
  for (const auto& st : s.stencils) {
    if (!is_consistent(s, st.name)) continue;
    s.rings.emplace_back(st.name, ring_test(st, s.ring_options));
    progress.tick();
  }
  progress.done();
  s.cpu_isotropy_s = t.seconds();
}

void stability(WaveStudies& s) {
  CpuTimer t;
  const std::vector<double> check_mu{0.0, 0.5, 1.0, 1.5};
  Progress progress("stability", s.stencils.size() * (1 + check_mu.size()));
  for (const auto& st : s.stencils) {
    StabilityCurve c{st.name, {}, {}};
    for (int i = 0; i <= 38; ++i) {
      const double mu_dt = 0.05 * i;  // 0 … 1.9
      c.mu_dt.push_back(mu_dt);
      c.limit.push_back(stability_limit(st, mu_dt));
    }
    s.stability_curves.push_back(c);
    progress.tick();
    for (double mu_dt : check_mu) {
      StabilityCheck k;
      k.stencil = st.name;
      k.mu_dt = mu_dt;
      k.computed_limit = stability_limit(st, mu_dt);
      k.lengyel_bound = lengyel_bound(mu_dt);
      k.below = run_growth(st, 0.98 * k.computed_limit, mu_dt);
      k.above = run_growth(st, 1.02 * k.computed_limit, mu_dt);
      k.measured_limit = measured_stability_limit(st, mu_dt, 0.9 * k.computed_limit, 1.1 * k.computed_limit,
                                                  s.options.quick ? 1e-3 : 1e-4);
      s.stability_checks.push_back(k);
      progress.tick();
    }
  }
  const Stencil five = named_stencil("five_point");
  s.lengyel_counterexample = run_growth(five, 0.75, 0.5, 16, 200);
  s.lengyel_counterexample_predicted = max_amplification(five, 0.75, 0.5);
  progress.done();
  s.cpu_stability_s = t.seconds();
}

void speed_vs_error(WaveStudies& s) {
  CpuTimer t;
  WorkPrecisionOptions o;
  // A harder version of the convergence problem: a narrower bump travelling twice as long, so that
  // the runs last long enough to time and the errors span the range a game would accept.
  o.problem = s.problem;
  o.problem.initial.width_m = 0.05;
  o.problem.t_end_s = 1.0;
  if (s.options.quick) {
    o.grids = {32, 64, 128};
    o.min_cpu_s = 0.002;
  } else {
    o.grids = {32, 48, 64, 96, 128, 192, 256, 384, 512, 768};
  }
  std::size_t total = 0;
  for (const auto& st : s.stencils) {
    o.stability_limit = stability_limit(st, 0.0);
    total += work_precision_work(o);
  }
  Progress progress("speed vs error", total);
  for (const auto& st : s.stencils) {
    o.stability_limit = stability_limit(st, 0.0);
    s.work_sigma_limit.emplace_back(st.name, o.stability_limit);
    s.work.emplace_back(st.name, run_work_precision(st, o, &progress));
  }
  progress.done();
  s.work_options = o;
  s.cpu_work_s = t.seconds();
}

}  // namespace

WaveStudies run_wave_studies(const WaveStudiesOptions& options) {
  WaveStudies s;
  s.options = options;
  for (const auto& name : options.stencils) s.stencils.push_back(named_stencil(name));
  if (options.quick) s.ring_options.n = 64, s.ring_options.width_m = 0.06;
  consistency(s);
  convergence(s);
  isotropy(s);
  stability(s);
  speed_vs_error(s);
  return s;
}

}  // namespace stoneskip
