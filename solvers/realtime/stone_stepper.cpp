#include "solvers/realtime/stone_stepper.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

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
      out.orientation = dq * s.orientation;
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

}  // namespace

ThrowResult run_realtime(const Stone& stone, const Environment& env, const RigidState& initial,
                         const RealtimeOptions& o, const WaterSurface* surface,
                         const std::function<void(double t_s)>& before_step) {
  const auto clock_start = std::chrono::steady_clock::now();
  ThrowResult r;
  {
    std::ostringstream name;
    name << "realtime (" << to_string(o.scheme) << ", dt=" << o.dt_s << " s, contact dt=" << o.contact_dt_s << " s)";
    r.solver = name.str();
  }
  r.release_position_m = initial.position_m;
  ContactLog log;
  RigidState s = initial;
  s.orientation.normalize();
  double t = 0;
  double next_output = 0;
  DeepestPoint deep = deepest_point(stone, s, surface);
  auto record = [&](double tt, const RigidState& st, double wetted) {
    if (o.record_trajectory) r.trajectory.push_back(sample(stone, env, tt, st, wetted));
  };
  if (deep.depth_m > 0) log.start(0, s, deep.position_m, mechanical_energy(stone, env, s).total_J());
  record(0, s, 0);
  next_output = o.output_dt_s;
  r.outcome = Outcome::time_limit;
  r.outcome_detail = "reached t_max";

  while (t < o.t_max_s - 1e-12 * o.t_max_s) {
    if (before_step) {
      before_step(t);
      deep = deepest_point(stone, s, surface);  // the surface under the stone may have moved
    }
    // Step size: fine while in the water or while the lowest vertex could reach it in one flight
    // step (clearance < max vertex speed × dt).
    const double omega = angular_velocity(stone, s).norm();
    const double reach = (s.velocity_m_s.norm() + omega * stone.bounding_radius_m) * o.dt_s;
    const bool near = deep.depth_m > -reach;
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
    const DeepestPoint deep_new = deepest_point(stone, s_new, surface);
    const bool was_wet = deep.depth_m > 0, is_wet = deep_new.depth_m > 0;
    if (was_wet != is_wet) {
      // The deepest depth crosses zero inside the step: locate it by linear interpolation.
      const double f = deep.depth_m / (deep.depth_m - deep_new.depth_m);
      const double tc = t + f * dt;
      const RigidState sc = lerp(s, s_new, f);
      const double ec = mechanical_energy(stone, env, sc).total_J();
      if (is_wet)
        log.start(tc, sc, deep_new.position_m, ec);
      else
        log.end(tc, sc, ec, true);
      record(tc, sc, 0);
    }
    double wetted = 0;
    if (is_wet) {
      wetted = water_loads(stone, env, s_new, surface).wetted_area_m2;
      log.observe_wetted_area(wetted);
    }
    s = s_new;
    t = t_new;
    deep = deep_new;
    if (o.output_dt_s <= 0 || t >= next_output - 1e-12) {
      record(t, s, wetted);
      while (o.output_dt_s > 0 && next_output <= t + 1e-12) next_output += o.output_dt_s;
    }
    if (deep.submerged_vertices == deep.vertex_count) {
      // Spec §1.8: completely below the surface: nothing here lifts a submerged stone.
      r.outcome = Outcome::sank;
      std::ostringstream m;
      m << "completely under water at t = " << t << " s";
      r.outcome_detail = m.str();
      break;
    }
  }
  if (log.in_contact()) log.end(t, s, mechanical_energy(stone, env, s).total_J(), false);
  if (o.record_trajectory && (r.trajectory.empty() || r.trajectory.back().t_s < t)) record(t, s, 0);
  finish_result(r, log, s, t);
  r.stats.cpu_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return r;
}

}  // namespace stoneskip
