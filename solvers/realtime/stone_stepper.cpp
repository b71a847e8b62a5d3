#include "solvers/realtime/stone_stepper.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "solvers/realtime/adaptive_step.hpp"
#include "solvers/realtime/clocks.hpp"
#include "solvers/realtime/dense_output.hpp"
#include "solvers/realtime/state_scales.hpp"

namespace stoneskip {

const char* to_string(Scheme s) {
  switch (s) {
    case Scheme::semi_implicit_euler: return "semi_implicit_euler";
    case Scheme::midpoint: return "midpoint";
    case Scheme::rk4: return "rk4";
    case Scheme::bs32: return "bs32";
  }
  return "?";
}

bool parse_scheme(const std::string& s, Scheme& out) {
  for (Scheme c : {Scheme::semi_implicit_euler, Scheme::midpoint, Scheme::rk4, Scheme::bs32}) {
    if (s == to_string(c)) {
      out = c;
      return true;
    }
  }
  return false;
}

int formal_order(Scheme s) {
  switch (s) {
    case Scheme::semi_implicit_euler: return 1;
    case Scheme::midpoint: return 2;
    case Scheme::rk4: return 4;
    case Scheme::bs32: return 3;
  }
  return 0;
}

bool is_adaptive(Scheme s) { return s == Scheme::bs32; }

namespace {

void normalise(RigidState& s) { s.orientation.normalize(); }

// y + h k on flat states.
StateVector axpy(const StateVector& y, double h, const StateVector& k) {
  StateVector out;
  for (int i = 0; i < kStateSize; ++i) out[i] = y[i] + h * k[i];
  return out;
}

StateVector rhs(const Stone& stone, const Environment& env, const StateVector& y, const WaterSurface* surface,
                std::vector<FacePush>* pushes = nullptr) {
  StateVector d;
  rigid_body_rhs(stone, env, y.data(), d.data(), surface, pushes);
  return d;
}

}  // namespace

RigidState realtime_step(const Stone& stone, const Environment& env, const RigidState& s, double dt,
                         Scheme scheme, const WaterSurface* surface, long* rhs_evaluations,
                         std::vector<FacePush>* start_pushes) {
  RigidState out;
  switch (scheme) {
    case Scheme::semi_implicit_euler: {
      // Forces at the start of the step; velocity and angular momentum first, then position with
      // the new velocity and orientation rotated by the new ω (exact rotation through |ω|dt).
      const StateDerivative d = rigid_body_rhs(stone, env, s, surface, nullptr, start_pushes);
      if (rhs_evaluations) ++*rhs_evaluations;
      out.velocity_m_s = s.velocity_m_s + dt * d.dvelocity;
      out.angular_momentum_kg_m2_s = s.angular_momentum_kg_m2_s + dt * d.dangular_momentum;
      out.position_m = s.position_m + dt * out.velocity_m_s;
      RigidState tmp = s;
      tmp.angular_momentum_kg_m2_s = out.angular_momentum_kg_m2_s;
      const Vec3 w = angular_velocity(stone, tmp);
      const double angle = w.norm() * dt;
      const Quat dq = angle > 0 ? Quat(Eigen::AngleAxisd(angle, w.normalized())) : Quat::Identity();
      // Attitude held (model/stone/environment.hpp): the orientation stays, like dq/dt = 0 in the rhs.
      out.orientation = env.attitude == Attitude::held ? s.orientation : dq * s.orientation;
      break;
    }
    case Scheme::midpoint: {
      const StateVector y = to_vector(s);
      const StateVector k1 = rhs(stone, env, y, surface, start_pushes);
      const StateVector k2 = rhs(stone, env, axpy(y, 0.5 * dt, k1), surface);
      if (rhs_evaluations) *rhs_evaluations += 2;
      out = from_vector(axpy(y, dt, k2).data());
      break;
    }
    case Scheme::rk4: {
      const StateVector y = to_vector(s);
      const StateVector k1 = rhs(stone, env, y, surface, start_pushes);
      const StateVector k2 = rhs(stone, env, axpy(y, 0.5 * dt, k1), surface);
      const StateVector k3 = rhs(stone, env, axpy(y, 0.5 * dt, k2), surface);
      const StateVector k4 = rhs(stone, env, axpy(y, dt, k3), surface);
      if (rhs_evaluations) *rhs_evaluations += 4;
      StateVector yn;
      for (int i = 0; i < kStateSize; ++i) yn[i] = y[i] + dt / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
      out = from_vector(yn.data());
      break;
    }
    case Scheme::bs32: {
      // One step of the pair's third-order solution at the given size (no error control).
      const StateVector y = to_vector(s);
      const StateVector k1 = rhs(stone, env, y, surface, start_pushes);
      StateVector atol;
      atol.fill(1.0);
      const Bs32Trial t = bs32_step(stone, env, y, k1, dt, surface, atol, 0.0);
      if (rhs_evaluations) *rhs_evaluations += 4;
      out = from_vector(t.y1.data());
      break;
    }
  }
  normalise(out);
  return out;
}

namespace {

bool finite(const RigidState& s) {
  return s.position_m.allFinite() && s.velocity_m_s.allFinite() && s.orientation.coeffs().allFinite() &&
         s.angular_momentum_kg_m2_s.allFinite();
}

TrajectorySample sample(const Stone& stone, const Environment& env, double t, const RigidState& s, double wetted) {
  TrajectorySample p;
  p.t_s = t;
  p.state = s;
  p.angular_velocity_rad_s = angular_velocity(stone, s);
  p.energy_J = mechanical_energy(stone, env, s).total_J();
  p.wetted_area_m2 = wetted;
  return p;
}

// A vertex crossing the surface inside a step: the fraction θ ∈ [0, 1] of the step at which its
// depth along the step's Hermite interpolant is zero.
struct Crossing {
  double fraction = 0;
  int vertex = -1;
};

enum class Direction { under, out, either };
enum class Pick { first, last };

// Among the vertices that cross in the step in the given direction (under: d0 ≤ 0 < d1; out:
// d0 > 0 ≥ d1): the first or the last to cross, on the interpolant. None crossed: fraction 0 and
// `fallback` (it was already so at the step's start). The first to go under is where a contact
// starts; the last to go under while every vertex ends the step under water is where the stone
// sinks; the last to come out is where a contact ends with every vertex dry.
Crossing locate(const HermiteStep& step, const Stone& stone, const WaterSurface* surface, const Waterline& w0,
                const Waterline& w1, Direction dir, Pick pick, int fallback,
                double fraction_tolerance = kFullFractionTolerance) {
  Crossing c;
  for (std::size_t j = 0; j < w0.depth_m.size(); ++j) {
    const double d0 = w0.depth_m[j], d1 = w1.depth_m[j];
    const bool under = d0 <= 0 && d1 > 0, out = d0 > 0 && d1 <= 0;
    if (!(dir == Direction::under ? under : dir == Direction::out ? out : (under || out))) continue;
    const double f = crossing_fraction(step, stone, surface, static_cast<int>(j), d0, d1, fraction_tolerance);
    if (c.vertex < 0 || (pick == Pick::last ? f > c.fraction : f < c.fraction)) c = {f, static_cast<int>(j)};
  }
  if (c.vertex < 0) c = {0.0, fallback};
  return c;
}

// Whether any vertex is under water at one end of a step and not at the other.
bool wetted_set_changed(const Waterline& w0, const Waterline& w1) {
  for (std::size_t j = 0; j < w0.depth_m.size(); ++j)
    if ((w0.depth_m[j] > 0) != (w1.depth_m[j] > 0)) return true;
  return false;
}

// The largest flight step after which no vertex can be deeper than dip_m (the depth of a dip
// that a step could enter and leave unseen): the lowest vertex, `clearance_m` above the water,
// closes at most at the centre's sinking speed plus |ω| r_bound, plus gravity's ½ g h². On live
// water, whose height varies under a stone moving sideways, the closing speed is |v| + |ω| r_bound.
double flight_step_limit(const Stone& stone, const Environment& env, const RigidState& s, double clearance_m,
                         double dip_m, bool flat_water) {
  const double rim = angular_velocity(stone, s).norm() * stone.bounding_radius_m;
  const double closing = (flat_water ? std::max(0.0, -s.velocity_m_s.z()) : s.velocity_m_s.norm()) + rim;
  const double reach = clearance_m + dip_m;
  const double g = std::max(0.0, env.gravity_m_s2);
  // closing h + ½ g h² = reach, in the form without cancellation.
  const double disc = std::sqrt(closing * closing + 2 * g * reach);
  if (!(closing + disc > 0)) return std::numeric_limits<double>::infinity();
  return 2 * reach / (closing + disc);
}

StateVector rhs_at(const Stone& stone, const Environment& env, const RigidState& s, const WaterSurface* surface) {
  return rhs(stone, env, to_vector(s), surface);
}

}  // namespace

ThrowResult run_realtime(const Stone& stone, const Environment& env, const RigidState& initial,
                         const RealtimeOptions& o, const WaterSurface* surface,
                         const std::function<void(double t_s)>& before_step) {
  if (!before_step) return run_realtime(stone, env, initial, o, surface, BeforeStepWithState{});
  return run_realtime(stone, env, initial, o, surface, [&](double t_s, const RigidState&) { before_step(t_s); });
}

ThrowResult run_realtime(const Stone& stone, const Environment& env, const RigidState& initial,
                         const RealtimeOptions& o, const WaterSurface* surface,
                         const BeforeStepWithState& before_step, std::vector<FacePush>* step_start_pushes) {
  const CpuTimer cpu;
  const WallTimer wall;
  ThrowResult r;
  const bool adaptive = is_adaptive(o.scheme);
  {
    std::ostringstream name;
    if (adaptive)
      name << "realtime (" << to_string(o.scheme) << ", rtol=" << o.rtol << ", atol=" << o.atol_m << " m, max dt=" << o.dt_s
           << " s)";
    else
      name << "realtime (" << to_string(o.scheme) << ", dt=" << o.dt_s << " s, contact dt=" << o.contact_dt_s << " s)";
    r.solver = name.str();
  }
  r.release_position_m = initial.position_m;
  r.outcome = Outcome::time_limit;
  r.outcome_detail = "reached t_max";
  ContactLog log;
  RigidState s = initial;
  s.orientation.normalize();
  double t = 0;
  Waterline now, next;  // vertex depths at the start and at the end of a step
  auto record = [&](double tt, const RigidState& st, double wetted) {
    if (o.record_trajectory) r.trajectory.push_back(sample(stone, env, tt, st, wetted));
  };
  auto wetted_area = [&](const RigidState& st) { return water_loads(stone, env, st, surface).wetted_area_m2; };
  auto energy = [&](const RigidState& st) { return mechanical_energy(stone, env, st).total_J(); };
  // Every transition goes through the log, which refuses one that would make contacts overlap;
  // the logic below keeps the log in step with the wet state, so a refusal is a bug, reported.
  auto logged = [&](ContactLog::Status status, double tt) {
    if (status == ContactLog::Status::ok) return true;
    r.outcome = Outcome::failed;
    std::ostringstream m;
    m << "contact log at t = " << tt << " s: " << to_string(status);
    r.outcome_detail = m.str();
    return false;
  };
  auto failed = [&](double tt, const std::string& why) {
    r.outcome = Outcome::failed;
    std::ostringstream m;
    m << why << " at t = " << tt << " s";
    r.outcome_detail = m.str();
  };
  auto sank_at = [&](double tt) {
    r.outcome = Outcome::sank;
    std::ostringstream m;
    m << "completely under water at t = " << tt << " s";
    r.outcome_detail = m.str();
  };
  // Brings the log in line with the wet state of s at time tt after a jump of the surface (the
  // start of the throw, or the water moved by before_step): a contact that the water starts or
  // ends, or a stone that the water covers, happens at tt. False when the throw ends here.
  auto settle = [&](double tt) {
    measure_waterline(stone, s, surface, now);
    bool changed = false, ok = true;
    if (now.wet() && !log.in_contact()) {
      const Vec3 touch = world_vertex(stone, s, s.orientation.toRotationMatrix(), now.deepest);
      ok = logged(log.start(tt, s, touch, energy(s)), tt);
      changed = true;
    } else if (!now.wet() && log.in_contact()) {
      ok = logged(log.end(tt, s, energy(s), true), tt);
      changed = true;
    }
    const bool sinks = ok && now.sunk();
    if (changed || sinks) {  // the wetted area only where something happened (it costs a force evaluation)
      const double wetted = now.wet() ? wetted_area(s) : 0.0;
      log.observe_wetted_area(wetted);
      if (sinks) {
        // Spec §1.8: completely below the surface: nothing here lifts a submerged stone.
        ok = logged(log.end(tt, s, energy(s), false), tt);
        if (ok) sank_at(tt);
      }
      if (tt > 0) record(tt, s, wetted);
    }
    return ok && r.outcome != Outcome::sank;
  };

  // The adaptive scheme's tolerances per component, its event window (the time in which the
  // stone's fastest point moves atol_m: a step that changes the wetted set is accepted when every
  // crossing lies within two windows of its end), the depth of a dip a flight step may leave
  // unseen, and the first step (the time to move 1 % of the stone's radius).
  const StateScales scales = state_scales(stone, initial, env.gravity_m_s2);
  const StateVector atol = scaled_absolute_tolerances(o.atol_m, scales);
  const double event_window_s = o.atol_m / scales.speed_m_s;
  const double dip_m = 1e-3 * stone.bounding_radius_m;
  double h = std::min(o.dt_s, 1e-2 * scales.length_m / scales.speed_m_s);
  StateVector k_start{};  // f at the start of the step (FSAL), valid while have_k
  bool have_k = false;

  bool going = settle(0);
  record(0, s, now.wet() ? wetted_area(s) : 0.0);
  double next_output = o.output_dt_s;
  while (going && t < o.t_max_s - 1e-12 * o.t_max_s) {
    if (before_step) {
      before_step(t, s);
      if (step_start_pushes) step_start_pushes->clear();
      // The surface may have moved: f(y) with it (still water cannot); a scene that presses the
      // water with the faces' pushes needs them from this step's own start.
      if (surface || step_start_pushes) have_k = false;
      if (!settle(t)) break;  // the surface under the stone may have moved
    }
    RigidState s_new;
    double dt = 0;
    bool near = false;
    HermiteStep dense;  // the step's interpolant; filled here for bs32, at a transition for the others
    bool have_dense = false;
    double trial_wetted_m2 = 0;  // bs32: the wetted area at the step's end
    if (!adaptive) {
      // Step size: fine while in the water or while the lowest vertex could reach it in one flight
      // step (clearance < max vertex speed × dt).
      const double omega = angular_velocity(stone, s).norm();
      const double reach = (s.velocity_m_s.norm() + omega * stone.bounding_radius_m) * o.dt_s;
      near = now.deepest_m() > -reach;
      dt = near ? o.contact_dt_s : o.dt_s;
      if (t + dt > o.t_max_s) dt = o.t_max_s - t;
      s_new = realtime_step(stone, env, s, dt, o.scheme, surface, &r.stats.rhs_evaluations, step_start_pushes);
      if (!finite(s_new)) {
        std::ostringstream m;
        m << "the state became NaN or infinite (step " << dt << " s is unstable here)";
        failed(t + dt, m.str());
        s = s_new;
        t = t + dt;
        break;
      }
      measure_waterline(stone, s_new, surface, next);
    } else {
      // Error-controlled step; a trial whose ends have different wetted sets is cut back to just
      // past its first crossing (located on its interpolant), so each kink of the right-hand side
      // lies within two event windows of a step's end and the error estimate sees smooth steps.
      near = now.wet();
      const StateVector y0 = to_vector(s);
      if (!have_k) {
        k_start = rhs(stone, env, y0, surface, step_start_pushes);
        ++r.stats.rhs_evaluations;
        have_k = true;
      }
      double h_resume = 0;  // the controller's proposal before an event cut the step back
      bool ok = false;
      Bs32Trial trial;
      for (int attempt = 0;; ++attempt) {
        double hh = std::min({h, o.dt_s, o.t_max_s - t});
        if (!now.wet()) hh = std::min(hh, flight_step_limit(stone, env, s, -now.deepest_m(), dip_m, surface == nullptr));
        if (!(hh > 1e-14 * std::max(1.0, t))) {
          failed(t, "the adaptive step fell below round-off");
          break;
        }
        trial = bs32_step(stone, env, y0, k_start, hh, surface, atol, o.rtol);
        r.stats.rhs_evaluations += 3;
        if (!(trial.error_norm <= 1.0)) {  // too large, or NaN
          ++r.stats.error_test_failures;
          h = std::isfinite(trial.error_norm) ? bs32_next_step(hh, trial.error_norm) : 0.25 * hh;
          continue;
        }
        const RigidState candidate = from_vector(trial.y1.data());
        measure_waterline(stone, candidate, surface, next);
        dense = HermiteStep{y0, trial.y1, k_start, trial.k4, hh};
        constexpr int kMaxEventCuts = 64;  // each cut shortens the step; a guard, never reached in practice
        if (attempt < kMaxEventCuts && wetted_set_changed(now, next)) {
          // Located to a tenth of the window: enough to end the cut step past the crossing.
          const Crossing c =
              locate(dense, stone, surface, now, next, Direction::either, Pick::first, -1, 0.1 * event_window_s / hh);
          if ((1 - c.fraction) * hh > 2 * event_window_s) {
            if (h_resume == 0) h_resume = bs32_next_step(hh, trial.error_norm);
            h = c.fraction * hh + event_window_s;
            ++r.stats.root_evaluations;  // real-time bs32: steps cut back to a crossing
            continue;
          }
        }
        dt = hh;
        s_new = candidate;
        h = std::max(bs32_next_step(hh, trial.error_norm), h_resume);
        ok = true;
        break;
      }
      if (!ok) break;
      k_start = trial.k4;  // FSAL
      trial_wetted_m2 = trial.wetted_area_m2;
      have_dense = true;
    }
    ++r.stats.steps;
    if (near) ++r.stats.contact_steps;
    const double t_new = t + dt;
    // Transitions inside the step, located on the step's cubic Hermite interpolant (the surface is
    // fixed during a step): a contact starts where the first vertex goes under, ends where the last
    // comes out, and the stone sinks where the last goes under.
    const bool starts = !log.in_contact() && next.wet(), ends = log.in_contact() && !next.wet();
    if (!have_dense && (starts || ends || next.sunk())) {
      dense = HermiteStep{to_vector(s), to_vector(s_new), rhs_at(stone, env, s, surface), rhs_at(stone, env, s_new, surface), dt};
      r.stats.rhs_evaluations += 2;
    }
    if (starts) {
      const Crossing c = locate(dense, stone, surface, now, next, Direction::under, Pick::first, next.deepest);
      const RigidState sc = dense.state_at(c.fraction);
      const double tc = t + c.fraction * dt;
      const Vec3 touch = world_vertex(stone, sc, sc.orientation.toRotationMatrix(), c.vertex);
      if (!logged(log.start(tc, sc, touch, energy(sc)), tc)) break;
      record(tc, sc, 0);
    } else if (ends) {
      const Crossing c = locate(dense, stone, surface, now, next, Direction::out, Pick::last, now.deepest);
      const RigidState sc = dense.state_at(c.fraction);
      const double tc = t + c.fraction * dt;
      if (!logged(log.end(tc, sc, energy(sc), true), tc)) break;
      record(tc, sc, 0);
    }
    if (next.sunk()) {
      const Crossing c = locate(dense, stone, surface, now, next, Direction::under, Pick::last, next.deepest);
      s = dense.state_at(c.fraction);
      t += c.fraction * dt;
      const double wetted = wetted_area(s);
      log.observe_wetted_area(wetted);
      if (!logged(log.end(t, s, energy(s), false), t)) break;
      record(t, s, wetted);
      sank_at(t);
      break;
    }
    double wetted = 0;
    if (next.wet()) {
      // bs32 evaluated the loads at s_new for its FSAL stage: their wetted area is this one.
      wetted = have_dense && adaptive ? trial_wetted_m2 : wetted_area(s_new);
      log.observe_wetted_area(wetted);
    }
    s = s_new;
    t = t_new;
    std::swap(now, next);
    if (o.output_dt_s <= 0 || t >= next_output - 1e-12) {
      record(t, s, wetted);
      while (o.output_dt_s > 0 && next_output <= t + 1e-12) next_output += o.output_dt_s;
    }
  }
  if (log.in_contact()) log.end(t, s, energy(s), false);
  if (o.record_trajectory && (r.trajectory.empty() || r.trajectory.back().t_s < t))
    record(t, s, r.outcome != Outcome::failed && now.wet() ? wetted_area(s) : 0.0);
  finish_result(r, log, s, t);
  r.stats.cpu_s = cpu.seconds();
  r.stats.wall_s = wall.seconds();
  return r;
}

}  // namespace stoneskip
