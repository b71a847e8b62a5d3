#include "solvers/scene/coupled_scene.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "model/coupling/pressure_head.hpp"
#include "model/stone/fluid_forces.hpp"
#include "model/water/height_field_surface.hpp"
#include "solvers/realtime/clocks.hpp"
#include "solvers/scene/draught_window.hpp"
#include "solvers/scene/wave_energy.hpp"

namespace stoneskip {

const char* to_string(Coupling c) {
  switch (c) {
    case Coupling::none: return "none";
    case Coupling::one_way: return "one_way";
    case Coupling::two_way: return "two_way";
  }
  return "?";
}

bool parse_coupling(const std::string& s, Coupling& out) {
  for (Coupling c : {Coupling::none, Coupling::one_way, Coupling::two_way})
    if (s == to_string(c)) {
      out = c;
      return true;
    }
  return false;
}

const char* to_string(Forcing f) {
  switch (f) {
    case Forcing::pressure: return "pressure";
    case Forcing::displacement: return "displacement";
  }
  return "?";
}

bool parse_forcing(const std::string& s, Forcing& out) {
  for (Forcing f : {Forcing::pressure, Forcing::displacement})
    if (s == to_string(f)) {
      out = f;
      return true;
    }
  return false;
}

const char* to_string(FreeWater f) {
  switch (f) {
    case FreeWater::one_at_a_time: return "one_at_a_time";
    case FreeWater::to_the_next_frame: return "to_the_next_frame";
    case FreeWater::to_the_next_look: return "to_the_next_look";
  }
  return "?";
}

bool parse_free_water(const std::string& s, FreeWater& out) {
  for (FreeWater f : {FreeWater::one_at_a_time, FreeWater::to_the_next_frame, FreeWater::to_the_next_look})
    if (s == to_string(f)) {
      out = f;
      return true;
    }
  return false;
}

const char* to_string(LevelInTime l) { return l == LevelInTime::held ? "held" : "extrapolated"; }

bool parse_level_in_time(const std::string& s, LevelInTime& out) {
  for (LevelInTime l : {LevelInTime::held, LevelInTime::extrapolated})
    if (s == to_string(l)) {
      out = l;
      return true;
    }
  return false;
}

double EnergyBudget::residual() const {
  const double gained = end_J - start_J;
  const double scale = std::max({std::abs(pressure_work_J), std::abs(gained), damping_loss_J});
  return scale > 0 ? std::abs(gained - pressure_work_J + damping_loss_J) / scale : 0.0;
}

const char* to_string(StoneStatus s) {
  switch (s) {
    case StoneStatus::in_play: return "in_play";
    case StoneStatus::sank: return "sank";
    case StoneStatus::ended: return "ended";
  }
  return "?";
}

long SceneOptions::frames() const {
  if (!(duration_s > 0) || !(frame_rate_hz > 0)) return 0;
  return static_cast<long>(std::floor(duration_s * frame_rate_hz + 1e-9));
}

double SceneOptions::end_s() const { return frame_rate_hz > 0 ? static_cast<double>(frames()) / frame_rate_hz : 0; }

int pressure_smoothing_passes(double head_width_m, double cell_m) {
  if (!(head_width_m > 0)) return kPressureSmoothingPasses;
  const double ratio = head_width_m / cell_m;
  if (!(ratio <= kMaxHeadWidthCells)) return 0;
  return std::max(kPressureSmoothingPasses, static_cast<int>(std::lround(2 * ratio * ratio)));
}

bool SceneOptions::valid(std::string* why) const {
  auto fail = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (!(frame_rate_hz > 0) || !std::isfinite(frame_rate_hz)) return fail("frame_rate_hz must be > 0");
  if (!(duration_s > 0) || !std::isfinite(duration_s)) return fail("duration_s must be > 0");
  if (end == SceneEnd::at_duration && frames() < 1) return fail("duration_s · frame_rate_hz must give at least one frame");
  if (frames() > 100000000) return fail("more than 1e8 frames");
  if (coupling == Coupling::none) return true;
  if (!water) return fail(std::string("coupling ") + to_string(coupling) + " needs a water field");
  std::string w;
  if (!water->field.is_valid(&w)) return fail(w);
  const std::size_t cells = static_cast<std::size_t>(water->field.nx) * water->field.ny;
  if (!water->initial_m.empty() && water->initial_m.size() != cells) return fail("initial heights: need nx·ny values");
  if (coupling == Coupling::two_way) {
    if (draught_samples < 1 || draught_samples > 4096) return fail("draught_samples must be in [1, 4096]");
    if (!(head_width_m >= 0) || !std::isfinite(head_width_m)) return fail("head_width_m must be >= 0");
    if (forcing == Forcing::pressure && pressure_smoothing_passes(head_width_m, water->field.cell_m) == 0) {
      std::ostringstream m;
      m.precision(4);
      m << "head_width_m = " << head_width_m << " m is " << head_width_m / water->field.cell_m << " cells of "
        << water->field.cell_m << " m: at most " << kMaxHeadWidthCells << " cells (the head takes 2 (w/d)² binomial passes, at most "
        << kMaxPressureSmoothingPasses << ")";
      return fail(m.str());
    }
    const double sigma = water->field.courant(), limit = coupled_courant_limit(water->field.stencil);
    if (sigma > limit) {
      std::ostringstream m;
      m.precision(4);
      m << "σ = cΔt/d = " << sigma << " is above the coupled stability limit " << limit << " of "
        << water->field.stencil.name << " under the stone (model/README.md §2.4: free limit/√2); take dt_s ≤ "
        << limit * water->field.cell_m / water->field.wave_speed_m_s << " s";
      return fail(m.str());
    }
  }
  return true;
}

std::string SceneSummary::brief() const {
  char buf[300];
  std::snprintf(buf, sizeof buf,
                "%ld frames (%.4g s simulated) at %.4g frames/s CPU, %.4g wall; slowest frame %.3g ms wall (#%ld)", frames,
                simulated_s, frames_per_s_cpu(), frames_per_s_wall(), 1e3 * slowest_frame_wall_s, slowest_frame);
  return buf;
}

namespace {

double steady_now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double thread_cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// The loop's state: the field, the draught window, the frames and their costs.
class SceneLoop {
 public:
  SceneLoop(const SceneOptions& o, const FrameRecorder& recorder, SceneSummary& out)
      : o_(o), recorder_(recorder), out_(out), two_way_(o.coupling == Coupling::two_way),
        pressure_(two_way_ && o.forcing == Forcing::pressure), frames_(o.frames()),
        rho_g_(o.environment.water_density_kg_m3 * o.environment.gravity_m_s2) {
    if (o.coupling != Coupling::none) {
      field_ = std::make_unique<HeightField>(o.water->field);
      if (!o.water->initial_m.empty()) field_->set_state(o.water->initial_m);
      surface_ = std::make_unique<HeightFieldSurface>(*field_, o.water->placement.origin_x_m, o.water->placement.origin_y_m,
                                                      o.level_in_time);
      out_.volume_start_m3 = field_->volume_m3();
      dt_s_ = o.water->field.dt_s;
      stays_flat_ = (o.coupling == Coupling::one_way || o.water->field.wave_speed_m_s == 0) &&
                    std::all_of(o.water->initial_m.begin(), o.water->initial_m.end(), [](double z) { return z == 0; });
    }
    if (two_way_) {
      const bool periodic = o.water->field.boundary == Boundary::periodic;
      if (!pressure_) draught_ = std::make_unique<StoneDraught>(o.stone.body_mesh);
      window_ = std::make_unique<DraughtWindow>(o.water->field.nx, o.water->field.ny, periodic);
      if (pressure_) next_window_ = std::make_unique<DraughtWindow>(o.water->field.nx, o.water->field.ny, periodic);
      if (pressure_) smoothing_passes_ = pressure_smoothing_passes(o.head_width_m, o.water->field.cell_m);
      if (o.energy_budget) {
        energy_ = std::make_unique<WaveEnergy>(o.water->field, rho_g_);
        out_.energy.measured = energy_->available();
        if (out_.energy.measured) out_.energy.start_J = energy_->energy(*field_).total_J;
      }
    }
    per_step_budget_ = energy_ && out_.energy.measured && o.water->field.damping_per_s > 0;
    out_.frame_costs.reserve(static_cast<std::size_t>(frames_));
    frame_cpu0_ = thread_cpu_now();
    frame_wall0_ = steady_now();
  }

  // The surface the stone is clipped against. A field that starts at rest and that nothing moves
  // (one-way, or two-way with c = 0) stays exactly flat: the stone steps on still water, as with
  // coupling none, bit for bit (model/README.md §2.4). Given a surface, the stepper must assume
  // live water (its flight steps bounded by |v|, not by the sinking speed: stone_stepper.cpp).
  const WaterSurface* surface() const { return stays_flat_ ? nullptr : surface_.get(); }

  // The faces' pushes at the start of each stone step, filled by the stepper's own first
  // right-hand side (run_realtime's step_start_pushes): read at the next step's start.
  std::vector<FacePush>* step_start_pushes() { return pressure_ ? &pushes_ : nullptr; }

  // Called at the start of every stone step: the step that just ended hands over the head it
  // pressed with, the water catches up with the stone's clock, the draught samples due are taken
  // from the stone's state, and the frames that ended are closed.
  void at_stone_step(double t_s, const RigidState& s) {
    ++cost_.stone_steps;
    const double impulse_N_s = two_way_ ? stone_step_impulse(t_s, s) : 0.0;
    if (pressure_) {
      press();
      finish_piece(t_s, impulse_N_s);
      advance_to(t_s);
      out_.draught_samples += 1;  // the head of the step starting here, read at its end
      ++cost_.draught_samples;
    } else {
      catch_up(t_s, &s);
      if (two_way_) track_stone_force(impulse_N_s);
    }
    take_deferred();  // the stone's next step reads the surface, at its start (HeightFieldSurface)
    if (surface_) surface_->set_time(t_s);
    while (closed_ < frames_ && frame_time(closed_ + 1) <= t_s) close_frame(StoneStatus::in_play, s);
  }

  // After the throw: the stone's last state (it is sampled up to end_s), then the water alone.
  void after_throw(const ThrowResult& r) {
    const StoneStatus status = r.outcome == Outcome::sank ? StoneStatus::sank : StoneStatus::ended;
    const double impulse_N_s = two_way_ ? stone_step_impulse(r.end_time_s, r.final_state) : 0.0;
    if (pressure_) {
      press();                                  // the last step's head, up to where the throw ended
      finish_piece(r.end_time_s, impulse_N_s);  // the stone leaves the scene: no head from here on
      pending_wet_ = false;
      in_contact_ = false;
    } else {
      catch_up(r.end_time_s, &r.final_state);
      if (two_way_) track_stone_force(impulse_N_s);
    }
    if (o_.end == SceneEnd::with_the_throw) {
      while (closed_ < frames_ && frame_time(closed_ + 1) <= r.end_time_s) close_frame(status, r.final_state);
      return;
    }
    while (closed_ < frames_) {
      catch_up(frame_time(closed_ + 1), nullptr);
      close_frame(status, r.final_state);
    }
  }

  void finish() {
    take_deferred();
    out_.frames = closed_;
    out_.simulated_s = frame_time(closed_);
    if (energy_ && out_.energy.measured) {
      const WaveEnergyReading e = energy_->energy(*field_);
      out_.energy.end_J = e.total_J;
      out_.energy.grid_scale_fraction = e.grid_scale_fraction();
    }
    // Pressure: what the stone gave the water in its last pieces, held in the windows of water steps
    // the scene ended before taking (their hats reach past its end).
    if (two_way_ && pressure_) {
      const double cell = o_.water->field.cell_m;
      out_.water_impulse_pending_N_s = dt_s_ * rho_g_ * cell * cell * (window_->sum() + next_window_->sum());
    }
    if (field_) {
      out_.volume_end_m3 = field_->volume_m3();
      out_.tiles = field_->tile_summary();
      out_.water_steps = field_->steps();
    }
  }

 private:
  double frame_time(long k) const { return static_cast<double>(k) / o_.frame_rate_hz; }

  // Steps every water window that ends by t_s, taking the draught samples due before each end
  // from the stone's state s (nullptr: the stone has left the scene).
  void catch_up(double t_s, const RigidState* s) {
    if (!field_) return;
    if (pressure_) {
      advance_to(t_s);
      return;
    }
    const int k = o_.draught_samples;
    for (;;) {
      const double t_n = time_after_deferred(), end = t_n + 0.5 * dt_s_;
      if (two_way_) {
        int due = 0;
        for (;;) {
          const double node = t_n - 0.5 * dt_s_ + (node_ + 0.5) * dt_s_ / k;
          if (node_ >= k || node > t_s || node >= end) break;
          ++node_;
          ++due;
        }
        if (due > 0 && s) {
          take_deferred();  // the sample reads the surface
          surface_->set_time(t_s);
          last_sample_s_ = t_s;
          sample(*s, due);
        } else if (due > 0) {
          in_episode_ = false;
        }
      }
      if (end > t_s) break;
      if (next_step_is_free()) {
        defer_step();
      } else {
        take_deferred();
        step_water();
      }
    }
  }

  // Pressure forcing: steps every water step n whose hat has ended (t_n+1 ≤ t_s).
  void advance_to(double t_s) {
    const double slack = 1e-9 * dt_s_;
    while (time_after_deferred() + dt_s_ <= t_s + slack) {
      if (next_step_is_free()) {
        defer_step();
      } else {
        take_deferred();
        step_water();
      }
    }
  }

  // Whether the field's next step is free: nothing waits to force it (the windows are empty, and
  // stay so while no sample or head is added) and no per-step budget term is wanted from it.
  bool next_step_is_free() const {
    if (o_.free_water == FreeWater::one_at_a_time || per_step_budget_) return false;
    return !two_way_ || (window_->empty() && (!next_window_ || next_window_->empty()));
  }

  // The field's clock once the deferred steps are taken: HeightField keeps time_s = steps · Δt.
  double time_after_deferred() const {
    return deferred_ == 0 ? field_->time_s() : static_cast<double>(field_->steps() + deferred_) * dt_s_;
  }

  // A free step, owed to the field until someone needs it. What step_water books for it is zero:
  // an empty patch adds nothing to the impulses or to the pressure work.
  void defer_step() {
    ++deferred_;
    ++cost_.water_steps;
    node_ = 0;
  }

  // Takes the owed steps in one HeightField::advance. Steps owed by frames already closed (only
  // FreeWater::to_the_next_look without a recorder) get their share of its cost, by their steps.
  void take_deferred() {
    if (deferred_ == 0) return;
    const long owed_by_closed = owed_by_closed_;
    const double w0 = steady_now(), c0 = owed_by_closed > 0 ? thread_cpu_now() : 0.0;
    field_->advance(deferred_);
    const double w1 = steady_now(), wall = w1 - w0;
    if (owed_by_closed == 0) {
      cost_.water_wall_s += wall;
    } else {
      const double cpu = thread_cpu_now() - c0;
      const double open_share = static_cast<double>(deferred_ - owed_by_closed) / static_cast<double>(deferred_);
      cost_.water_wall_s += open_share * wall;
      const double closed_wall = wall - open_share * wall, closed_cpu = cpu - open_share * cpu;
      frame_wall0_ += closed_wall;  // the open frame's clocks leave out the closed frames' share
      frame_cpu0_ += closed_cpu;
      for (const auto& [f, steps] : owing_) {
        FrameCost& c = out_.frame_costs[f];
        const double share = static_cast<double>(steps) / static_cast<double>(owed_by_closed);
        c.water_wall_s += share * closed_wall;
        c.wall_s += share * closed_wall;
        c.cpu_s += share * closed_cpu;
        out_.water_wall_s += share * closed_wall;
        out_.wall_s += share * closed_wall;
        out_.cpu_s += share * closed_cpu;
        note_slowest(static_cast<long>(f) + 1, c);
      }
    }
    deferred_ = 0;
    owed_by_closed_ = 0;
    owing_.clear();
  }

  // The water's vertical impulse on the stone over its step that ends at (t_s, s), from the stone's
  // own momentum: J = m Δv_z + m g Δt − J_air, J_air by the trapezoidal rule on the air force at the
  // step's two ends (the air's force is smooth and small: its quadrature error is far below the
  // water's). This is the impulse the stepper actually applied, whatever its scheme; Σ F_z(t₀) h,
  // the force at each step's start held over it, is only the semi-implicit Euler stepper's (with
  // bs32 at 1e-8 it was 0.4 % off on the seed's scene). 0 for the first call (no step has ended).
  double stone_step_impulse(double t_s, const RigidState& s) {
    const double m = o_.stone.mass.mass_kg, air_z = air_loads(o_.stone, o_.environment, s).force_N.z();
    double j = 0;
    if (have_step_start_ && t_s > step_start_t_) {
      const double h = t_s - step_start_t_;
      j = m * (s.velocity_m_s.z() - step_start_vz_) + m * o_.environment.gravity_m_s2 * h - 0.5 * (air_z + step_start_air_z_) * h;
    }
    have_step_start_ = true;
    step_start_t_ = t_s;
    step_start_vz_ = s.velocity_m_s.z();
    step_start_air_z_ = air_z;
    return j;
  }

  // Pressure forcing: the head held over the stone step [pending_t_, t_end] is spread over the
  // water steps with the hat weights: a piece [a, b] ⊂ [t_n, t_n+1] gives step n the weight
  // ∫ hatₙ/Δt = (b − a)/Δt · (1 − r) and step n+1 (b − a)/Δt · r, r = ((a + b)/2 − t_n)/Δt.
  // The head has the shape of the faces' pushes at the step's start and carries the impulse the
  // stone received over the step (impulse_N_s, stone_step_impulse): it is scaled by that over
  // F_z(t₀) h, so the water receives what the stone gives up, to round-off, under every scheme.
  // A step that began dry carries its impulse (the touch within it; in flight only the air's
  // quadrature error) to the next step if that one begins pressing; else it is dropped, from the
  // stone's sum as from the water's (a touch wholly inside one step, which bs32's located
  // crossings do not allow, is then missed by both).
  void finish_piece(double t_end, double impulse_N_s) {
    take_deferred();  // the pieces go to the windows of the field's current level
    if (!(t_end > pending_t_)) return;
    if (!std::isfinite(impulse_N_s)) impulse_N_s = 0;  // a failed solve's last step: booked nowhere
    if (!pending_wet_) {
      carried_N_s_ = impulse_N_s;
    } else {
      impulse_N_s += carried_N_s_;
      carried_N_s_ = 0;
      out_.stone_vertical_impulse_N_s += impulse_N_s;
      const double len = t_end - pending_t_, held_N_s = pending_force_N_ * len;
      double scale = held_N_s != 0 ? impulse_N_s / held_N_s : 0.0;
      const DraughtPatch* shape = &head_;
      double rastered_N = pending_rastered_N_;
      if (!(scale >= kLeastHeadScale && scale <= kMostHeadScale)) {
        // The start's head does not carry this step's impulse (its faces' pushes nearly cancel, or
        // the force changes sign over the step): scaled, it would be a huge or inverted head. The
        // impulse goes instead on |h|, the footprint's shape at the start, with the same total.
        reshaped_head_ = head_;
        for (double& v : reshaped_head_.b_m) v = std::abs(v);
        const double cell = o_.water->field.cell_m;
        const double total_N = reshaped_head_.volume_m3(cell) * rho_g_;
        scale = total_N > 0 ? impulse_N_s / (total_N * len) : 0.0;
        shape = &reshaped_head_;
        rastered_N = window_->kept_sum(reshaped_head_) * rho_g_ * cell * cell;
        ++out_.heads_on_footprint;
      }
      ContactImpulse& c = out_.contact_impulses.back();
      c.end_s = t_end;
      c.stone_N_s += impulse_N_s;
      c.water_N_s += scale * rastered_N * len;
      const double slack = 1e-9 * dt_s_;
      for (double a = pending_t_; a < t_end;) {
        const double tn = field_->time_s(), tn1 = tn + dt_s_;
        if (a >= tn1 - slack) {
          step_water();  // its hat is complete
          continue;
        }
        const double b = std::min(t_end, tn1);
        const double r = std::clamp((0.5 * (a + b) - tn) / dt_s_, 0.0, 1.0);
        const double w0 = steady_now();
        window_->add(*shape, scale * (b - a) / dt_s_ * (1 - r));
        next_window_->add(*shape, scale * (b - a) / dt_s_ * r);
        cost_.draught_wall_s += steady_now() - w0;
        a = b;
      }
    }
    pending_t_ = t_end;
  }

  // Pressure forcing: the faces' pushes at the start of the stone step that began at pending_t_
  // (the stepper's, against the surface it used), rasterised into the head held over that step.
  void press() {
    const double w0 = steady_now();
    const double t_s = pending_t_;
    const PressureHeadSummary h = rasterise_pressure_head(pushes_, o_.water->field.cell_m, o_.water->placement, rho_g_, head_);
    pushes_.clear();
    pending_wet_ = h.wet() && !head_.empty();
    pending_force_N_ = h.force_N;
    // What the grid receives of the head: the points beyond a pond's rim are dropped (DraughtWindow).
    const double cell = o_.water->field.cell_m;
    pending_rastered_N_ = pending_wet_ ? window_->kept_sum(head_) * rho_g_ * cell * cell : 0.0;
    if (pending_wet_ && !in_contact_) {
      out_.contact_impulses.emplace_back();
      out_.contact_impulses.back().start_s = t_s;
      out_.contact_impulses.back().end_s = t_s;
    }
    in_contact_ = pending_wet_;
    last_volume_m3_ = head_.empty() ? 0.0 : head_.volume_m3(o_.water->field.cell_m);
    out_.max_draught_volume_m3 = std::max(out_.max_draught_volume_m3, last_volume_m3_);  // of the head (h = p/(ρ_w g))
    cost_.draught_wall_s += steady_now() - w0;
  }

  // Displacement forcing: the stone's vertical impulse over the step that just ended
  // (stone_step_impulse); the faces' pushes are not asked for.
  void track_stone_force(double impulse_N_s) { out_.stone_vertical_impulse_N_s += impulse_N_s; }

  void sample(const RigidState& s, int due) {
    const double w0 = steady_now();
    const DraughtSummary d = draught_->compute(s, *field_, o_.water->placement, sample_patch_);
    if (d.wet) {
      window_->add(sample_patch_, static_cast<double>(due) / o_.draught_samples);
      const double eta = surface_->height_m(s.position_m.x(), s.position_m.y());
      if (!in_episode_) {
        out_.episodes.emplace_back();
        out_.episodes.back().start_s = last_sample_s_;
        out_.episodes.back().surface_at_start_m = eta;
        out_.episodes.back().lowest_surface_m = eta;
      }
      DraughtEpisode& e = out_.episodes.back();
      e.end_s = last_sample_s_;
      e.max_volume_m3 = std::max(e.max_volume_m3, d.volume_m3);
      e.volume_time_m3_s += d.volume_m3 * due * dt_s_ / o_.draught_samples;
      e.lowest_surface_m = std::min(e.lowest_surface_m, eta);
    }
    in_episode_ = d.wet;
    last_volume_m3_ = d.volume_m3;
    out_.max_draught_volume_m3 = std::max(out_.max_draught_volume_m3, d.volume_m3);
    out_.draught_samples += 1;
    ++cost_.draught_samples;
    cost_.draught_wall_s += steady_now() - w0;
  }

  void step_water() {
    const double w0 = steady_now();
    if (two_way_) {
      window_->take(step_patch_);
      if (pressure_) {
        std::swap(window_, next_window_);  // step n+1's rising half is in
        // The binomial passes are linear: smoothing the step's sum once is smoothing every stone
        // step's head (to round-off), at the cost of one patch per water step.
        smooth_conservatively(step_patch_, smoothing_passes_, smooth_scratch_);
        // The window kept only the grid's points; what the smoothing spilt past a wall goes back
        // onto the grid by reflection, so the water still receives the whole head.
        if (o_.water->field.boundary != Boundary::periodic)
          fold_onto_walled_grid(step_patch_, o_.water->field.nx, o_.water->field.ny, smooth_scratch_);
      }
      // What the water receives: the patch's points on the grid (beyond a pond's rim they are ignored).
      const double kept_m3 = kept_volume_m3(step_patch_);
      out_.draught_impulse_m3_s += dt_s_ * kept_m3;
      out_.water_vertical_impulse_N_s += dt_s_ * rho_g_ * kept_m3;
      const double budget0 = cost_.energy_budget_wall_s;
      forced_step();
      node_ = 0;
      ++cost_.water_steps;
      cost_.water_wall_s += steady_now() - w0 - (cost_.energy_budget_wall_s - budget0);  // the budget's share apart
      return;
    }
    field_->step();
    ++cost_.water_steps;
    cost_.water_wall_s += steady_now() - w0;
  }

  // HeightField::step(patch) with the budget's terms: Wₙ = ρ g d² ⟨hⁿ, (zⁿ⁻¹ − zⁿ⁺¹)/2⟩ on the
  // patch, and Dₙ from the whole grid (solvers/scene/wave_energy.hpp).
  // Σ b d² over the patch's points that act on the grid (HeightField::patch_point_on_grid).
  double kept_volume_m3(const DraughtPatch& p) const {
    double s = 0;
    for (int c = 0; c < p.nj; ++c)
      for (int a = 0; a < p.ni; ++a) {
        int i = p.i0 + a, j = p.j0 + c;
        if (field_->patch_point_on_grid(i, j)) s += p.at(a, c);
      }
    const double cell = o_.water->field.cell_m;
    return s * cell * cell;
  }

  // Σ b z over the patch's points where they act on the grid (a periodic patch's images wrapped, a
  // point beyond another pond's rim left out): reading z at the unwrapped index would read outside
  // the field's storage.
  double patch_dot(const DraughtPatch& p, bool previous) const {
    const HeightField& f = *field_;
    double s = 0;
    for (int c = 0; c < p.nj; ++c)
      for (int a = 0; a < p.ni; ++a) {
        int i = p.i0 + a, j = p.j0 + c;
        if (f.patch_point_on_grid(i, j)) s += p.at(a, c) * (previous ? f.previous_height(i, j) : f.height(i, j));
      }
    return s;
  }

  void forced_step() {
    const HeightField& f = *field_;
    const DraughtPatch& p = step_patch_;
    double work = patch_dot(p, true);
    if (energy_ && out_.energy.measured && o_.water->field.damping_per_s > 0) {
      const double b0 = steady_now();
      before_.resize(static_cast<std::size_t>(f.nx()) * f.ny());
      for (int j = 0; j < f.ny(); ++j)
        for (int i = 0; i < f.nx(); ++i) before_[static_cast<std::size_t>(j) * f.nx() + i] = f.previous_height(i, j);
      cost_.energy_budget_wall_s += steady_now() - b0;
    }
    field_->step(p);
    work -= patch_dot(p, false);
    const double cell = o_.water->field.cell_m;
    out_.energy.pressure_work_J += 0.5 * rho_g_ * cell * cell * work;
    if (energy_ && out_.energy.measured && o_.water->field.damping_per_s > 0) {
      const double b0 = steady_now();
      f.heights(after_);
      out_.energy.damping_loss_J += energy_->damping_loss_J(before_, after_);
      cost_.energy_budget_wall_s += steady_now() - b0;
    }
  }

  void close_frame(StoneStatus status, const RigidState& s) {
    // The recorder looks at the field; without one, to_the_next_look lets the frame close owing.
    if (recorder_ || o_.free_water != FreeWater::to_the_next_look) take_deferred();
    ++closed_;
    if (recorder_) {
      const double w0 = steady_now();
      SceneFrame f;
      f.index = closed_;
      f.t_s = frame_time(closed_);
      f.stone_status = status;
      f.stone = s;
      f.field = field_.get();
      if (o_.water) f.placement = o_.water->placement;
      f.draught_volume_m3 = last_volume_m3_;
      recorder_(f);
      cost_.recording_wall_s += steady_now() - w0;
    }
    const double cpu = thread_cpu_now(), wall = steady_now();
    cost_.t_s = frame_time(closed_);
    cost_.cpu_s = cpu - frame_cpu0_;
    cost_.wall_s = wall - frame_wall0_;
    cost_.stone_wall_s = std::max(0.0, cost_.wall_s - cost_.draught_wall_s - cost_.water_wall_s - cost_.recording_wall_s -
                                           cost_.energy_budget_wall_s);
    out_.frame_costs.push_back(cost_);
    out_.cpu_s += cost_.cpu_s;
    out_.wall_s += cost_.wall_s;
    out_.stone_wall_s += cost_.stone_wall_s;
    out_.draught_wall_s += cost_.draught_wall_s;
    out_.water_wall_s += cost_.water_wall_s;
    out_.recording_wall_s += cost_.recording_wall_s;
    out_.energy_budget_wall_s += cost_.energy_budget_wall_s;
    note_slowest(closed_, cost_);
    if (deferred_ > owed_by_closed_) {  // the frame closes owing steps of its own
      owing_.emplace_back(out_.frame_costs.size() - 1, deferred_ - owed_by_closed_);
      owed_by_closed_ = deferred_;
    }
    cost_ = FrameCost{};
    frame_cpu0_ = cpu;
    frame_wall0_ = wall;
  }

  void note_slowest(long frame, const FrameCost& c) {
    if (c.wall_s > out_.slowest_frame_wall_s) {
      out_.slowest_frame_wall_s = c.wall_s;
      out_.slowest_frame_cpu_s = c.cpu_s;
      out_.slowest_frame = frame;
    }
  }

  const SceneOptions& o_;
  const FrameRecorder& recorder_;
  SceneSummary& out_;
  const bool two_way_, pressure_;
  const long frames_;
  const double rho_g_;
  double dt_s_ = 0;
  std::unique_ptr<HeightField> field_;
  std::unique_ptr<HeightFieldSurface> surface_;
  std::unique_ptr<StoneDraught> draught_;
  std::unique_ptr<DraughtWindow> window_, next_window_;  // pressure: steps n and n+1
  std::unique_ptr<WaveEnergy> energy_;
  std::vector<double> before_, after_;
  DraughtPatch sample_patch_, step_patch_, head_;
  std::vector<FacePush> pushes_;
  std::vector<double> smooth_scratch_;
  int smoothing_passes_ = kPressureSmoothingPasses;  // pressure_smoothing_passes of the scene's width
  double pending_t_ = 0, pending_force_N_ = 0, pending_rastered_N_ = 0;
  bool pending_wet_ = false, in_contact_ = false;
  // The stone step that ends at the next call of stone_step_impulse: its start, v_z and air force.
  double carried_N_s_ = 0;  // pressure: the impulse of a step that began dry (finish_piece)
  DraughtPatch reshaped_head_;  // pressure: |h| of a head whose scale would be out of range (finish_piece)
  // The range of a step's impulse over its start's held force within which the head is scaled
  // (finish_piece): a step's force changes by a few times at most where the head is a fair shape.
  static constexpr double kLeastHeadScale = 0.1, kMostHeadScale = 10;
  bool have_step_start_ = false;
  double step_start_t_ = 0, step_start_vz_ = 0, step_start_air_z_ = 0;
  int node_ = 0;  // draught samples taken in the current window
  bool in_episode_ = false;
  double last_sample_s_ = 0;
  double last_volume_m3_ = 0;
  long closed_ = 0;
  bool per_step_budget_ = false;  // Dₙ measured at every step (energy_budget on a damped field)
  bool stays_flat_ = false;       // the field is still water for the whole scene
  long deferred_ = 0;             // free steps owed to the field
  long owed_by_closed_ = 0;       // of them, those of frames already closed
  std::vector<std::pair<std::size_t, long>> owing_;  // (closed frame, its owed steps)
  FrameCost cost_;
  double frame_cpu0_ = 0, frame_wall0_ = 0;
};

}  // namespace

SceneSummary run_scene(const SceneOptions& o, const FrameRecorder& recorder, const StoneStepRecorder& stone_steps) {
  std::string why;
  if (!o.valid(&why)) throw std::invalid_argument("scene: " + why);
  SceneSummary out;
  out.options_brief = o;
  if (out.options_brief.water) out.options_brief.water->initial_m.clear();
  RealtimeOptions steps = o.stone_steps;
  if (o.end == SceneEnd::at_duration) steps.t_max_s = std::min(steps.t_max_s, o.end_s());
  SceneLoop loop(o, recorder, out);
  out.stone = run_realtime(o.stone, o.environment, o.initial, steps, loop.surface(),
                           [&](double t_s, const RigidState& s) {
                             if (stone_steps) stone_steps(t_s, s);
                             loop.at_stone_step(t_s, s);
                           },
                           loop.step_start_pushes());
  if (stone_steps) stone_steps(out.stone.end_time_s, out.stone.final_state);
  loop.after_throw(out.stone);
  loop.finish();
  if (o.coupling != Coupling::none) {
    std::ostringstream name;
    name << out.stone.solver << ", " << to_string(o.coupling) << " on a live " << o.water->field.nx << "x"
         << o.water->field.ny << " height field (" << o.water->field.stencil.name << ")";
    out.stone.solver = name.str();
  }
  return out;
}

}  // namespace stoneskip
