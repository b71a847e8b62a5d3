#include "solvers/realtime/stone_stepper.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <utility>

#include "model/stone/load_switches.hpp"
#include "solvers/realtime/adaptive_step.hpp"
#include "solvers/realtime/clocks.hpp"
#include "solvers/realtime/dense_output.hpp"
#include "solvers/realtime/sliding_steps.hpp"
#include "solvers/realtime/state_scales.hpp"
#include "solvers/realtime/stone_events.hpp"

namespace stoneskip {

const char* to_string(Scheme s) {
  switch (s) {
    case Scheme::semi_implicit_euler: return "semi_implicit_euler";
    case Scheme::midpoint: return "midpoint";
    case Scheme::rk4: return "rk4";
    case Scheme::bs32: return "bs32";
    case Scheme::dp54: return "dp54";
  }
  return "?";
}

bool parse_scheme(const std::string& s, Scheme& out) {
  for (Scheme c : {Scheme::semi_implicit_euler, Scheme::midpoint, Scheme::rk4, Scheme::bs32, Scheme::dp54}) {
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
    case Scheme::dp54: return 5;
  }
  return 0;
}

int steady_spin_order(Scheme s) {
  if (s == Scheme::semi_implicit_euler) return formal_order(s);  // exact rotation (stone_stepper.hpp)
  const int p = formal_order(s);
  return p % 2 == 1 ? p + 1 : p;
}

bool is_adaptive(Scheme s) { return s == Scheme::bs32 || s == Scheme::dp54; }

const char* to_string(KinkSteps k) {
  switch (k) {
    case KinkSteps::none: return "none";
    case KinkSteps::crossings: return "crossings";
    case KinkSteps::all: return "all";
  }
  return "?";
}

bool parse_kink_steps(const std::string& s, KinkSteps& out) {
  for (KinkSteps k : {KinkSteps::none, KinkSteps::crossings, KinkSteps::all}) {
    if (s == to_string(k)) {
      out = k;
      return true;
    }
  }
  return false;
}

KinkSteps default_kink_steps(Scheme s) {
  if (s == Scheme::dp54) return KinkSteps::all;
  return is_adaptive(s) ? KinkSteps::crossings : KinkSteps::none;
}

namespace {

void normalise(RigidState& s) { s.orientation.normalize(); }

// y + h k on flat states.
StateVector axpy(const StateVector& y, double h, const StateVector& k) {
  StateVector out;
  for (int i = 0; i < kStateSize; ++i) out[i] = y[i] + h * k[i];
  return out;
}

StateVector rhs(const Stone& stone, const Environment& env, const StateVector& y, const WaterSurface* surface,
                std::vector<FacePush>* pushes = nullptr, const LoadMode* mode = nullptr) {
  StateVector d;
  rigid_body_rhs(stone, env, y.data(), d.data(), surface, pushes, mode);
  return d;
}

// The adaptive schemes' pair (adaptive_step.hpp): one trial, its right-hand sides, the next step.
AdaptiveTrial adaptive_trial(Scheme scheme, const Stone& stone, const Environment& env, const StateVector& y0,
                             const StateVector& k1, double h, const WaterSurface* surface, const StateVector& atol,
                             double rtol, const FieldFunction* field = nullptr, const LoadMode* mode = nullptr) {
  return scheme == Scheme::dp54 ? dp54_step(stone, env, y0, k1, h, surface, atol, rtol, field, mode)
                                : bs32_step(stone, env, y0, k1, h, surface, atol, rtol, field, mode);
}
long trial_rhs(Scheme scheme) { return scheme == Scheme::dp54 ? 6 : 3; }
double next_step(Scheme scheme, double h, double error_norm) {
  return scheme == Scheme::dp54 ? dp54_next_step(h, error_norm) : bs32_next_step(h, error_norm);
}

}  // namespace

namespace {

// One step of a scheme from s with its first stage k1 = f(s) given; the other stages are counted.
// `met_water` (optional) is set where a later stage felt the water's loads (midpoint, rk4).
RigidState step_from(const Stone& stone, const Environment& env, const RigidState& s, const StateVector& k1, double dt,
                     Scheme scheme, const WaterSurface* surface, long* rhs_evaluations, const LoadMode* mode = nullptr,
                     bool* met_water = nullptr) {
  // A later stage's f(y), the same numbers as rhs(); with met_water, whether its water loads wet a face.
  auto stage = [&](const StateVector& y) {
    if (!met_water) return rhs(stone, env, y, surface, nullptr, mode);
    Loads loads;
    const StateDerivative d = rigid_body_rhs(stone, env, from_vector(y.data()), surface, &loads, nullptr, mode);
    *met_water = *met_water || loads.water.wetted_area_m2 > 0;
    StateVector out;
    to_vector(d, out.data());
    return out;
  };
  RigidState out;
  switch (scheme) {
    case Scheme::semi_implicit_euler: {
      // Forces at the start of the step; velocity and angular momentum first, then position with
      // the new velocity and orientation rotated by the new ω (exact rotation through |ω|dt).
      const Vec3 dv(k1[kVelocity], k1[kVelocity + 1], k1[kVelocity + 2]);
      const Vec3 dl(k1[kAngularMomentum], k1[kAngularMomentum + 1], k1[kAngularMomentum + 2]);
      out.velocity_m_s = s.velocity_m_s + dt * dv;
      out.angular_momentum_kg_m2_s = s.angular_momentum_kg_m2_s + dt * dl;
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
      const StateVector k2 = stage(axpy(y, 0.5 * dt, k1));
      if (rhs_evaluations) *rhs_evaluations += 1;
      out = from_vector(axpy(y, dt, k2).data());
      break;
    }
    case Scheme::rk4: {
      const StateVector y = to_vector(s);
      const StateVector k2 = stage(axpy(y, 0.5 * dt, k1));
      const StateVector k3 = stage(axpy(y, 0.5 * dt, k2));
      const StateVector k4 = stage(axpy(y, dt, k3));
      if (rhs_evaluations) *rhs_evaluations += 3;
      StateVector yn;
      for (int i = 0; i < kStateSize; ++i) yn[i] = y[i] + dt / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
      out = from_vector(yn.data());
      break;
    }
    case Scheme::bs32:
    case Scheme::dp54: {
      // One step of the pair's higher-order solution at the given size (no error control).
      StateVector atol;
      atol.fill(1.0);
      const AdaptiveTrial t = adaptive_trial(scheme, stone, env, to_vector(s), k1, dt, surface, atol, 0.0);
      if (rhs_evaluations) *rhs_evaluations += trial_rhs(scheme);
      out = from_vector(t.y1.data());
      break;
    }
  }
  normalise(out);
  return out;
}

}  // namespace

RigidState realtime_step(const Stone& stone, const Environment& env, const RigidState& s, double dt,
                         Scheme scheme, const WaterSurface* surface, long* rhs_evaluations,
                         std::vector<FacePush>* start_pushes, bool* stage_met_water) {
  const StateVector k1 = rhs(stone, env, to_vector(s), surface, start_pushes);
  if (rhs_evaluations) ++*rhs_evaluations;
  return step_from(stone, env, s, k1, dt, scheme, surface, rhs_evaluations, nullptr, stage_met_water);
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

enum class Direction { under, out };
enum class Pick { first, last };

// Among the vertices that cross in the step in the given direction (under: d0 ≤ 0 < d1; out:
// d0 > 0 ≥ d1): the first or the last to cross, on the interpolant. None crossed: fraction 0 and
// `fallback` (it was already so at the step's start). The first to go under is where a contact
// starts; the last to go under while every vertex ends the step under water is where the stone
// sinks; the last to come out is where a contact ends with every vertex dry.
Crossing locate(const HermiteStep& step, const Stone& stone, const WaterSurface* surface, const Waterline& w0,
                const Waterline& w1, Direction dir, Pick pick, int fallback) {
  Crossing c;
  for (std::size_t j = 0; j < w0.depth_m.size(); ++j) {
    const double d0 = w0.depth_m[j], d1 = w1.depth_m[j];
    const bool under = d0 <= 0 && d1 > 0, out = d0 > 0 && d1 <= 0;
    if (!(dir == Direction::under ? under : out)) continue;
    const double f = crossing_fraction(step, stone, surface, static_cast<int>(j), d0, d1);
    if (c.vertex < 0 || (pick == Pick::last ? f > c.fraction : f < c.fraction)) c = {f, static_cast<int>(j)};
  }
  if (c.vertex < 0) c = {0.0, fallback};
  return c;
}

// A fixed step cut back to a kink ends this fraction of the step past it: far below any step, and
// a kink left that close inside the next step costs O((fraction · dt)²) there.
constexpr double kFixedKinkWindow = 1e-6;

// The kinks a step watches (KinkSteps) and the first of them inside a step: the fraction θ of
// the step just past it, located on the step's Hermite interpolant. Vertex crossings are read from
// the depths at the step's ends (so over live water too); face and air switches from the switching
// functions of stone_events.hpp, in the mode of the step's start.
class KinkWatch {
 public:
  KinkWatch(const Stone& stone, const Environment& env, const WaterSurface* surface, KinkSteps kinks)
      : stone_(stone), surface_(surface), kinks_(kinks) {
    if (kinks == KinkSteps::all) {
      events_ = std::make_unique<StoneEvents>(stone, env, true, surface);
      if (events_->count() == events_->vertex_count()) {
        events_.reset();  // nothing but the crossings (the paper convention, no air switch)
      } else {
        g0_.assign(events_->count(), 0.0);
        g1_ = g0_;
        under_.assign(events_->vertex_count(), 0);
      }
      loads_ = std::make_unique<LoadSwitches>(stone, env, surface);
      if (!loads_->active()) loads_.reset();
    }
  }
  bool active() const { return kinks_ != KinkSteps::none; }
  // The loaded region held over the step (load_switches.hpp), or null where nothing is held.
  const LoadMode* held() const { return loads_ ? &loads_->load_mode() : nullptr; }
  // Whether the loaded region held over this step differs from the one held over the step before
  // (a right-hand side at the step's end then is not one at this step's start).
  bool held_changed() const { return held_changed_; }
  // The step's start state: the mode (vertices under water, live faces) and the functions there.
  void start(const StateVector& y0) {
    // The pressure distribution's switches, in the mode of the step's start (load_switches.hpp).
    if (loads_) {
      previous_held_ = loads_->load_mode().loaded_faces;
      const int previous_side = loads_->load_mode().underside;
      loads_->reset(from_vector(y0.data()), l0_);
      held_changed_ = previous_held_ != loads_->load_mode().loaded_faces ||
                      previous_side != loads_->load_mode().underside;
    }
    if (!events_) return;
    const std::vector<char> before = under_;
    events_->set_mode(from_vector(y0.data()));
    for (int j = 0; j < events_->vertex_count(); ++j) under_[j] = events_->vertex_under(j);
    // The step before ended here in the same mode: its end values are these.
    if (have_g1_ && y0 == y1_ && under_ == before) {
      g0_ = g1_;
      ok0_ = true;
    } else {
      ok0_ = events_->evaluate(y0.data(), g0_.data());
    }
    have_g1_ = false;
  }
  // The first kink with θ > skip_below (a kink the step before was cut to lies just after its
  // start), located to fraction_tolerance; negative when no watched function changes sign. A
  // function's search stops once its bracket lies past the earliest kink found so far: the result
  // is the same, bit for bit, at a fraction of the evaluations where many switches change sign.
  double first(const HermiteStep& dense, const Waterline& w0, const Waterline& w1, double fraction_tolerance,
               double skip_below) {
    double first = 2;
    if (kinks_ == KinkSteps::none) return -1;
    for (std::size_t j = 0; j < w0.depth_m.size(); ++j) {
      const double d0 = w0.depth_m[j], d1 = w1.depth_m[j];
      if ((d0 > 0) == (d1 > 0)) continue;
      const double f = crossing_fraction(dense, stone_, surface_, static_cast<int>(j), d0, d1, fraction_tolerance);
      if (f > skip_below) first = std::min(first, f);
    }
    have_g1_ = events_ && ok0_ && events_->evaluate(dense.y1.data(), g1_.data());
    if (have_g1_) {
      y1_ = dense.y1;
      for (int k = events_->vertex_count(); k < events_->count(); ++k) {
        if ((g0_[k] > 0) == (g1_[k] > 0)) continue;
        const double f = sign_change_fraction(
            [&](double c) {
              const StateVector y = dense.at(c);
              return events_->value(y.data(), k);
            },
            g0_[k], g1_[k], fraction_tolerance, first);
        if (f > skip_below) first = std::min(first, f);
      }
    }
    if (loads_) {
      loads_->evaluate(from_vector(dense.y1.data()), l1_);
      for (std::size_t k = 0; k < l0_.size(); ++k) {
        // A value that does not exist at an end (NaN), or sits on a tie (0), is no sign change.
        if (!(l0_[k] * l1_[k] < 0)) continue;
        const double f = sign_change_fraction(
            [&](double c) { return loads_->value(from_vector(dense.at(c).data()), static_cast<int>(k)); }, l0_[k],
            l1_[k], fraction_tolerance, first);
        if (f > skip_below) first = std::min(first, f);
      }
    }
    return first <= 1 ? first : -1;
  }

 private:
  const Stone& stone_;
  const WaterSurface* surface_;
  KinkSteps kinks_;
  std::unique_ptr<StoneEvents> events_;
  std::unique_ptr<LoadSwitches> loads_;  // all, under savitsky and savitsky_wagner
  std::vector<double> g0_, g1_;
  std::vector<double> l0_, l1_;  // loads_' values at the step's start and end
  std::vector<char> previous_held_;   // the loaded region held over the step before
  bool held_changed_ = false;
  std::vector<char> under_;  // the mode of the last start
  StateVector y1_{};         // where g1_ was evaluated (the last trial's end)
  bool ok0_ = false, have_g1_ = false;
};

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

// The flight's right-hand side at s (gravity and air; the water's loads left out): the slope at
// the end of a step that a contact starts inside, for the interpolant the entry is located on.
// Before the first vertex goes under the stone is in flight; f at a step's end under water holds
// the water's loads at the full depth the step reached, and a cubic Hermite through that slope
// swings the flight part of the step far off the scheme's own states (a 5 ms semi-implicit Euler
// step into the water at 30 m/s gave an entry speed of 32.2 m/s against 29.9 m/s).
StateVector flight_rhs_at(const Stone& stone, const Environment& env, const RigidState& s, const WaterSurface* surface) {
  Loads loads;
  StateDerivative d = rigid_body_rhs(stone, env, s, surface, &loads);
  d.dvelocity -= loads.water.force_N / stone.mass.mass_kg;
  if (env.attitude != Attitude::held) d.dangular_momentum -= loads.water.torque_N_m;
  StateVector y{};
  to_vector(d, y.data());
  return y;
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
  const KinkSteps kink_steps = o.kinks.value_or(default_kink_steps(o.scheme));
  {
    std::ostringstream name;
    if (adaptive)
      name << "realtime (" << to_string(o.scheme) << ", rtol=" << o.rtol << ", atol=" << o.atol_m << " m, max dt=" << o.dt_s
           << " s";
    else
      name << "realtime (" << to_string(o.scheme) << ", dt=" << o.dt_s << " s, contact dt=" << o.contact_dt_s << " s";
    // What departs from the scheme's defaults.
    if (kink_steps != default_kink_steps(o.scheme)) name << ", kinks " << to_string(kink_steps);
    if (adaptive && o.rhs_per_frame > 0) name << ", at most " << o.rhs_per_frame << " rhs per " << o.frame_dt_s << " s frame";
    name << ")";
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
  KinkWatch kinks(stone, env, surface, kink_steps);
  SlidingSteps sliding(stone, env, adaptive && o.slide && surface == nullptr);  // bs32 in still water (sliding_steps.hpp)
  // The frame budget (bs32): the end of the current frame and the right-hand sides spent before it began.
  const bool budgeted = adaptive && o.rhs_per_frame > 0;
  double frame_end_s = 0;
  long frame_rhs0 = 0;

  // Guards (adaptive steps): a window of max_steps_per_ms steps must span 1 ms or more; and in the
  // physical convention, whose forces only take energy away (model/README.md §1.6), a total energy
  // above kRunawayFactor × (release energy + 1 J) is a state that ran away (steps forced by a
  // budget far beyond what the throw allows, or an unstable fixed step), not a throw.
  constexpr double kRunawayFactor = 1e3;
  const double runaway_J = kRunawayFactor * (std::abs(energy(initial)) + 1.0);
  // The window holds at least twice the steps of the largest step allowed (a case may allow
  // nanosecond steps); max_steps_per_ms ≤ 0: no collapse guard.
  const long collapse_window =
      o.max_steps_per_ms > 0 ? std::max<long>(o.max_steps_per_ms, static_cast<long>(std::ceil(2e-3 / o.dt_s))) : 0;
  long window_steps = 0;
  double window_t = 0;
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
    HermiteStep dense;  // the step's interpolant; filled here for bs32 and kink-watching steps, else at a transition
    bool have_dense = false;
    double trial_wetted_m2 = 0;  // bs32: the wetted area at the step's end
    constexpr int kMaxKinkCuts = 64;  // each cut shortens the step; a guard, never reached in practice
    if (!adaptive) {
      // Step size: fine while in the water or while the lowest vertex could reach it in one flight
      // step (clearance < max vertex speed × dt).
      const double omega = angular_velocity(stone, s).norm();
      const double reach = (s.velocity_m_s.norm() + omega * stone.bounding_radius_m) * o.dt_s;
      near = now.deepest_m() > -reach;
      dt = near ? o.contact_dt_s : o.dt_s;
      if (t + dt > o.t_max_s) dt = o.t_max_s - t;
      if (!kinks.active()) {
        bool stage_wet = false;
        s_new = realtime_step(stone, env, s, dt, o.scheme, surface, &r.stats.rhs_evaluations, step_start_pushes, &stage_wet);
        if (finite(s_new)) measure_waterline(stone, s_new, surface, next);
        // A step whose stages felt the water while neither end is wet passed through a contact that
        // no step resolved: no contact is logged, and the loads changed the throw (a game-frame rk4
        // step of a grazing throw). Counted and said, never silent.
        if (stage_wet && finite(s_new) && !now.wet() && !next.wet() && !log.in_contact()) {
          if (r.stats.steps_through_water++ == 0) r.stats.first_step_through_water_s = t;
        }
      } else {
        // Steps that end at the kinks: a trial over which a watched function changes sign is cut back
        // to just past its first root and taken again; f at the end (the interpolant's, and the next
        // step's first stage) costs one right-hand side.
        const StateVector y0 = to_vector(s);
        kinks.start(y0);
        // The step before ended in the region it held: its last stage is this step's first only
        // where this step holds the same region.
        if (!have_k || kinks.held_changed()) {
          k_start = rhs(stone, env, y0, surface, step_start_pushes);
          ++r.stats.rhs_evaluations;
          have_k = true;
        }
        StateVector k_end{};
        // The distributed pressure's loaded region is held over the step (LoadMode): each stage
        // sees one branch of the loads, and a step cut back to where the region changes ends a
        // window past the switch still on the old branch; the next step starts on the new one.
        const LoadMode* held = kinks.held();
        // The window is the step's as first tried: a kink within it of the start is behind the
        // step, and a cut step ends it past the kink. (Relative to each cut trial instead, the
        // window shrank with every cut, and where a retaken step's end and the trial's interpolant
        // disagree on a root, as a first-order scheme's can by O(dt²), the cuts converged on it
        // without end.)
        const double window = kFixedKinkWindow * dt;
        for (int attempt = 0;; ++attempt) {
          s_new = step_from(stone, env, s, k_start, dt, o.scheme, surface, &r.stats.rhs_evaluations, held);
          if (!finite(s_new)) break;
          const StateVector y1 = to_vector(s_new);
          k_end = rhs(stone, env, y1, surface, nullptr, held);
          ++r.stats.rhs_evaluations;
          measure_waterline(stone, s_new, surface, next);
          dense = HermiteStep{y0, y1, k_start, k_end, dt};
          const double f = attempt < kMaxKinkCuts ? kinks.first(dense, now, next, kFullFractionTolerance, window / dt) : -1;
          if (f > 0 && (1 - f) * dt > window) {
            dt = f * dt + window;
            ++r.stats.root_evaluations;
            continue;
          }
          break;
        }
        k_start = k_end;  // the next step's first stage (FSAL), if it holds the same region
        have_dense = true;
      }
      if (!finite(s_new)) {
        std::ostringstream m;
        m << "the state became NaN or infinite (step " << dt << " s is unstable here)";
        failed(t + dt, m.str());
        s = s_new;
        t = t + dt;
        break;
      }
    } else {
      // Error-controlled step; a trial whose ends differ in a watched kink (by default the wetted
      // set) is cut back to just past its first kink (located on its interpolant), so each kink
      // lies within two event windows of a step's end and the error estimate sees smooth steps.
      near = now.wet();
      const StateVector y0 = to_vector(s);
      if (budgeted && t >= frame_end_s - 1e-9 * o.frame_dt_s) {
        while (frame_end_s <= t + 1e-9 * o.frame_dt_s) frame_end_s += o.frame_dt_s;
        frame_rhs0 = r.stats.rhs_evaluations;
      }
      if (sliding.probe(r.stats.steps, t, s)) have_k = false;  // the steps stalled at an attracting switch
      kinks.start(y0);
      // dp54 holds the distributed pressure's loaded region over the step (kinks `all`; LoadMode),
      // as the fixed schemes do: a step cut back to a face's switch ends a window past it with every
      // stage on the old branch, and the next step starts on the new one. Without it its sixth stage
      // (c = 1, weight 11/84 in its solution) sees the new branch, and the step errs by 11/84 of its
      // length × the jump, whatever the window (solvers/README.md, "The pressure distributions' own
      // switches"). bs32's stage at c = 1 has weight 0 in its solution: held, it kept the same bench
      // counts for 4 % more right-hand sides, so it does not hold.
      const LoadMode* held = o.scheme == Scheme::dp54 && !sliding.active() ? kinks.held() : nullptr;
      // The step before ended in the region it held: its last stage is this step's first only where
      // this step holds the same region.
      if (!have_k || (held && kinks.held_changed())) {
        k_start = sliding.active() ? sliding.rhs(y0) : rhs(stone, env, y0, surface, step_start_pushes, held);
        ++r.stats.rhs_evaluations;
        have_k = true;
      }
      if (sliding.active()) sliding.start_step(y0);
      double h_resume = 0;  // the controller's proposal before an event cut the step back
      bool ok = false;
      AdaptiveTrial trial;
      int cuts = 0;  // kink cuts of this step (error-test rejections do not count against the guard)
      for (;;) {
        double hh = std::min({h, o.dt_s, o.t_max_s - t});
        if (!now.wet()) hh = std::min(hh, flight_step_limit(stone, env, s, -now.deepest_m(), dip_m, surface == nullptr));
        // With a budget: the step ends by the frame's end and is no shorter than the budget left
        // allows (each trial costs trial_rhs right-hand sides); such a step is accepted whatever its error.
        double floor_h = 0;
        if (budgeted) {
          const double left_s = std::min(frame_end_s, o.t_max_s) - t;
          const long trials = std::max(1L, (o.rhs_per_frame - (r.stats.rhs_evaluations - frame_rhs0)) / trial_rhs(o.scheme));
          floor_h = left_s / static_cast<double>(trials);
          hh = std::clamp(hh, floor_h, left_s);
        }
        if (!(hh > 1e-14 * std::max(1.0, t))) {
          // Say what the stone was doing: a step this short is a state running away (the paper
          // convention's energy gain spins a stone up without bound) or a jump in the force.
          std::ostringstream m;
          // The paper convention's printed forces create energy (spec §1.6): a thousandfold gain
          // is the model running away, not the stepper failing, and is named so.
          if (env.convention == Convention::paper && energy(s) > 1e3 * std::max(std::abs(energy(initial)), 1e-3))
            m << "the paper convention's printed forces ran the stone away (model/README.md §1.6; a thousandfold energy gain); ";
          m << "the adaptive step fell below round-off (speed " << s.velocity_m_s.norm() << " m/s, spin "
            << angular_velocity(stone, s).norm() << " rad/s, energy " << energy(s) << " J against "
            << energy(initial) << " J at release)";
          failed(t, m.str());
          break;
        }
        trial = adaptive_trial(o.scheme, stone, env, y0, k_start, hh, surface, atol, o.rtol, sliding.field(), held);
        r.stats.rhs_evaluations += trial_rhs(o.scheme);
        const bool forced = budgeted && hh <= floor_h * (1 + 1e-12);
        if (forced && !std::isfinite(trial.error_norm)) {
          // The budget holds the step at its floor: a shorter retry would be lengthened to the same
          // step and fail the same way, for ever. A state that is not a number is a failure.
          failed(t, "the state is not a number after a step the frame's budget forces (step " + std::to_string(hh) +
                        " s): the right-hand side is not finite there");
          break;
        }
        if (!(trial.error_norm <= 1.0) && !(forced && std::isfinite(trial.error_norm))) {  // too large, or NaN
          ++r.stats.error_test_failures;
          h = std::isfinite(trial.error_norm) ? next_step(o.scheme, hh, trial.error_norm) : 0.25 * hh;
          continue;
        }
        const RigidState candidate = from_vector(trial.y1.data());
        measure_waterline(stone, candidate, surface, next);
        dense = HermiteStep{y0, trial.y1, k_start, trial.k4, hh, trial.quartic, trial.has_quartic};
        if (cuts < kMaxKinkCuts) {
          // Located to a tenth of the window: enough to end the cut step past the kink.
          const double f = kinks.first(dense, now, next, 0.1 * event_window_s / hh, 0.0);
          const double cut = f * hh + event_window_s;
          if (f > 0 && (1 - f) * hh > 2 * event_window_s && cut >= floor_h) {
            if (h_resume == 0) h_resume = next_step(o.scheme, hh, trial.error_norm);
            h = cut;
            ++cuts;
            ++r.stats.root_evaluations;  // real-time: steps cut back to a kink
            continue;
          }
        }
        if (sliding.active() && cuts < kMaxKinkCuts) {
          // A sliding's exit or a hold's end inside the trial: cut back to just past it, as a kink.
          const double f = sliding.first_root(dense);
          const double cut = f * hh + event_window_s;
          if (f > 0 && (1 - f) * hh > 2 * event_window_s && cut >= floor_h) {
            if (h_resume == 0) h_resume = next_step(o.scheme, hh, trial.error_norm);
            h = cut;
            ++cuts;
            ++r.stats.root_evaluations;
            continue;
          }
        }
        if (trial.error_norm > 1.0) ++r.stats.budget_forced_steps;
        dt = hh;
        s_new = candidate;
        h = std::max(next_step(o.scheme, hh, trial.error_norm), h_resume);
        r.stats.max_error_ratio = std::max(r.stats.max_error_ratio, trial.error_norm);
        r.stats.position_error_estimate_m += trial.position_error_m;
        ok = true;
        break;
      }
      if (!ok) break;
      k_start = trial.k4;  // FSAL
      trial_wetted_m2 = sliding.active() ? wetted_area(s_new) : trial.wetted_area_m2;
      have_dense = true;
      if (sliding.after_step(t + dt, trial.y1)) have_k = false;  // the rules changed: f at the end with them
    }
    ++r.stats.steps;
    if (near) ++r.stats.contact_steps;
    const double t_new = t + dt;
    if (adaptive && collapse_window > 0 && r.stats.steps - window_steps >= collapse_window) {
      if (t_new - window_t < 1e-3) {
        std::ostringstream m;
        m << "the adaptive step collapsed: " << r.stats.steps - window_steps << " steps from t = " << window_t
          << " s to " << t_new << " s, less than 1 ms (RealtimeOptions::max_steps_per_ms; speed "
          << s_new.velocity_m_s.norm() << " m/s, spin " << angular_velocity(stone, s_new).norm() << " rad/s, energy "
          << energy(s_new) << " J against " << energy(initial)
          << " J at release): a contact too stiff for an explicit scheme, a vertex held at the surface (the CVODE "
             "reference, implicit, may solve these), or a state running away";
        if (const std::string what = sliding.record().sliding_what(); !what.empty()) m << "; it collapsed while sliding along " << what;
        failed(t_new, m.str());
        s = s_new;
        t = t_new;
        break;
      }
      window_steps = r.stats.steps;
      window_t = t_new;
    }
    if (env.convention == Convention::physical && !(energy(s_new) <= runaway_J)) {
      std::ostringstream m;
      m << "the state ran away: energy " << energy(s_new) << " J against " << energy(initial)
        << " J at release, which the physical convention's forces cannot give (steps of " << dt
        << " s: too long for this throw)";
      failed(t_new, m.str());
      s = s_new;
      t = t_new;
      break;
    }
    // Transitions inside the step, located on the step's cubic Hermite interpolant (the surface is
    // fixed during a step): a contact starts where the first vertex goes under, ends where the last
    // comes out, and the stone sinks where the last goes under.
    const bool starts = !log.in_contact() && next.wet(), ends = log.in_contact() && !next.wet();
    if (!have_dense && (starts || ends || next.sunk())) {
      dense = HermiteStep{to_vector(s), to_vector(s_new), rhs_at(stone, env, s, surface), rhs_at(stone, env, s_new, surface), dt};
      r.stats.rhs_evaluations += 2;
    }
    if (starts) {
      // Without steps cut at the crossings (a fixed step), the entry is located on the flight's
      // interpolant (flight_rhs_at); a sinking in the same step on the full one.
      HermiteStep entry = dense;
      if (!have_dense) {
        entry.f1 = flight_rhs_at(stone, env, s_new, surface);
        ++r.stats.rhs_evaluations;
      }
      const Crossing c = locate(entry, stone, surface, now, next, Direction::under, Pick::first, next.deepest);
      const RigidState sc = entry.state_at(c.fraction);
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
      // The first output time past t, found at once: stepping it up by output_dt_s hung on an
      // output_dt_s far below the step (1e-14 s: 1e11 additions a 1 ms step; 1e-300 s: none that move it).
      if (o.output_dt_s > 0 && next_output <= t + 1e-12)
        next_output = o.output_dt_s * (std::floor((t + 1e-12) / o.output_dt_s) + 1);
    }
  }
  if (log.in_contact()) log.end(t, s, energy(s), false);
  if (o.record_trajectory && (r.trajectory.empty() || r.trajectory.back().t_s < t))
    record(t, s, r.outcome != Outcome::failed && now.wet() ? wetted_area(s) : 0.0);
  finish_result(r, log, s, t);
  r.stats.rhs_evaluations += sliding.extra_loads();  // right-hand sides are load evaluations
  r.outcome_detail += sliding.record().summary(t, "stalled");
  r.stats.cpu_s = cpu.seconds();
  r.stats.wall_s = wall.seconds();
  return r;
}

}  // namespace stoneskip
