#include "solvers/realtime/stone_stepper.hpp"

#include <cmath>
#include <sstream>
#include <utility>

#include "solvers/realtime/clocks.hpp"

namespace stoneskip {

const char* to_string(Scheme s) {
  switch (s) {
    case Scheme::semi_implicit_euler: return "semi_implicit_euler";
    case Scheme::midpoint: return "midpoint";
    case Scheme::rk4: return "rk4";
  }
  return "?";
}

bool parse_scheme(const std::string& s, Scheme& out) {
  for (Scheme c : {Scheme::semi_implicit_euler, Scheme::midpoint, Scheme::rk4}) {
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
  }
  return 0;
}

namespace {

void normalise(RigidState& s) { s.orientation.normalize(); }

// y + h k on flat states.
StateVector axpy(const StateVector& y, double h, const StateVector& k) {
  StateVector out;
  for (int i = 0; i < kStateSize; ++i) out[i] = y[i] + h * k[i];
  return out;
}

StateVector rhs(const Stone& stone, const Environment& env, const StateVector& y, const WaterSurface* surface) {
  StateVector d;
  rigid_body_rhs(stone, env, y.data(), d.data(), surface);
  return d;
}

}  // namespace

RigidState realtime_step(const Stone& stone, const Environment& env, const RigidState& s, double dt,
                         Scheme scheme, const WaterSurface* surface, long* rhs_evaluations) {
  RigidState out;
  switch (scheme) {
    case Scheme::semi_implicit_euler: {
      // Forces at the start of the step; velocity and angular momentum first, then position with
      // the new velocity and orientation rotated by the new ω (exact rotation through |ω|dt).
      const StateDerivative d = rigid_body_rhs(stone, env, s, surface);
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
      const StateVector k1 = rhs(stone, env, y, surface);
      const StateVector k2 = rhs(stone, env, axpy(y, 0.5 * dt, k1), surface);
      if (rhs_evaluations) *rhs_evaluations += 2;
      out = from_vector(axpy(y, dt, k2).data());
      break;
    }
    case Scheme::rk4: {
      const StateVector y = to_vector(s);
      const StateVector k1 = rhs(stone, env, y, surface);
      const StateVector k2 = rhs(stone, env, axpy(y, 0.5 * dt, k1), surface);
      const StateVector k3 = rhs(stone, env, axpy(y, 0.5 * dt, k2), surface);
      const StateVector k4 = rhs(stone, env, axpy(y, dt, k3), surface);
      if (rhs_evaluations) *rhs_evaluations += 4;
      StateVector yn;
      for (int i = 0; i < kStateSize; ++i) yn[i] = y[i] + dt / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
      out = from_vector(yn.data());
      break;
    }
  }
  normalise(out);
  return out;
}

namespace {

RigidState lerp(const RigidState& a, const RigidState& b, double f) {
  RigidState s;
  s.position_m = a.position_m + f * (b.position_m - a.position_m);
  s.velocity_m_s = a.velocity_m_s + f * (b.velocity_m_s - a.velocity_m_s);
  s.orientation = a.orientation.slerp(f, b.orientation);
  s.angular_momentum_kg_m2_s = a.angular_momentum_kg_m2_s + f * (b.angular_momentum_kg_m2_s - a.angular_momentum_kg_m2_s);
  return s;
}

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

// A vertex crossing the surface inside a step: the fraction f ∈ [0, 1] of the step at which its
// depth, interpolated linearly between the step's ends (d0 at the start, d1 at the end), is zero.
struct Crossing {
  double fraction = 0;
  int vertex = -1;
};

// Among the vertices that go under in the step (d0 ≤ 0 < d1): the first (latest = false) or the
// last (latest = true) to cross. The first is where a contact starts; the last to go under while
// every vertex ends the step under water is where the stone sinks.
Crossing going_under(const Waterline& w0, const Waterline& w1, bool latest) {
  Crossing c;
  for (std::size_t j = 0; j < w0.depth_m.size(); ++j) {
    const double d0 = w0.depth_m[j], d1 = w1.depth_m[j];
    if (!(d0 <= 0 && d1 > 0)) continue;
    const double f = d0 / (d0 - d1);
    if (c.vertex < 0 || (latest ? f > c.fraction : f < c.fraction)) c = {f, static_cast<int>(j)};
  }
  if (c.vertex < 0) c = {0.0, w1.deepest};  // none crossed in the step: it was already so at its start
  return c;
}

// The last vertex to come out in the step (d0 > 0 ≥ d1): where a contact ends with every vertex dry.
Crossing last_out(const Waterline& w0, const Waterline& w1) {
  Crossing c;
  for (std::size_t j = 0; j < w0.depth_m.size(); ++j) {
    const double d0 = w0.depth_m[j], d1 = w1.depth_m[j];
    if (!(d0 > 0 && d1 <= 0)) continue;
    const double f = d0 / (d0 - d1);
    if (c.vertex < 0 || f > c.fraction) c = {f, static_cast<int>(j)};
  }
  if (c.vertex < 0) c = {0.0, w0.deepest};  // none crossed in the step: it was already so at its start
  return c;
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
                         const BeforeStepWithState& before_step) {
  const CpuTimer cpu;
  const WallTimer wall;
  ThrowResult r;
  {
    std::ostringstream name;
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

  bool going = settle(0);
  record(0, s, now.wet() ? wetted_area(s) : 0.0);
  double next_output = o.output_dt_s;
  while (going && t < o.t_max_s - 1e-12 * o.t_max_s) {
    if (before_step) {
      before_step(t, s);
      if (!settle(t)) break;  // the surface under the stone may have moved
    }
    // Step size: fine while in the water or while the lowest vertex could reach it in one flight
    // step (clearance < max vertex speed × dt).
    const double omega = angular_velocity(stone, s).norm();
    const double reach = (s.velocity_m_s.norm() + omega * stone.bounding_radius_m) * o.dt_s;
    const bool near = now.deepest_m() > -reach;
    double dt = near ? o.contact_dt_s : o.dt_s;
    if (t + dt > o.t_max_s) dt = o.t_max_s - t;
    const RigidState s_new = realtime_step(stone, env, s, dt, o.scheme, surface, &r.stats.rhs_evaluations);
    ++r.stats.steps;
    if (near) ++r.stats.contact_steps;
    const double t_new = t + dt;
    if (!finite(s_new)) {
      r.outcome = Outcome::failed;
      std::ostringstream m;
      m << "the state became NaN or infinite at t = " << t_new << " s (step " << dt << " s is unstable here)";
      r.outcome_detail = m.str();
      s = s_new;
      t = t_new;
      break;
    }
    measure_waterline(stone, s_new, surface, next);
    // Transitions inside the step, located by linear interpolation of the vertex depths (the
    // surface is fixed during a step): a contact starts where the first vertex goes under, ends
    // where the last comes out, and the stone sinks where the last goes under.
    if (!log.in_contact() && next.wet()) {
      const Crossing c = going_under(now, next, false);
      const RigidState sc = lerp(s, s_new, c.fraction);
      const double tc = t + c.fraction * dt;
      const Vec3 touch = world_vertex(stone, sc, sc.orientation.toRotationMatrix(), c.vertex);
      if (!logged(log.start(tc, sc, touch, energy(sc)), tc)) break;
      record(tc, sc, 0);
    } else if (log.in_contact() && !next.wet()) {
      const Crossing c = last_out(now, next);
      const RigidState sc = lerp(s, s_new, c.fraction);
      const double tc = t + c.fraction * dt;
      if (!logged(log.end(tc, sc, energy(sc), true), tc)) break;
      record(tc, sc, 0);
    }
    if (next.sunk()) {
      const Crossing c = going_under(now, next, true);
      s = lerp(s, s_new, c.fraction);
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
      wetted = wetted_area(s_new);
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
