#include "tools/scene/resource_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace stoneskip {

namespace {

constexpr double kDouble = sizeof(double);
constexpr double kTrajectoryColumns = 17;  // the result file's trajectory table (throw_output.hpp)

std::string sci(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", v);
  return b;
}

double rhs_per_step(Scheme s) {
  switch (s) {
    case Scheme::semi_implicit_euler: return 1;
    case Scheme::midpoint: return 2;
    case Scheme::rk4: return 4;
    case Scheme::bs32: return 6;  // 3 per trial; as many trials cut back to a crossing or rejected
    case Scheme::dp54: return 12;  // 6 per trial, the same
  }
  return 4;
}

// Worst-case steps of the real-time stepper: every step at contact_dt_s; bs32 has no step floor,
// so it is estimated as if every step were 6e-5 s, a third of its mean step in a planing contact at
// rtol 1e-8 (~2e-4 s; about 1e-4 s at the default 1e-9), and every step in contact: at 6 right-hand
// sides a step, the work the fixed stepper's 10 µs contact step was estimated at (the spin-60 throw
// of cases/spin_sweep_base.toml takes 34 537 right-hand sides at rtol 1e-8 where this allows 1e6
// over its 10 s). The estimate does not scale with rtol: a case with a much tighter tolerance can
// take more steps than it says.
// Either way no step is longer than dt_s (bs32's largest step, the fixed schemes' flight step), so a
// dt_s below the step assumed bounds the estimate instead (bs32 with dt_s = 1e-9 takes 1e10 steps
// over 10 s, not 1.7e5).
constexpr double kAdaptiveEstimateStep_s = 6e-5;
double realtime_steps(const RealtimeOptions& o) {
  const double assumed = is_adaptive(o.scheme) ? kAdaptiveEstimateStep_s : o.contact_dt_s;
  return std::ceil(o.t_max_s / std::min(assumed, o.dt_s));
}

// Trajectory samples held in memory: one per output_dt_s (plus contact transitions), or every step.
// The real-time stepper records at the ends of its steps, at most one sample a step; the reference
// interpolates every output time inside its steps, however many fall in one (cvode_stone.cpp,
// ReferenceSolve::integrate), so its count is not bounded by its steps.
double samples(double t_max_s, double output_dt_s, double max_steps) {
  if (output_dt_s <= 0) return max_steps;
  return std::min(max_steps, std::floor(t_max_s / output_dt_s) + 1) + 64;
}
double interpolated_samples(double t_max_s, double output_dt_s, double max_steps) {
  if (output_dt_s <= 0) return max_steps;
  return std::floor(t_max_s / output_dt_s) + 1 + 64;
}

// A trajectory sample in memory (a vector grows by doubling: up to twice its size) and, with
// --out, its row of the table written out.
double sample_bytes(bool writes_file) {
  return 2.0 * sizeof(TrajectorySample) + (writes_file ? kTrajectoryColumns * kDouble : 0.0);
}

}  // namespace

ResourceEstimate estimate_scene(const StoneCase& c, double duration_s, double frame_rate_hz) {
  StoneCase over = c;
  over.realtime.t_max_s = std::max(c.realtime.t_max_s, duration_s);
  ResourceEstimate e = estimate_run(over, RunSolvers{true, false, false});
  const double frames = duration_s * frame_rate_hz;
  e.add_memory(frames * 64.0, std::to_string(static_cast<long long>(frames)) + " frames' records");
  return e;
}

ResourceEstimate estimate_movie(double frames, double images, double width_px, double height_px, double top_cells, double near_cells,
                                double record_bytes) {
  ResourceEstimate e;
  auto g = [](double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3g", v);
    return std::string(b);
  };
  const double pixels = width_px * height_px;
  e.add_work(images * pixels, kMaxMoviePixels, "movie pixels drawn (" + g(images) + " pictures × " + g(width_px) + "×" + g(height_px) + ")");
  const double per_frame_bytes = 4 * (top_cells * top_cells + near_cells * near_cells), per_image_bytes = 3 * pixels;
  e.add_work(frames * per_frame_bytes + images * per_image_bytes, kMaxMovieTemporaryBytes,
             "bytes of temporary disk (" + g(frames) + " frames × " + human_bytes(per_frame_bytes) + " of data, " + g(images) +
                 " pictures × " + human_bytes(per_image_bytes) + ")");
  e.add_memory(frames * record_bytes, g(frames) + " movie frames' records of " + human_bytes(record_bytes));
  return e;
}

double movie_picture_limit(double frames, double width_px, double height_px, double top_cells, double near_cells) {
  const double pixels = width_px * height_px, data = frames * 4 * (top_cells * top_cells + near_cells * near_cells);
  return std::max(0.0, std::min(kMaxMoviePixels / pixels, (kMaxMovieTemporaryBytes - data) / (3 * pixels)));
}

ResourceEstimate estimate_run(const StoneCase& c, const RunSolvers& solvers) {
  ResourceEstimate e;
  const double triangles = static_cast<double>(c.stone.body_mesh.triangles.size());
  e.add_memory(triangles * 64 * kDouble, "");  // mesh, normals, areas, clipping scratch: small
  if (solvers.realtime) {
    const RealtimeOptions& o = c.realtime;
    const double steps = realtime_steps(o), rhs = rhs_per_step(o.scheme);
    e.add_work(steps * rhs * triangles, kMaxTriangleEvaluations,
               "triangle evaluations of the real-time stepper (t_max_s / the shortest step = " + sci(steps) + " steps × " +
                   sci(rhs) + " right-hand sides × " + sci(triangles) + " triangles)");
    const double n = samples(o.t_max_s, o.output_dt_s, steps);
    e.add_memory(n * sample_bytes(solvers.writes_file), sci(n) + " trajectory samples of the real-time run");
    if (c.water) {
      const HeightFieldOptions& f = c.water->field;
      const double cells = static_cast<double>(f.nx) * f.ny;
      const double padded = static_cast<double>(f.nx + 2) * (f.ny + 2);
      const double water_steps = std::ceil(o.t_max_s / f.dt_s);
      e.add_work(cells * water_steps, kMaxCellUpdates,
                 "cell updates of the scene's water (" + sci(cells) + " cells × t_max_s / water.dt_s = " + sci(water_steps) +
                     " steps)");
      e.add_memory((3 * padded + cells) * kDouble, "the water's " + std::to_string(f.nx) + " x " + std::to_string(f.ny) + " field");
    }
  }
  if (solvers.reference) {
    const ReferenceOptions& o = c.reference;
    const double steps = static_cast<double>(o.max_steps);
    e.add_work(steps * triangles, kMaxTriangleEvaluations,
               "triangle evaluations of the reference ([reference] max_steps = " + sci(steps) + " × " + sci(triangles) +
                   " triangles)");
    const double n = interpolated_samples(o.t_max_s, o.output_dt_s, steps);
    e.add_memory(n * sample_bytes(solvers.writes_file), sci(n) + " trajectory samples of the reference");
    e.add_memory(steps * kDouble, human_bytes(steps * kDouble) + " for the located events' times, at most one a step ([reference] "
                                      "max_steps = " + sci(steps) + ")");
  }
  return e;
}

ResourceEstimate estimate_wave(const WaveCase& c) {
  ResourceEstimate e;
  const HeightFieldOptions& w = c.water;
  const double cells = static_cast<double>(w.nx) * w.ny;
  const bool periodic = w.boundary == Boundary::periodic;
  // Initial and final surfaces, the field's two levels and the Laplacian of its start; with the
  // reference: FFTW's real and half-complex buffers, the symbol, two transforms, its surface. A walled
  // pond's reference (solvers/spectral/walled_wave.hpp, since 7 December) holds FFTW's two real
  // buffers, the symbol, the two initial transforms, the evolved modes and its surface: measured
  // (peak RSS, 2048²) half an array above the periodic one's.
  const double arrays = periodic ? 10.5 : 11.5;
  e.add_memory(arrays * cells * kDouble, sci(arrays) + " arrays of " + std::to_string(w.nx) + " x " + std::to_string(w.ny) +
                                             " cells, the spectral reference included");
  const double steps = static_cast<double>(c.steps());
  e.add_work(cells * steps, kMaxCellUpdates, "cell updates (" + sci(cells) + " cells × " + sci(steps) + " steps)");
  return e;
}

ResourceEstimate estimate_sweep(const ResourceEstimate& heaviest_throw, double throws, double row_bytes, double threads) {
  ResourceEstimate e;
  e.add_memory(throws * row_bytes, "the table of " + sci(throws) + " throws");
  const double at_once = std::min(threads, std::max(throws, 1.0));  // no more threads than throws are started
  e.add_memory(at_once * heaviest_throw.memory_bytes, sci(at_once) + " throws at once");
  for (const auto& w : heaviest_throw.work) {
    e.add_work(w.count, w.limit, w.what + " in the heaviest throw of the design");
    e.add_work(throws * w.count, kSweepWorkFactor * w.limit, "worst-case " + w.what.substr(0, w.what.find(" (")) + " in all (" +
                                                                  sci(throws) + " throws × " + sci(w.count) + ")");
  }
  return e;
}

ResourceEstimate estimate_regress(const std::vector<BounceSweepSpec>& sweeps) {
  ResourceEstimate e;
  double total = 0, throws = 0;
  for (const auto& s : sweeps) {
    const double triangles = static_cast<double>(s.base.stone.body_mesh.triangles.size());
    const double per_throw = s.solver.kind == SolverKind::realtime
                                 ? realtime_steps(s.solver.realtime) * rhs_per_step(s.solver.realtime.scheme) * triangles
                                 : static_cast<double>(s.solver.reference.max_steps) * triangles;
    double widest = 0;
    for (std::size_t i = 1; i < s.values.size(); ++i) widest = std::max(widest, s.values[i] - s.values[i - 1]);
    const double halvings = widest > s.threshold_tolerance ? std::ceil(std::log2(widest / s.threshold_tolerance)) : 0;
    const double thresholds = std::min<double>(s.values.size() - 1, s.max_thresholds);
    const double n = static_cast<double>(s.values.size()) * (1 + std::max(0, s.ensemble_members)) + thresholds * halvings;
    e.add_work(per_throw, kMaxTriangleEvaluations, "triangle evaluations in one throw of baseline " + s.name);
    throws += n;
    total += n * per_throw;
  }
  e.add_work(total, kMaxRegressTriangleEvaluations,
             "triangle evaluations in all (" + sci(throws) + " throws at most, grids, ensembles and bisections)");
  return e;
}

}  // namespace stoneskip
