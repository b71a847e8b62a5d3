#include "verification/stones/realtime_convergence.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>

#include "verification/stones/contact_comparison.hpp"
#include "verification/stones/parallel_runs.hpp"
#include "verification/stones/state_error.hpp"

namespace stoneskip {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// One run of the whole stepper at one step size.
struct StepperPoint {
  bool ok = false;
  std::string problem;
  ThrowResult full;
  StateAt at_free_flight;
};

// The scale of a relative state error's round-off over an interval: 1 (velocity, orientation,
// angular momentum are relative or angles) or the largest |x| in stone radii at its ends (the
// position error is |Δx| / R, and x + h v rounds at ε |x|), whichever is larger.
double position_scale(const Stone& stone, const RigidState& a, const RigidState& b) {
  const double r = std::max(stone.bounding_radius_m, 1e-6);  // as position_error
  return std::max({1.0, a.position_m.norm() / r, b.position_m.norm() / r});
}

// N steps' worst-case accumulated rounding: N ε × scale (ε the double's unit round-off × 2).
double roundoff_bound(long steps, double scale) {
  return static_cast<double>(steps) * std::numeric_limits<double>::epsilon() * scale;
}

}  // namespace

void finish_series(ConvergenceSeries& s, const RealtimeConvergenceOptions& o) {
  const double floor_factor = o.floor_factor;
  const std::size_t n = s.h_s.size();
  s.in_fit.assign(n, false);
  s.below_floor.assign(n, false);
  s.notes.resize(n);
  std::vector<double> h, e;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(s.error[i])) {
      if (s.notes[i].empty()) s.notes[i] = "failed";
      continue;
    }
    if (s.error[i] <= floor_factor * s.reference_error) {
      s.notes[i] = "below the reference's error bound";
      s.below_floor[i] = true;
      continue;
    }
    if (i < s.roundoff.size() && s.error[i] <= s.roundoff[i]) {
      char note[96];
      std::snprintf(note, sizeof note, "at round-off (N ε × scale = %.3g)", s.roundoff[i]);
      s.notes[i] = note;
      s.below_floor[i] = true;
      continue;
    }
    s.in_fit[i] = true;
    h.push_back(s.h_s[i]);
    e.push_back(s.error[i]);
  }
  OrderFitOptions fo;
  fo.correction_term = o.correction_term && !s.against_tolerance;  // the expansion is in the step, not tol
  s.fit = fit_order(h, e, fo);
  OrderJudgement j;
  j.expected_order = s.formal_order;
  j.tolerance = o.order_tolerance;
  j.expected_name = "formal";
  s.decision = judge_order(s.fit, j);
  if (h.size() < n) {
    // Say which points the fit lacks and why (a fit of too few points otherwise reads as if the
    // runs had no error at all).
    int failed = 0, floor = 0, lists = 0, roundoff = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (s.in_fit[i]) continue;
      if (s.notes[i].rfind("contact lists differ", 0) == 0) ++lists;
      else if (s.notes[i].rfind("at round-off", 0) == 0) ++roundoff;
      else if (s.below_floor[i]) ++floor;
      else ++failed;
    }
    std::string why;
    auto add = [&](int k, const char* what) {
      if (k == 0) return;
      why += (why.empty() ? "" : ", ") + std::to_string(k) + " " + what;
    };
    add(lists, "with a contact list unlike the reference's");
    add(floor, "below the reference's error bound");
    add(roundoff, "at round-off");
    add(failed, "failed");
    s.left_out = " (of " + std::to_string(n) + " runs, left out: " + why + ")";
    s.decision.reason += s.left_out;
  }
  // Errors that do not fall, within a decade of the reference's estimated error: the estimate
  // (the check run's difference) can fall short of the reference's own error (CVODE's orientation
  // error is not proportional to its tolerance: at rtol 1e-6 a flight's orientation error was 1.4×
  // the difference to the check at 1e-5), so such a series may measure the reference, not the
  // scheme. Said beside the verdict, which stays the fit's.
  if (s.decision.verdict == OrderVerdict::does_not_converge && s.reference_error > 0 && !e.empty() &&
      *std::min_element(e.begin(), e.end()) <= 10 * s.reference_error) {
    char b[256];
    std::snprintf(b, sizeof b,
                  "; its smallest error is %.3g× the reference's estimated error: the reference may not resolve these "
                  "errors (tighten reference_rtol)",
                  *std::min_element(e.begin(), e.end()) / s.reference_error);
    s.left_out += b;
    s.decision.reason += b;
  }
  // GCI (Celik et al. 2008) from the three finest steps of the order fit (finite values, above the
  // reference's error bound and round-off, the reference's contact list): a value the fit left out
  // would put its floor into Eq. 9 as if it were the scheme's error. h_s is descending. An apparent
  // order outside the formal ± the verdict's tolerance reverts to it with Fs = 3 (gci.hpp).
  std::vector<std::size_t> idx;
  for (std::size_t i = n; i-- > 0 && idx.size() < 3;)
    if (s.in_fit[i] && std::isfinite(s.value[i])) idx.push_back(i);
  if (idx.size() == 3 && !s.against_tolerance) {  // GCI needs steps, not tolerances
    s.has_gci = true;
    GciOptions go;
    go.formal_order = s.formal_order;
    go.order_band = o.order_tolerance;
    s.gci = grid_convergence_index(s.value[idx[0]], s.value[idx[1]], s.value[idx[2]], s.h_s[idx[0]], s.h_s[idx[1]],
                                   s.h_s[idx[2]], go);
  }
}

namespace {

ConvergenceSeries make_series(const std::string& quantity, const std::string& description, const std::string& unit,
                              Scheme scheme) {
  ConvergenceSeries s;
  s.quantity = quantity;
  s.description = description;
  s.unit = unit;
  s.scheme = to_string(scheme);
  s.formal_order = formal_order(scheme);
  return s;
}

// A steady spin: the angular momentum along one of the body's principal axes (the body frame's:
// make_stone turns a stone onto them), so that ω stays constant without a torque (the air model
// exerts none, model/README.md §1.5) and the attitude converges at steady_spin_order.
bool steady_spin(const RigidState& s) {
  const Vec3 body = s.orientation.conjugate() * s.angular_momentum_kg_m2_s;
  const double largest = body.cwiseAbs().maxCoeff();
  if (!(largest > 0)) return false;  // no rotation: the attitude is exact, and the errors below any reference's
  int across = 0;
  for (int k = 0; k < 3; ++k) across += std::abs(body[k]) > 1e-12 * largest;
  return across == 1;
}

// The located events of the reference inside [start, end], their spacing.
ContactEvents contact_events(const ThrowResult& ref, const ContactRecord& c) {
  ContactEvents ev;
  ev.start_s = c.start_s;
  ev.end_s = c.end_s;
  for (double t : ref.event_times_s)
    if (t >= c.start_s && t <= c.end_s) ev.times_s.push_back(t);
  std::vector<double> gaps;
  for (std::size_t k = 1; k < ev.times_s.size(); ++k) gaps.push_back(ev.times_s[k] - ev.times_s[k - 1]);
  if (gaps.empty()) {
    ev.min_spacing_s = ev.median_spacing_s = kNaN;
  } else {
    std::sort(gaps.begin(), gaps.end());
    ev.min_spacing_s = gaps.front();
    ev.median_spacing_s = gaps.size() % 2 ? gaps[gaps.size() / 2] : 0.5 * (gaps[gaps.size() / 2 - 1] + gaps[gaps.size() / 2]);
  }
  return ev;
}

}  // namespace

EventCrowding crowding(const std::vector<double>& events, double t0, double h, long steps, double a, double b) {
  EventCrowding c;
  c.h_s = h;
  for (long k = 0; k < steps; ++k) {
    const double lo = t0 + static_cast<double>(k) * h, hi = lo + h;
    if (hi <= a || lo >= b) continue;  // overlaps the window over a positive length
    ++c.steps_in_window;
    int n = 0;
    for (double t : events) n += (t > lo && t <= hi) || (k == 0 && t == lo) ? 1 : 0;
    if (n >= 2) ++c.steps_with_two_or_more;
  }
  return c;
}

RealtimeConvergenceResult run_realtime_convergence(const ThrowProblem& p, const RealtimeConvergenceOptions& o) {
  RealtimeConvergenceResult res;
  res.case_label = p.label;
  const ParallelOptions par{o.workers, "", {}};

  // 1. Two references: the one we compare with and one 100x looser (the check), whose difference
  //    bounds the reference's own error (the floor below which an observed error means nothing).
  ReferenceOptions ref = p.reference;
  ref.rtol = o.reference_rtol;
  ref.atol = o.reference_atol;
  ref.record_trajectory = false;
  // The truth restarts at every located event, so that every kink of the right-hand side is a
  // located event (the events diagnostic below lists them), and applies the absolute tolerance
  // uniformly: atol on every component is far tighter on velocity, quaternion and angular
  // momentum than the per-component scaling (which matches their error to atol on positions), and
  // over a long planing contact that difference shows in the sinking point at the fitted steps.
  ref.restart = RestartStrategy::every_event;
  ref.atol_scaling = ToleranceScaling::uniform;
  ReferenceOptions fine = ref;  // the check run
  fine.rtol = ref.rtol * o.check_factor;
  fine.atol = ref.atol * o.check_factor;
  res.reference_rtol = ref.rtol;
  res.check_rtol = fine.rtol;
  ThrowResult r_ref, r_fine;
  run_jobs({[&] { r_ref = solve(p, reference_choice(ref)); }, [&] { r_fine = solve(p, reference_choice(fine)); }}, par);
  res.reference = r_ref;
  if (r_ref.outcome == Outcome::failed) {
    res.problems.push_back("the reference failed: " + r_ref.outcome_detail);
    return res;
  }
  if (r_ref.contacts.empty()) {
    res.problems.push_back("the throw never touches the water: no contact interval");
    return res;
  }

  // 2. The intervals. Free flight: release to 80 % of the way to the first touch. Contact: the
  //    first contact with a quarter of its duration of flight on each side.
  const ContactRecord& c1 = r_ref.contacts[0];
  const double dur = c1.end_s - c1.start_s;
  res.flight_interval_start_s = 0;
  res.flight_interval_end_s = 0.8 * c1.start_s;
  res.contact_interval_start_s = c1.start_s - 0.25 * dur;
  res.contact_interval_end_s = c1.bounced ? c1.end_s + 0.25 * dur : c1.end_s;
  res.free_flight_time_s = kNaN;
  if (c1.bounced) {
    const double next = r_ref.contacts.size() > 1 ? r_ref.contacts[1].start_s : r_ref.end_time_s;
    res.free_flight_time_s = 0.5 * (c1.end_s + next);
  } else {
    res.problems.push_back("the stone does not bounce at its first contact: no free flight after it to compare");
  }
  if (!c1.bounced) res.problems.push_back("the contact interval ends when the stone sinks (no flight after it)");

  // The events diagnostic: the reference's kinks inside the first contact, and how crowded the
  // scheme-alone steps over the contact interval are with them.
  res.events = contact_events(r_ref, c1);
  for (int n : o.interval_steps) {
    const double h = (res.contact_interval_end_s - res.contact_interval_start_s) / n;
    res.events.scheme_alone.push_back(
        crowding(res.events.times_s, res.contact_interval_start_s, h, n, c1.start_s, c1.end_s));
  }

  // Reference states at the interval ends (both references).
  const std::vector<double> times{res.flight_interval_end_s, res.contact_interval_start_s, res.contact_interval_end_s,
                                  res.free_flight_time_s};
  std::vector<StateAt> at_ref(times.size()), at_fine(times.size());
  {
    std::vector<std::function<void()>> jobs;
    for (std::size_t k = 0; k < times.size(); ++k) {
      if (!std::isfinite(times[k])) continue;
      jobs.push_back([&, k] { at_ref[k] = state_at(p, reference_choice(ref), times[k]); });
      jobs.push_back([&, k] { at_fine[k] = state_at(p, reference_choice(fine), times[k]); });
    }
    run_jobs(jobs, par);
  }
  for (std::size_t k = 0; k < times.size(); ++k)
    if (std::isfinite(times[k]) && !at_ref[k].ok)
      res.problems.push_back("reference state at t = " + std::to_string(times[k]) + " s: " + at_ref[k].problem);

  // 3. The scheme alone over the two intervals.
  const std::size_t ns = o.schemes.size(), nN = o.interval_steps.size();
  std::vector<RigidState> flight_end(ns * nN), contact_end(ns * nN);
  // 4. The whole stepper: a fixed scheme over the flight steps, an adaptive one over its tolerances.
  std::vector<std::vector<double>> settings(ns);
  for (std::size_t a = 0; a < ns; ++a) settings[a] = is_adaptive(o.schemes[a]) ? o.adaptive_tolerances : o.dt_s;
  std::vector<std::vector<StepperPoint>> points(ns);
  for (std::size_t a = 0; a < ns; ++a) points[a].resize(settings[a].size());
  {
    std::vector<std::function<void()>> jobs;
    for (std::size_t a = 0; a < ns; ++a) {
      for (std::size_t b = 0; b < nN; ++b) {
        if (at_ref[0].ok)
          jobs.push_back([&, a, b] {
            flight_end[a * nN + b] =
                integrate_fixed(p.stone, p.environment, p.initial, times[0], o.interval_steps[b], o.schemes[a]);
          });
        if (at_ref[1].ok && at_ref[2].ok)
          jobs.push_back([&, a, b] {
            contact_end[a * nN + b] = integrate_fixed(p.stone, p.environment, at_ref[1].state, times[2] - times[1],
                                                      o.interval_steps[b], o.schemes[a]);
          });
      }
      for (std::size_t b = 0; b < settings[a].size(); ++b) {
        jobs.push_back([&, a, b] {
          RealtimeOptions ro = p.realtime;
          ro.scheme = o.schemes[a];
          if (is_adaptive(ro.scheme)) {
            ro.rtol = ro.atol_m = settings[a][b];
          } else {
            ro.dt_s = settings[a][b];
            ro.contact_dt_s = o.contact_ratio * settings[a][b];
            ro.kinks = o.fixed_kinks;
          }
          ro.record_trajectory = false;
          StepperPoint& pt = points[a][b];
          pt.full = solve(p, realtime_choice(ro));
          if (std::isfinite(times[3])) pt.at_free_flight = state_at(p, realtime_choice(ro), times[3]);
          pt.ok = pt.full.outcome != Outcome::failed;
          if (!pt.ok) pt.problem = pt.full.outcome_detail;
        });
      }
    }
    run_jobs(jobs, ParallelOptions{o.workers, "stones: convergence of the real-time stepper", o.progress});
  }

  // 5. Series.
  for (std::size_t a = 0; a < ns; ++a) {
    const Scheme sc = o.schemes[a];
    if (at_ref[0].ok) {
      auto s = make_series("flight_interval_state",
                           "state after a free-flight interval (scheme alone, N equal steps)", "1 (relative)", sc);
      s.reference_error = at_fine[0].ok ? state_error(p.stone, at_ref[0].state, at_fine[0].state) : 0;
      const double flight_scale = position_scale(p.stone, p.initial, at_ref[0].state);
      for (std::size_t b = 0; b < nN; ++b) {
        s.roundoff.push_back(roundoff_bound(o.interval_steps[b], flight_scale));
        s.h_s.push_back(times[0] / o.interval_steps[b]);
        s.value.push_back(kNaN);
        s.error.push_back(state_error(p.stone, flight_end[a * nN + b], at_ref[0].state));
      }
      finish_series(s, o);
      res.series.push_back(s);
      // Its position and orientation parts alone (state_error.hpp: a part can converge faster).
      for (int part = 0; part < 2; ++part) {
        auto err = [&](const RigidState& x, const RigidState& truth) {
          return part == 0 ? position_error(p.stone, x, truth) : orientation_error(x, truth);
        };
        const bool spin = part == 1 && steady_spin(p.initial);
        auto q = make_series(part == 0 ? "flight_interval_position" : "flight_interval_orientation",
                             part == 0   ? "position after a free-flight interval (scheme alone), in stone radii"
                             : spin      ? "orientation after a free-flight interval (scheme alone), angle, in a steady spin "
                                           "(expected: an odd order one more, solvers/README.md)"
                                         : "orientation after a free-flight interval (scheme alone), angle",
                             part == 0 ? "1 (radii)" : "rad", sc);
        if (spin) q.formal_order = steady_spin_order(sc);
        q.reference_error = at_fine[0].ok ? err(at_ref[0].state, at_fine[0].state) : 0;
        for (std::size_t b = 0; b < nN; ++b) {
          q.roundoff.push_back(roundoff_bound(o.interval_steps[b], part == 0 ? flight_scale : 1.0));
          q.h_s.push_back(times[0] / o.interval_steps[b]);
          q.value.push_back(kNaN);
          q.error.push_back(err(flight_end[a * nN + b], at_ref[0].state));
        }
        finish_series(q, o);
        res.series.push_back(q);
      }
    }
    if (at_ref[1].ok && at_ref[2].ok) {
      auto s = make_series("contact_interval_state",
                           "state after an interval holding the whole first contact (scheme alone, N equal steps)",
                           "1 (relative)", sc);
      s.reference_error = at_fine[2].ok ? state_error(p.stone, at_ref[2].state, at_fine[2].state) : 0;
      const double contact_scale = position_scale(p.stone, at_ref[1].state, at_ref[2].state);
      for (std::size_t b = 0; b < nN; ++b) {
        s.roundoff.push_back(roundoff_bound(o.interval_steps[b], contact_scale));
        s.h_s.push_back((times[2] - times[1]) / o.interval_steps[b]);
        s.value.push_back(kNaN);
        const RigidState& e = contact_end[a * nN + b];
        const bool finite = e.position_m.allFinite() && e.velocity_m_s.allFinite();
        s.error.push_back(finite ? state_error(p.stone, e, at_ref[2].state) : kNaN);
      }
      finish_series(s, o);
      res.series.push_back(s);
    }
    // Whole stepper: against the flight step, or (adaptive) against the tolerance.
    const bool by_tol = is_adaptive(sc);
    const std::size_t nd = settings[a].size();
    auto whole_series = [&](const std::string& quantity, const std::string& description, const std::string& unit) {
      auto s = make_series(quantity, by_tol ? description + ", against its tolerance" : description, unit, sc);
      if (by_tol) {
        s.against_tolerance = true;
        s.formal_order = 1;
      }
      return s;
    };
    const ContactRecord* f1 = r_fine.contacts.empty() ? nullptr : &r_fine.contacts[0];
    struct Scalar {
      const char* quantity;
      const char* description;
      const char* unit;
      std::function<double(const ThrowResult&)> get;
    };
    const std::vector<Scalar> scalars{
        {"contact1_start_time", "start time of the first contact (whole stepper)", "s",
         [](const ThrowResult& r) { return r.contacts.empty() ? kNaN : r.contacts[0].start_s; }},
        {"contact1_end_time", "end time of the first contact (whole stepper)", "s",
         [](const ThrowResult& r) { return r.contacts.empty() ? kNaN : r.contacts[0].end_s; }},
        {"contact1_exit_speed", "speed at the end of the first contact (whole stepper)", "m/s",
         [](const ThrowResult& r) { return r.contacts.empty() ? kNaN : r.contacts[0].exit_speed_m_s; }},
    };
    for (const auto& q : scalars) {
      auto s = whole_series(q.quantity, q.description, q.unit);
      s.reference_error = f1 ? std::abs(q.get(r_fine) - q.get(r_ref)) : 0;
      for (std::size_t b = 0; b < nd; ++b) {
        const StepperPoint& pt = points[a][b];
        s.h_s.push_back(settings[a][b]);
        const double v = pt.ok ? q.get(pt.full) : kNaN;
        s.value.push_back(v);
        s.error.push_back(std::abs(v - q.get(r_ref)));
        s.notes.push_back(pt.ok ? "" : pt.problem);
      }
      finish_series(s, o);
      res.series.push_back(s);
    }
    {
      auto s = whole_series("contact1_exit_position", "centre of mass at the end of the first contact (whole stepper)", "m");
      s.reference_error = f1 ? (f1->exit_position_m - c1.exit_position_m).norm() : 0;
      for (std::size_t b = 0; b < nd; ++b) {
        const StepperPoint& pt = points[a][b];
        s.h_s.push_back(settings[a][b]);
        s.value.push_back(kNaN);
        s.error.push_back(pt.ok && !pt.full.contacts.empty()
                              ? (pt.full.contacts[0].exit_position_m - c1.exit_position_m).norm()
                              : kNaN);
        s.notes.push_back(pt.ok ? "" : pt.problem);
      }
      finish_series(s, o);
      res.series.push_back(s);
    }
    // Errors of a contact-list quantity (bounce positions, touch points) against the reference;
    // a run whose contact list differs from the reference's has no error to compare.
    auto contact_series = [&](const char* name, const char* title, const char* unit, double ContactComparison::*field) {
      auto s = whole_series(name, title, unit);
      const ContactComparison cf = compare_contacts(r_fine, r_ref);
      s.reference_error = cf.same_contacts() && std::isfinite(cf.*field) ? cf.*field : 0;
      for (std::size_t b = 0; b < nd; ++b) {
        const StepperPoint& pt = points[a][b];
        s.h_s.push_back(settings[a][b]);
        s.value.push_back(kNaN);
        const ContactComparison c = compare_contacts(pt.full, r_ref);
        std::string note = pt.ok ? "" : pt.problem;
        if (pt.ok && !c.same_contacts()) note = "contact lists differ: " + c.brief();
        s.error.push_back(pt.ok && c.same_contacts() ? c.*field : kNaN);
        s.notes.push_back(note);
      }
      finish_series(s, o);
      res.series.push_back(s);
    };
    contact_series("bounce_positions",
                   "largest error of the bounce positions (centre of mass where a contact ends in a bounce; whole "
                   "stepper)",
                   "m", &ContactComparison::max_exit_position_error_m);
    contact_series("touch_points", "largest error of the first-touch points of all contacts (whole stepper)", "m",
                   &ContactComparison::max_touch_error_m);
    if (r_ref.outcome == Outcome::sank) {
      contact_series("sink_position", "centre of mass where the stone sank (whole stepper)", "m",
                     &ContactComparison::max_sink_position_error_m);
      contact_series("sink_time", "time at which the stone sank (whole stepper)", "s",
                     &ContactComparison::sink_time_error_s);
    }
    if (at_ref[3].ok) {
      auto s = whole_series("free_flight_state", "state in free flight after the first bounce (whole stepper)",
                            "1 (relative)");
      s.reference_error = at_fine[3].ok ? state_error(p.stone, at_ref[3].state, at_fine[3].state) : 0;
      for (std::size_t b = 0; b < nd; ++b) {
        const StepperPoint& pt = points[a][b];
        s.h_s.push_back(settings[a][b]);
        s.value.push_back(kNaN);
        s.error.push_back(pt.at_free_flight.ok ? state_error(p.stone, pt.at_free_flight.state, at_ref[3].state) : kNaN);
        s.notes.push_back(pt.at_free_flight.ok ? "" : pt.at_free_flight.problem);
      }
      finish_series(s, o);
      res.series.push_back(s);
    }
  }
  return res;
}

}  // namespace stoneskip
