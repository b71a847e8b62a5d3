#include "verification/captures/capture_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>

#include "model/coupling/draught.hpp"
#include "model/coupling/pressure_head.hpp"
#include "model/stone/fluid_forces.hpp"
#include "solvers/realtime/clocks.hpp"
#include "solvers/realtime/stone_stepper.hpp"
#include "solvers/reference/cvode_stone.hpp"
#include "solvers/scene/draught_window.hpp"
#include "solvers/spectral/forced_walled_wave.hpp"

namespace stoneskip {

bool CaptureSceneOptions::valid(std::string* why) const {
  auto fail = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (!scene.valid(why)) return false;
  if (scene.end != SceneEnd::at_duration) return fail("the scene must run to its duration (SceneEnd::at_duration)");
  if (!(reference_output_dt_s > 0) || !std::isfinite(reference_output_dt_s))
    return fail("reference_output_dt_s must be > 0");
  if (!(quadrature_interval_s > 0) || !std::isfinite(quadrature_interval_s))
    return fail("quadrature_interval_s must be > 0");
  if (quadrature_nodes < 1 || quadrature_nodes > 32) return fail("quadrature_nodes must be in [1, 32]");
  if (!(max_reference_cell_transforms > 0)) return fail("max_reference_cell_transforms must be > 0");
  return agreement.valid(why);
}

// ---- the trajectory's pose between samples ----

TrajectoryPose::TrajectoryPose(const std::vector<TrajectorySample>& samples) : samples_(samples) {
  // Located events can repeat a time: keep the last sample of each time, so intervals have length > 0.
  std::vector<TrajectorySample> kept;
  for (const auto& s : samples_) {
    if (!kept.empty() && s.t_s <= kept.back().t_s) kept.back() = s;
    else kept.push_back(s);
  }
  samples_ = std::move(kept);
}

std::optional<RigidState> TrajectoryPose::at(double t_s) const {
  if (samples_.empty() || t_s > samples_.back().t_s) return std::nullopt;
  if (t_s <= samples_.front().t_s) return samples_.front().state;
  const auto hi = std::upper_bound(samples_.begin(), samples_.end(), t_s,
                                   [](double t, const TrajectorySample& s) { return t < s.t_s; });
  if (hi == samples_.end()) return samples_.back().state;
  const RigidState& a = (hi - 1)->state;
  const RigidState& b = hi->state;
  const double h = hi->t_s - (hi - 1)->t_s, u = (t_s - (hi - 1)->t_s) / h;
  // Cubic Hermite basis on [0, 1].
  const double h00 = (1 + 2 * u) * (1 - u) * (1 - u), h10 = u * (1 - u) * (1 - u), h01 = u * u * (3 - 2 * u),
               h11 = u * u * (u - 1);
  RigidState s = a;
  s.position_m = h00 * a.position_m + h10 * h * a.velocity_m_s + h01 * b.position_m + h11 * h * b.velocity_m_s;
  s.velocity_m_s = (1 - u) * a.velocity_m_s + u * b.velocity_m_s;
  s.orientation = a.orientation.normalized().slerp(u, b.orientation.normalized());
  s.angular_momentum_kg_m2_s = (1 - u) * a.angular_momentum_kg_m2_s + u * b.angular_momentum_kg_m2_s;
  return s;
}

namespace {

// Adds a patch into a dense nx × ny grid (row-major): wrapped on a periodic grid, clipped elsewhere.
void add_wrapped(const DraughtPatch& p, int nx, int ny, bool periodic, std::vector<double>& grid) {
  if (p.empty()) return;
  for (int c = 0; c < p.nj; ++c)
    for (int a = 0; a < p.ni; ++a) {
      int i = p.i0 + a, j = p.j0 + c;
      if (periodic) {
        i = ((i % nx) + nx) % nx;
        j = ((j % ny) + ny) % ny;
      } else if (i < 0 || j < 0 || i >= nx || j >= ny) {
        continue;
      }
      grid[static_cast<std::size_t>(j) * nx + i] += p.at(a, c);
    }
}

}  // namespace

DraughtField trajectory_draught(const Mesh& body_mesh, const HeightFieldOptions& field, const FieldPlacement& placement,
                                const TrajectoryPose& pose) {
  struct State {
    State(const Mesh& mesh, const HeightFieldOptions& options) : draught(mesh), flat(options) {}
    StoneDraught draught;
    HeightField flat;  // at rest: the draught against the flat surface
    DraughtPatch patch;
  };
  HeightFieldOptions flat_options = field;
  flat_options.threads = 1;
  flat_options.mode = StepMode::full;
  auto st = std::make_shared<State>(body_mesh, flat_options);
  const int nx = field.nx, ny = field.ny;
  const bool periodic = field.boundary == Boundary::periodic;
  return [st, nx, ny, periodic, placement, pose](double t_s, std::vector<double>& b) {
    b.assign(static_cast<std::size_t>(nx) * ny, 0.0);
    const std::optional<RigidState> s = pose.at(t_s);
    if (!s) return;
    st->draught.compute(*s, st->flat, placement, st->patch);
    add_wrapped(st->patch, nx, ny, periodic, b);
  };
}

DraughtField trajectory_pressure_head(const Stone& stone, const Environment& env, const HeightFieldOptions& field,
                                      const FieldPlacement& placement, const TrajectoryPose& pose, int smoothing_passes) {
  struct State {
    std::vector<FacePush> pushes;
    DraughtPatch patch;
    std::vector<double> scratch;
  };
  auto st = std::make_shared<State>();
  const int nx = field.nx, ny = field.ny;
  const double cell = field.cell_m;
  const bool periodic = field.boundary == Boundary::periodic;
  const double rho_g = env.water_density_kg_m3 * env.gravity_m_s2;
  return [st, stone, env, nx, ny, cell, periodic, rho_g, placement, pose, smoothing_passes](double t_s,
                                                                                           std::vector<double>& h) {
    h.assign(static_cast<std::size_t>(nx) * ny, 0.0);
    const std::optional<RigidState> s = pose.at(t_s);
    if (!s) return;
    water_loads(stone, env, *s, nullptr, &st->pushes);  // the flat surface: still water
    rasterise_pressure_head(st->pushes, cell, placement, rho_g, st->patch);
    // As the scene does (solvers/scene/coupled_scene.cpp): a walled pond keeps the grid's points of
    // the head, and what the smoothing spills past a wall is reflected back onto the grid.
    if (!periodic) drop_beyond_rim(st->patch, nx, ny, st->scratch);
    smooth_conservatively(st->patch, smoothing_passes, st->scratch);
    if (!periodic) fold_onto_walled_grid(st->patch, nx, ny, st->scratch);
    add_wrapped(st->patch, nx, ny, periodic, h);
  };
}

std::vector<double> hat_forced_leapfrog(const HeightFieldOptions& field, const std::vector<double>& initial_m,
                                        const DraughtField& head, double piece_s, long steps) {
  HeightField f(field);
  if (!initial_m.empty()) f.set_state(initial_m);
  const bool periodic = field.boundary == Boundary::periodic;
  DraughtWindow cur(field.nx, field.ny, periodic), next(field.nx, field.ny, periodic);
  std::vector<double> h;
  DraughtPatch sample, step_patch;
  const double dt = field.dt_s;
  const int pieces = std::max(1, static_cast<int>(std::ceil(dt / piece_s - 1e-9)));
  for (long n = 0; n < steps; ++n) {
    // [t_n, t_n+1]: step n's falling half and step n+1's rising half (∫ hat/Δt over a piece
    // [a, b] is (b − a)/Δt · (1 − r) and (b − a)/Δt · r, r = ((a + b)/2 − t_n)/Δt, exact for a
    // head constant on the piece).
    const double t_n = f.time_s();
    for (int q = 0; q < pieces; ++q) {
      const double r = (q + 0.5) / pieces;
      head(t_n + r * dt, h);
      sample.reset(0, 0, field.nx, field.ny);
      bool any = false;
      for (std::size_t c = 0; c < h.size(); ++c) {
        sample.b_m[c] = h[c];
        any = any || h[c] != 0;
      }
      if (!any) continue;
      cur.add(sample, (1.0 - r) / pieces);
      next.add(sample, r / pieces);
    }
    cur.take(step_patch);
    std::swap(cur, next);
    f.step(step_patch);
  }
  std::vector<double> z;
  f.heights(z);
  return z;
}

std::vector<double> prescribed_forced_leapfrog(const HeightFieldOptions& field, const std::vector<double>& initial_m,
                                               const DraughtField& draught, int samples_per_step, long steps) {
  HeightField f(field);
  if (!initial_m.empty()) f.set_state(initial_m);
  const bool periodic = field.boundary == Boundary::periodic;
  DraughtWindow window(field.nx, field.ny, periodic);
  std::vector<double> b;
  DraughtPatch sample, step_patch;
  const double dt = field.dt_s;
  const int k = samples_per_step;
  for (long n = 0; n < steps; ++n) {
    const double t_n = f.time_s();
    for (int q = 0; q < k; ++q) {
      // The scene's node rule (draught_window.hpp); nodes before t = 0 see the stone at its release.
      const double node = std::max(0.0, t_n - 0.5 * dt + (q + 0.5) * dt / k);
      draught(node, b);
      sample.reset(0, 0, field.nx, field.ny);
      bool wet = false;
      for (std::size_t c = 0; c < b.size(); ++c) {
        sample.b_m[c] = b[c];
        wet = wet || b[c] > 0;
      }
      if (wet) window.add(sample, 1.0 / k);
    }
    window.take(step_patch);
    f.step(step_patch);
  }
  std::vector<double> z;
  f.heights(z);
  return z;
}

namespace {

double max_abs_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

// The forced reference on the scene's pond: the Fourier one on a periodic pond, the cosine or sine
// one on a walled pond (solvers/spectral/forced_walled_wave.hpp), whose walls are where the
// leapfrog's ghost cells put them and whose head is taken on the grid's points as the scene takes it.
std::vector<double> spectral(const HeightFieldOptions& field, SpectralSymbol symbol, const std::vector<double>& initial_m,
                             const DraughtField& draught, const DuhamelQuadrature& q, double t_s, long& transforms) {
  const std::vector<double> initial =
      initial_m.empty() ? std::vector<double>(static_cast<std::size_t>(field.nx) * field.ny, 0.0) : initial_m;
  std::vector<double> z;
  if (field.boundary != Boundary::periodic) {
    ForcedWalledWave w(walled_wave_options(field, symbol), draught, q);
    w.set_initial(initial);
    w.evaluate(t_s, z);
    transforms += w.draught_transforms();
    return z;
  }
  ForcedSpectralWave w(spectral_wave_options(field, symbol), draught, q);
  w.set_initial(initial);
  w.evaluate(t_s, z);
  transforms += w.draught_transforms();
  return z;
}

// Contacts paired by overlapping time: a contact of one run that overlaps none of the other's is
// unpaired (a sub-millisecond rim contact of one run alone must not shift every later pair, as
// pairing the i-th with the i-th did). Both lists are in time order; the one that ends first moves on.
std::vector<std::pair<int, int>> paired_by_overlap(const std::vector<ContactRecord>& a, const std::vector<ContactRecord>& b) {
  std::vector<std::pair<int, int>> out;
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (a[i].start_s <= b[j].end_s && b[j].start_s <= a[i].end_s) {
      out.emplace_back(static_cast<int>(i), static_cast<int>(j));
      ++i;
      ++j;
    } else if (a[i].end_s < b[j].end_s) {
      ++i;
    } else {
      ++j;
    }
  }
  return out;
}

void compare_contacts(CaptureSceneComparison& out) {
  const auto& sc = out.scene.stone.contacts;
  const auto& rc = out.reference.contacts;
  const auto& wc = out.still_water.contacts;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<int> still_of(rc.size(), -1);
  for (const auto& [w, r] : paired_by_overlap(wc, rc)) {
    still_of[r] = w;
    out.still_max_start_difference_s = std::max(out.still_max_start_difference_s, std::abs(wc[w].start_s - rc[r].start_s));
  }
  for (const auto& [i, r] : paired_by_overlap(sc, rc)) {
    SceneContactComparison c;
    c.index = r + 1;
    c.scene_start_s = sc[i].start_s;
    c.scene_end_s = sc[i].end_s;
    c.reference_start_s = rc[r].start_s;
    c.reference_end_s = rc[r].end_s;
    c.still_start_s = still_of[r] >= 0 ? wc[still_of[r]].start_s : nan;
    c.still_end_s = still_of[r] >= 0 ? wc[still_of[r]].end_s : nan;
    c.scene_exit_x_m = sc[i].exit_position_m.x();
    c.reference_exit_x_m = rc[r].exit_position_m.x();
    c.scene_bounced = sc[i].bounced;
    c.reference_bounced = rc[r].bounced;
    out.max_start_difference_s = std::max(out.max_start_difference_s, std::abs(c.scene_start_s - c.reference_start_s));
    out.max_end_difference_s = std::max(out.max_end_difference_s, std::abs(c.scene_end_s - c.reference_end_s));
    out.contacts.push_back(c);
  }
}

}  // namespace

CaptureSceneComparison compare_capture_scene(const CaptureSceneOptions& o) {
  std::string why;
  if (!o.valid(&why)) throw std::invalid_argument("capture scene: " + why);
  CaptureSceneComparison out;
  SceneOptions so = o.scene;
  so.stone_steps.output_dt_s = o.reference_output_dt_s;  // the scene stone's path, for the forcing it would make

  // The scene, keeping the field at its last frame.
  std::vector<double> last_field;
  double field_t = 0;
  long field_steps = 0;
  const long frames = so.frames();
  out.scene = run_scene(so, [&](const SceneFrame& f) {
    if (f.index == frames && f.field) {
      f.field->heights(last_field);
      field_t = f.field->time_s();
      field_steps = f.field->steps();
    }
  });
  out.scene.frame_costs.clear();

  // The stepper on still water, and CVODE.
  RealtimeOptions still = so.stone_steps;
  still.t_max_s = std::min(still.t_max_s, so.end_s());
  out.still_water = run_realtime(so.stone, so.environment, so.initial, still);
  ReferenceOptions ro = o.reference;
  ro.t_max_s = std::min(ro.t_max_s, so.end_s());
  ro.output_dt_s = o.reference_output_dt_s;
  ro.record_trajectory = true;
  out.reference = run_reference(so.stone, so.environment, so.initial, ro);
  compare_contacts(out);

  // The ensembles on still water: the stepper against CVODE.
  out.agreement = nudged_agreement(so.stone, so.environment, so.initial, still, ro, o.agreement);

  // The waves.
  if (so.coupling != Coupling::two_way) {
    out.waves_not_compared = std::string("the scene's coupling is ") + to_string(so.coupling) + ": the stone makes no waves";
    return out;
  }
  if (out.reference.outcome == Outcome::failed) {
    out.waves_not_compared = "the CVODE reference failed (" + out.reference.outcome_detail + ")";
    return out;
  }
  const HeightFieldOptions& field = so.water->field;
  DuhamelQuadrature q;
  q.nodes = o.quadrature_nodes;
  q.intervals = std::max(1, static_cast<int>(std::ceil(field_t / o.quadrature_interval_s - 1e-9)));
  q.intervals += q.intervals % 2;  // even: the estimate's coarse evaluation has exactly twice the sub-interval
  const double work = 2.5 * q.intervals * q.nodes * static_cast<double>(field.nx) * field.ny;
  if (work > o.max_reference_cell_transforms) {
    char b[240];
    std::snprintf(b, sizeof b,
                  "the references would take %.3g cell-transforms of b (%d sub-intervals of %d nodes on %d × %d cells), "
                  "more than the limit of %.3g",
                  work, q.intervals, q.nodes, field.nx, field.ny, o.max_reference_cell_transforms);
    out.waves_not_compared = b;
    return out;
  }
  const CpuTimer cpu;
  const WallTimer wall;
  WaveComparison& w = out.waves;
  w.t_s = field_t;
  w.steps = field_steps;
  w.scene_m = last_field;
  // The head the references prescribe, and the leapfrog gathering it as the scene does: the
  // pressure head with hat weights on pieces of the scene's contact step, or the draught in
  // windows of K samples.
  const bool pressure = so.forcing == Forcing::pressure;
  auto prescribed = [&](const TrajectoryPose& p) {
    return pressure ? trajectory_pressure_head(so.stone, so.environment, field, so.water->placement, p,
                                               pressure_smoothing_passes(so.head_width_m, field.cell_m))
                    : trajectory_draught(so.stone.body_mesh, field, so.water->placement, p);
  };
  auto leapfrog = [&](const DraughtField& h) {
    return pressure ? hat_forced_leapfrog(field, so.water->initial_m, h, so.stone_steps.contact_dt_s, w.steps)
                    : prescribed_forced_leapfrog(field, so.water->initial_m, h, so.draught_samples, w.steps);
  };
  const TrajectoryPose pose(out.reference.trajectory);
  const DraughtField b = prescribed(pose);
  w.prescribed_m = leapfrog(b);
  w.own_path_m = leapfrog(prescribed(TrajectoryPose(out.scene.stone.trajectory)));
  w.quadrature_intervals = q.intervals;
  w.semi_discrete_m = spectral(field, SpectralSymbol::stencil, so.water->initial_m, b, q, w.t_s, w.transforms);
  w.continuum_m = spectral(field, SpectralSymbol::continuum, so.water->initial_m, b, q, w.t_s, w.transforms);
  DuhamelQuadrature coarse = q;
  coarse.intervals = q.intervals / 2;
  const std::vector<double> coarse_m =
      spectral(field, SpectralSymbol::continuum, so.water->initial_m, b, coarse, w.t_s, w.transforms);
  for (double z : w.continuum_m) w.amplitude_m = std::max(w.amplitude_m, std::abs(z));
  w.model_m = max_abs_difference(w.scene_m, w.prescribed_m);
  w.path_m = max_abs_difference(w.own_path_m, w.prescribed_m);
  w.feedback_m = max_abs_difference(w.scene_m, w.own_path_m);
  w.time_m = max_abs_difference(w.prescribed_m, w.semi_discrete_m);
  w.space_m = max_abs_difference(w.semi_discrete_m, w.continuum_m);
  w.total_m = max_abs_difference(w.scene_m, w.continuum_m);
  w.quadrature_m = max_abs_difference(w.continuum_m, coarse_m);
  w.reference_cpu_s = cpu.seconds();
  w.reference_wall_s = wall.seconds();
  out.waves_compared = true;
  return out;
}

}  // namespace stoneskip
