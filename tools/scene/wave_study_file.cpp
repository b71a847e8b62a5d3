#include "tools/scene/wave_study_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tools/io/input_error.hpp"
#include "tools/scene/resource_estimate.hpp"
#include "tools/scene/study_keys.hpp"
#include "tools/scene/wave_case.hpp"
#include "verification/waves/stability.hpp"

namespace stoneskip {

namespace {

std::vector<int> grid_list(TomlTable& t, const std::string& key, const std::vector<int>& fallback) {
  auto v = t.maybe_numbers(key);
  if (!v) return fallback;
  std::vector<int> out;
  for (double x : *v) {
    if (x != std::floor(x) || x < 8 || x > 4096 || static_cast<long>(x) % 4 != 0)
      t.fail(key, "grid sizes must be whole multiples of 4 in [8, 4096]");
    out.push_back(static_cast<int>(x));
  }
  if (out.empty()) t.fail(key, "must not be empty");
  // A refinement sequence coarse to fine: the fits and the GCI take the last entries as the finest,
  // so [128, 64, 32] fitted the coarsest and named 0.0156 m "finest h"; a repeat has no ratio.
  for (std::size_t i = 1; i < out.size(); ++i)
    if (out[i] <= out[i - 1]) t.fail(key, "grid sizes must increase strictly (coarse to fine), no repeats");
  return out;
}

// Refuses a convergence run whose σ = cΔt/d is above the stencil's stability limit (|g| > 1 on a
// mode of the periodic grid): the leapfrog grows there, and the sequence's "order" (a 2.8e6 m
// error read as "order not established") measured nothing. The 3×3 stencils' symbols are extreme
// at k ∈ {0, π}², modes of every even grid, so verification/waves/stability.hpp's 64-wavenumber
// grid decides for each run's own grid.
void refuse_unstable_run(const std::string& file, const std::string& key, const std::vector<std::string>& stencils,
                         const WaveProblem& p, int n, long steps) {
  const double dt = p.t_end_s / static_cast<double>(steps);
  const double sigma = p.wave_speed_m_s * dt * n / p.length_m, mu_dt = p.damping_per_s * dt;
  for (const auto& name : stencils) {
    const Stencil st = named_stencil(name);
    if (max_amplification(st, sigma, mu_dt) <= 1 + StabilityLimitOptions{}.growth_tolerance) continue;
    char b[320];
    std::snprintf(b, sizeof b,
                  "sigma = %.4g on the %d² grid (%ld steps) is above %s's stability limit %.4g at mu dt = %.3g: the "
                  "leapfrog is unstable there, so its error measures no order",
                  sigma, n, steps, name.c_str(), stability_limit(st, mu_dt), mu_dt);
    throw_input_error(file, 0, key, b);
  }
}

// kd values are given in units of π (kd_over_pi = 0.125 is π/8).
std::vector<double> kd_list(TomlTable& t, const std::string& key, const std::vector<double>& fallback) {
  auto v = t.maybe_numbers(key);
  if (!v) return fallback;
  std::vector<double> out;
  for (double x : *v) {
    if (!(x > 0 && x <= 1)) t.fail(key, "kd/π must be in (0, 1]");
    out.push_back(M_PI * x);
  }
  if (out.empty()) t.fail(key, "must not be empty");
  return out;
}

void read_problem(TomlTable t, WaveProblem& p) {
  p.length_m = t.number_or("length_m", p.length_m);
  t.require_positive("length_m", p.length_m);
  p.wave_speed_m_s = t.number_or("wave_speed_m_s", p.wave_speed_m_s);
  t.require_positive("wave_speed_m_s", p.wave_speed_m_s);
  p.damping_per_s = t.number_or("damping_per_s", p.damping_per_s);
  t.require_non_negative("damping_per_s", p.damping_per_s);
  p.t_end_s = t.number_or("t_end_s", p.t_end_s);
  t.require_positive("t_end_s", p.t_end_s);
  if (auto i = t.maybe_table("initial")) {
    p.initial = read_disturbance(*i);
    // Every grid of the study spans length_m: one check holds for all of them.
    if (const std::string why = disturbance_image_problem(p.initial, p.length_m, p.length_m, kMaxAmplitude_m); !why.empty())
      i->fail(p.initial.kind == DisturbanceKind::ring ? "radius_m" : "width_m", why);
    // The problem is refined (convergence, work–precision): an impulse has one cell's height at
    // every spacing, so its volume shrinks as d² and it has no continuum limit. Its absolute error
    // then falls with the solution itself (order ≈ 1 for every stencil, the relative error ≈ 97 %),
    // which the study would call convergence.
    if (p.initial.kind == DisturbanceKind::impulse)
      i->fail("kind", "an impulse (one cell's height at every spacing) has no continuum limit, so a refinement study of it "
                      "measures nothing; use gaussian, plane_wave or ring");
  }
  t.finish();
}

}  // namespace

WaveStudyFile load_wave_study_file(const std::string& path, const std::vector<std::string>& overrides) {
  const TomlDocument doc = load_toml(path, overrides);
  WaveStudyFile f;
  f.file = doc.file;
  f.text = doc.text;
  TomlTable top = doc.top();
  f.title = read_case_title(top);
  WaveStudiesOptions& o = f.options;
  {
    TomlTable s = top.table("study");
    o.preset = study_preset(s, "waves");
    if (auto names = s.maybe_strings("stencils")) {
      for (const auto& n : *names)
        if (!is_stencil_name(n))
          s.fail("stencils", "'" + n + "' is not one of five_point, nine_point_half, nine_point_isotropic, paper_eq11");
      if (names->empty()) s.fail("stencils", "must not be empty");
      o.stencils = *names;
    }
    s.finish();
  }
  if (auto p = top.maybe_table("problem")) read_problem(*p, o.problem);
  if (auto c = top.maybe_table("consistency")) {
    o.consistency.max_kd = c->number_or("max_kd", o.consistency.max_kd);
    // The cubic fit in (kd)² is trusted where its own error stays below the tolerance's lower
    // bound: its Laplacian coefficient errs by round-off ∝ 1/max_kd² below (5e-11 at 0.01 for
    // the shipped stencils, 4e-9 at 1e-3, where s₂ was 0.0775–0.090 for 1/12) and by truncation
    // ∝ max_kd⁶ above (4e-10 at 0.15, 1.9e-7 at 0.5, where five_point was called inconsistent).
    c->require_in("max_kd", o.consistency.max_kd, 0.01, 0.15);
    o.consistency.samples = static_cast<int>(count_in(*c, "samples", o.consistency.samples, 4, 1000));
    o.consistency.angles = static_cast<int>(count_in(*c, "angles", o.consistency.angles, 2, 10000));
    o.consistency.tolerance = c->number_or("tolerance", o.consistency.tolerance);
    // Above the fit's own error (≤ 4e-10 over the max_kd range) and far below paper_eq11's
    // constant term 1/3, the inconsistency it must see.
    c->require_in("tolerance", o.consistency.tolerance, 1e-9, 1e-3);
    c->finish();
  }
  if (auto c = top.maybe_table("convergence")) {
    ConvergenceStudyOptions& v = o.convergence;
    v.space_grids = grid_list(*c, "space_grids", v.space_grids);
    v.time_grid = static_cast<int>(count_in(*c, "time_grid", v.time_grid, 8, 4096));
    if (v.time_grid % 4 != 0) c->fail("time_grid", "must be a multiple of 4");
    if (auto steps = c->maybe_numbers("time_steps")) {
      v.time_steps.clear();
      for (double x : *steps) {
        if (x != std::floor(x) || x < 1 || x > 1e7) c->fail("time_steps", "step counts must be whole numbers in [1, 1e7]");
        v.time_steps.push_back(static_cast<long>(x));
      }
      if (v.time_steps.empty()) c->fail("time_steps", "must not be empty");
      for (std::size_t i = 1; i < v.time_steps.size(); ++i)
        if (v.time_steps[i] <= v.time_steps[i - 1]) c->fail("time_steps", "step counts must increase strictly (coarse to fine), no repeats");
    }
    v.both_grids = grid_list(*c, "both_grids", v.both_grids);
    v.both_sigma = c->number_or("both_sigma", v.both_sigma);
    c->require_in("both_sigma", v.both_sigma, 1e-3, 1.0);
    // The sequences' work, against the limit `stoneskip wave` keeps (kMaxCellUpdates): a study file
    // asking for 6.7e14 cell updates (about two years) started at once, its progress line the
    // only warning. The time sequence: time_grid² cells × Σ time_steps; the space–time one: N²
    // cells × t_end c N / (σ L) steps on each grid N; both for every stencil.
    const double stencils = static_cast<double>(o.stencils.size());
    double time_updates = 0, both_updates = 0;
    for (long n : v.time_steps) time_updates += static_cast<double>(v.time_grid) * v.time_grid * static_cast<double>(n);
    for (int n : v.both_grids)
      both_updates += static_cast<double>(n) * n *
                      std::ceil(o.problem.t_end_s * o.problem.wave_speed_m_s * n / (v.both_sigma * o.problem.length_m));
    auto refuse_above = [&](const char* key, double updates, const char* what) {
      if (stencils * updates <= kMaxCellUpdates) return;
      char b[240];
      std::snprintf(b, sizeof b, "the %s needs %.3g cell updates over %d stencils, above the limit of %.3g that `stoneskip wave` keeps",
                    what, stencils * updates, static_cast<int>(stencils), kMaxCellUpdates);
      c->fail(key, b);
    };
    refuse_above("time_steps", time_updates, "time sequence (time_grid² × Σ time_steps)");
    refuse_above("both_grids", both_updates, "space–time sequence (N² × t_end c N / (σ L) on each grid)");
    // The walled squares (the same grids and σ, to walls_t_end_s): reflecting and fixed, or fewer.
    if (auto walls = c->maybe_strings("walls")) {
      v.walls.clear();
      for (const auto& w : *walls) {
        Boundary b{};
        if (!parse_boundary(w, b) || b == Boundary::periodic)
          c->fail("walls", "'" + w + "' is not a walled boundary (reflecting, fixed)");
        if (std::find(v.walls.begin(), v.walls.end(), b) != v.walls.end()) c->fail("walls", "'" + w + "' is named twice");
        v.walls.push_back(b);
      }
    }
    v.walls_t_end_s = c->number_or("walls_t_end_s", v.walls_t_end_s);
    c->require_in("walls_t_end_s", v.walls_t_end_s, 1e-3, 1e3);
    double walls_updates = 0;
    for (int n : v.both_grids)
      walls_updates += static_cast<double>(v.walls.size()) * n * n *
                       std::ceil(v.walls_t_end_s * o.problem.wave_speed_m_s * n / (v.both_sigma * o.problem.length_m));
    refuse_above("walls_t_end_s", walls_updates, "walled sequences (N² × walls_t_end c N / (σ L) on each grid, each wall kind)");
    v.fit_points = static_cast<int>(count_in(*c, "fit_points", v.fit_points, 0, 100));
    if (v.fit_points == 1) c->fail("fit_points", "a fit needs at least 2 points (0: all)");
    v.judgement.expected_order = c->number_or("expected_order", v.judgement.expected_order);
    c->require_positive("expected_order", v.judgement.expected_order);
    v.judgement.tolerance = c->number_or("order_tolerance", v.judgement.tolerance);
    c->require_positive("order_tolerance", v.judgement.tolerance);
    v.judgement.minimum_order = c->number_or("minimum_order", v.judgement.minimum_order);
    c->require_non_negative("minimum_order", v.judgement.minimum_order);
    c->finish();
  }
  if (auto c = top.maybe_table("isotropy")) {
    WaveIsotropyOptions& v = o.isotropy;
    v.polar_kd = kd_list(*c, "polar_kd_over_pi", v.polar_kd);
    v.polar_angles = static_cast<int>(count_in(*c, "polar_angles", v.polar_angles, 3, 100000));
    v.spread_kd_min = M_PI * c->number_or("spread_kd_min_over_pi", v.spread_kd_min / M_PI);
    v.spread_kd_max = M_PI * c->number_or("spread_kd_max_over_pi", v.spread_kd_max / M_PI);
    if (!(v.spread_kd_min > 0 && v.spread_kd_min < v.spread_kd_max && v.spread_kd_max <= M_PI))
      c->fail("spread_kd_max_over_pi", "need 0 < spread_kd_min_over_pi < spread_kd_max_over_pi <= 1");
    v.spread_points = static_cast<int>(count_in(*c, "spread_points", v.spread_points, 2, 100000));
    v.table_kd = M_PI * c->number_or("table_kd_over_pi", v.table_kd / M_PI);
    c->require_in("table_kd_over_pi", v.table_kd / M_PI, 1e-6, 1.0);
    v.baseline_stencil = c->string_or("baseline_stencil", v.baseline_stencil);
    v.measured_kd = kd_list(*c, "measured_kd_over_pi", v.measured_kd);
    v.measured_angles = static_cast<int>(count_in(*c, "measured_angles", v.measured_angles, 2, 1000));
    v.measured_grid = static_cast<int>(count_in(*c, "measured_grid", v.measured_grid, 16, 4096));
    v.measured_sigma = c->number_or("measured_sigma", v.measured_sigma);
    c->require_in("measured_sigma", v.measured_sigma, 1e-4, 0.5);
    v.measured_steps = count_in(*c, "measured_steps", v.measured_steps, 16, 10000000);
    if (auto r = c->maybe_table("ring")) {
      v.ring.n = static_cast<int>(count_in(*r, "n", v.ring.n, 16, 4096));
      v.ring.width_m = r->number_or("width_m", v.ring.width_m);
      r->require_in("width_m", v.ring.width_m, 1e-4, 0.25);
      v.ring.t_s = r->number_or("t_s", v.ring.t_s);
      r->require_in("t_s", v.ring.t_s, 1e-3, 0.45);
      v.ring.sigma = r->number_or("sigma", v.ring.sigma);
      r->require_in("sigma", v.ring.sigma, 1e-3, 0.7);
      v.ring.angles = static_cast<int>(count_in(*r, "angles", v.ring.angles, 2, 10000));
      r->finish();
    }
    c->finish();
  }
  if (auto c = top.maybe_table("stability")) {
    WaveStabilityOptions& v = o.stability;
    v.mu_dt_max = c->number_or("mu_dt_max", v.mu_dt_max);
    c->require_in("mu_dt_max", v.mu_dt_max, 0.0, 1.99);
    v.mu_dt_points = static_cast<int>(count_in(*c, "mu_dt_points", v.mu_dt_points, 2, 10000));
    if (auto m = c->maybe_numbers("check_mu_dt")) {
      for (double x : *m)
        if (!(x >= 0 && x < 2)) c->fail("check_mu_dt", "every μΔt must be in [0, 2)");
      v.check_mu_dt = *m;
    }
    v.check_factor = c->number_or("check_factor", v.check_factor);
    c->require_in("check_factor", v.check_factor, 1e-4, 0.5);
    v.measured_tolerance = c->number_or("measured_tolerance", v.measured_tolerance);
    c->require_in("measured_tolerance", v.measured_tolerance, 1e-8, 0.1);
    v.measured_steps = count_in(*c, "measured_steps", v.measured_steps, 10, 10000000);
    v.damping_independence_tolerance = c->number_or("damping_independence_tolerance", v.damping_independence_tolerance);
    c->require_positive("damping_independence_tolerance", v.damping_independence_tolerance);
    v.lengyel_sigma = c->number_or("lengyel_sigma", v.lengyel_sigma);
    c->require_positive("lengyel_sigma", v.lengyel_sigma);
    v.lengyel_mu_dt = c->number_or("lengyel_mu_dt", v.lengyel_mu_dt);
    c->require_in("lengyel_mu_dt", v.lengyel_mu_dt, 0.0, 1.99);
    v.lengyel_steps = count_in(*c, "lengyel_steps", v.lengyel_steps, 10, 10000000);
    c->finish();
  }
  if (auto c = top.maybe_table("speed")) {
    WaveSpeedOptions& v = o.speed;
    v.work.problem = o.problem;
    if (auto p = c->maybe_table("problem")) read_problem(*p, v.work.problem);
    v.work.grids = grid_list(*c, "grids", v.work.grids);
    v.work.sigma_fractions = positive_list(*c, "sigma_fractions", v.work.sigma_fractions);
    for (double fraction : v.work.sigma_fractions)
      if (fraction > 1) c->fail("sigma_fractions", "fractions of the stability limit must be <= 1");
    v.work.min_cpu_s = c->number_or("min_cpu_s", v.work.min_cpu_s);
    c->require_in("min_cpu_s", v.work.min_cpu_s, 0.0, 60.0);
    v.targets_m = positive_list(*c, "targets_m", v.targets_m);
    v.baseline_stencil = c->string_or("baseline_stencil", v.baseline_stencil);
    v.material_gain = c->number_or("material_gain", v.material_gain);
    c->require_in("material_gain", v.material_gain, 1.0, 100.0);
    c->finish();
  } else {
    o.speed.work.problem = o.problem;
  }
  top.finish();
  // Every convergence run stable (the steps as run_convergence_study takes them), once all tables
  // are read: a [problem] alone (t_end_s = 1.5) put the default time sequence at σ = 1.5.
  const ConvergenceStudyOptions& v = o.convergence;
  for (long n : v.time_steps) refuse_unstable_run(f.file, "convergence.time_steps", o.stencils, o.problem, v.time_grid, n);
  for (int n : v.both_grids)
    refuse_unstable_run(f.file, "convergence.both_sigma", o.stencils, o.problem, n,
                        std::lround(o.problem.t_end_s * o.problem.wave_speed_m_s / (v.both_sigma * o.problem.length_m / n)));
  std::string why;
  if (!o.valid(&why)) throw_input_error(f.file, 0, "", why);
  return f;
}

}  // namespace stoneskip
