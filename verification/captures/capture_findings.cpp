#include "verification/captures/capture_findings.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <numbers>

#include "verification/study/verdict_rules.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kWarningsKept = 20;  // the page lists this many reader warnings and counts the rest

void put_interval(Record& parent, const std::string& key, const Interval& v) {
  parent.child(key).set("nominal", v.nominal).set("low", v.low).set("high", v.high);
}

std::string joined(const std::vector<std::string>& v, const std::string& sep) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
  return s;
}

Record settings_findings(const CaptureAnalysis& a) {
  const CaptureOptions& o = a.options;
  Record r;
  r.set_strings("mounting", mounting_settings(o.mounting));
  r.set_strings("thrower", thrower_settings(o.thrower));
  r.set("height_mapping", std::string(to_string(o.thrower.height_mapping)));
  r.set("release_height_m", o.thrower.release_height_m);
  r.set("still_height_m", o.thrower.still_height_m);
  r.set("speed_scale", o.thrower.speed_scale);
  r.set("spin_scale", o.thrower.spin_scale);
  r.set("finger_spin_rev_s", o.thrower.finger_spin_rev_s);
  r.set("clock_option", std::string(to_string(o.timing.clock)));
  r.set("release_button", std::string(o.release_button == kButtonA ? "A" : "B"));
  // The ensemble's perturbations (capture_analysis.hpp, "Uncertainty").
  r.set("members_requested", o.members);
  r.set("seed", static_cast<double>(o.seed));
  r.set("accel_noise_g", o.accel_noise_g);
  r.set("accel_bias_g", o.accel_bias_g);
  r.set("gyro_noise_deg_s", o.gyro_noise_deg_s);
  r.set("gyro_scale_rel_uncertainty", o.gyro_scale_rel_uncertainty);
  r.set("lever_arm_rel_uncertainty", o.mounting.lever_arm_rel_uncertainty);
  r.set("height_uncertainty_m", o.thrower.height_uncertainty_m);
  r.set("max_accel_g", o.max_accel_g);
  r.set("max_rate_deg_s", o.max_rate_deg_s);
  r.set("interval_low_percent", 100 * kIntervalLowQuantile);
  r.set("interval_high_percent", 100 * kIntervalHighQuantile);
  return r;
}

Record timing_findings(const CaptureAnalysis& a) {
  const TimingStats& t = a.timing.stats;
  Record r;
  r.set("samples", t.samples);
  r.set("repeated", t.repeated);
  r.set("used", t.used);
  r.set("duration_s", t.duration_s);
  r.set("period_s", t.period_s);
  r.set("rate_hz", t.rate_hz);
  r.set("mean_rate_hz", t.mean_rate_hz);
  r.set("jitter_s", t.jitter_s);
  r.set("max_jitter_s", t.max_jitter_s);
  r.set("min_interval_s", t.min_interval_s);
  r.set("max_interval_s", t.max_interval_s);
  r.set("equal_stamps", t.equal_stamps);
  r.set("clock_residual_rms_s", t.clock_residual_rms_s);
  r.set("clock_residual_max_s", t.clock_residual_max_s);
  r.set("clock_rate_hz", t.clock_rate_hz);  // the regular clock fitted through the reports' slots
  r.set("clock", std::string(to_string(t.clock)));
  r.set("gaps", t.gaps);
  r.set("dropped_reports", t.dropped_reports);
  r.set("longest_gap_s", t.longest_gap_s);
  r.set("nominal", t.nominal);
  r.set("ok", t.ok);
  r.set("bursts", t.bursts);
  r.set("gap_factor", a.options.timing.gap_factor);
  r.set("regular_max_residual_intervals", a.options.timing.regular_max_residual_intervals);
  // Every interval between kept reports as stamped, the reports lost before each, and how far each
  // stamp lies from the clock used (zero when the stamps are used as given).
  Table iv{{"t_s", "interval_ms", "lost_reports", "stamp_minus_clock_ms"}, {}};
  const TimedSamples& ts = a.timing;
  const bool slots = ts.report_index.size() == ts.index.size();
  for (std::size_t k = 1; k < ts.index.size() && k < a.series.t_s.size(); ++k) {
    const double stamp = a.trace.samples[ts.index[k]].t_s;
    iv.add_row({a.series.t_s[k], 1e3 * (stamp - a.trace.samples[ts.index[k - 1]].t_s),
                slots ? double(ts.report_index[k] - ts.report_index[k - 1] - 1) : 0.0, 1e3 * (stamp - ts.t_s[k])});
  }
  r.set_table("intervals", iv);
  return r;
}

Record motion_findings(const CaptureAnalysis& a) {
  const CaptureOptions& o = a.options;
  Record r;
  Record& sat = r.child("saturation");
  sat.set("saturation_g", o.saturation_g);
  sat.set("samples_x", a.saturated_samples[0]);
  sat.set("samples_y", a.saturated_samples[1]);
  sat.set("samples_z", a.saturated_samples[2]);
  sat.set("samples_any", a.saturated_any);
  sat.set("fraction", a.saturated_fraction);
  sat.set("in_swing", a.saturated_in_swing);
  sat.set("swing_samples", a.swing_samples);
  sat.set("clipped_in_swing", a.clipped);
  sat.set("clipped_axes", a.clipped_axes);
  sat.set("gyro_saturated_in_swing", a.gyro_saturated_in_swing);
  Table spans{{"axis", "t0_s", "t1_s", "samples"}, {}};
  for (const auto& s : a.spans) spans.add_row({double(s.axis), s.t0_s, s.t1_s, double(s.samples)});
  sat.set_table("spans", spans);

  Record& still = r.child("still");
  still.set("found", a.still_found);
  still.set("t0_s", a.still_found ? a.still_t0_s : kNaN);
  still.set("t1_s", a.still_found ? a.still_t1_s : kNaN);
  still.set("accel_g", a.nominal_computed ? a.still_accel_g : kNaN);
  still.set("accel_error_g", a.nominal_computed ? a.still_accel_error_g : kNaN);
  still.set("caveat_g", o.rules.calibration_caveat_g);
  still.set("unusable_g", o.rules.calibration_unusable_g);
  still.set("min_still_s", o.min_still_s);
  still.set("accel_tol_g", o.still_accel_tol_g);
  still.set("rate_tol_deg_s", o.still_rate_tol_deg_s);
  for (int i = 0; i < 3; ++i)
    still.set(std::string("gyro_bias_") + "xyz"[i] + "_deg_s", a.nominal_computed ? a.gyro_bias_deg_s[i] : kNaN);
  still.set("range_switches", a.gyro_range_switches);
  still.set("range_inferred", a.trace.gyro_mode_inferred);

  Record& rel = r.child("release");
  rel.set("button", std::string(o.release_button == kButtonA ? "A" : "B"));
  rel.set("has_buttons", a.trace.has_buttons);
  rel.set("press_found", a.press_found);
  rel.set("found", a.release_found);
  rel.set("at_end", a.release_at_end);
  rel.set("t_s", a.release_found ? a.release_t_s : kNaN);
  rel.set("t_low_s", a.release_found ? a.release_t_low_s : kNaN);
  rel.set("t_high_s", a.release_found ? a.release_t_high_s : kNaN);

  // The samples as the plots show them: the rate with the gyro bias removed once the still part
  // is known; the stone's speed from the integrated accelerometer and from ω × lever arm.
  const ProcessedSeries& s = a.series;
  const bool full = s.world_accel_m_s2.size() == s.t_s.size() && s.rate_deg_s.size() == s.t_s.size();
  Table t{{"t_s", "ax_g", "ay_g", "az_g", "wx_deg_s", "wy_deg_s", "wz_deg_s", "button", "clipped", "stone_speed_m_s",
           "lever_speed_m_s"},
          {}};
  const Vec3 lever = o.mounting.lever_arm_m;
  for (std::size_t k = 0; k < s.t_s.size(); ++k) {
    const Vec3 w = full ? s.rate_deg_s[k] : a.trace.samples[a.timing.index[k]].rate_deg_s;
    const double lever_speed = full ? (w * (std::numbers::pi / 180.0)).cross(lever).norm() : kNaN;
    t.add_row({s.t_s[k], s.accel_g[k].x(), s.accel_g[k].y(), s.accel_g[k].z(), w.x(), w.y(), w.z(),
               double((s.buttons[k] & o.release_button) != 0), double((s.flags[k] & kAccelSaturated) != 0),
               full ? s.stone_speed_m_s[k] : kNaN, lever_speed});
  }
  r.set_table("samples", t);
  r.set("bias_removed", full);
  return r;
}

Record throw_findings(const CaptureAnalysis& a, const CaptureSimulation& sim) {
  Record r;
  const bool ok = a.can_throw();
  r.set("computed", ok);
  if (!ok) return r;
  const ReleaseKinematics& n = a.nominal;
  r.set("members", a.ensemble.size());
  r.set("clipped", a.clipped);
  r.set("release_t_s", n.t_s);
  r.set("speed_difference_m_s", a.speed_difference_m_s);
  r.set("accel_lower_speed_m_s", a.accel_lower.accel_speed_m_s);
  r.set("accel_upper_speed_m_s", a.accel_upper.accel_speed_m_s);
  // Clipped: whether the lever arm's speed was raised to the accelerometer's lower bound (absent in
  // data written before the speeds were raised: the page then describes the older method).
  if (a.clipped) r.set("lever_raised_to_bound", a.nominal.speed_floored);
  r.set("roll_angle_deg", n.roll_angle_deg);
  Record& v = r.child("virtual");
  put_interval(v, "speed_m_s", a.speed_m_s);
  put_interval(v, "attack_angle_deg", a.attack_angle_deg);
  put_interval(v, "path_angle_deg", a.path_angle_deg);
  put_interval(v, "spin_rev_s", a.spin_rev_s);
  put_interval(v, "height_m", a.height_m);
  Record& m = r.child("measured");
  put_interval(m, "speed_m_s", a.measured_speed_m_s);
  put_interval(m, "accel_speed_m_s", a.accel_speed_m_s);
  put_interval(m, "lever_speed_m_s", a.lever_speed_m_s);
  put_interval(m, "spin_rev_s", a.measured_spin_rev_s);
  put_interval(m, "rise_m", a.rise_m);
  // The release velocities, room and virtual (heading turned: horizontal along +x).
  for (int i = 0; i < 3; ++i) {
    r.set(std::string("measured_v") + "xyz"[i] + "_m_s", n.measured.velocity_m_s[i]);
    r.set(std::string("virtual_v") + "xyz"[i] + "_m_s", n.velocity_m_s[i]);
  }
  const bool bounces = sim.ensemble_bounces.size() == a.ensemble.size();
  Table e{{"speed_m_s", "attack_angle_deg", "path_angle_deg", "spin_rev_s", "height_m", "measured_speed_m_s",
           "accel_speed_m_s", "lever_speed_m_s", "measured_spin_rev_s", "rise_m", "bounces_realtime"},
          {}};
  for (std::size_t k = 0; k < a.ensemble.size(); ++k) {
    const ReleaseKinematics& x = a.ensemble[k];
    e.add_row({x.speed_m_s, x.attack_angle_deg, x.path_angle_deg, x.spin_rev_s, x.height_m, x.measured_speed_m_s,
               x.accel_speed_m_s, x.lever_speed_m_s, x.measured_spin_rev_s, x.measured.rise_m,
               bounces && sim.ensemble_bounces[k] >= 0 ? double(sim.ensemble_bounces[k]) : kNaN});
  }
  r.set_table("ensemble", e);
  // The stone in the room from the start of the still part to the last sample before the release.
  Table path{{"t_s", "x_m", "y_m", "z_m"}, {}};
  const ProcessedSeries& s = a.series;
  if (s.stone_position_m.size() == s.t_s.size())
    for (std::size_t k = a.still_begin; k <= a.release_sample && k < s.t_s.size(); ++k)
      path.add_row({s.t_s[k], s.stone_position_m[k].x(), s.stone_position_m[k].y(), s.stone_position_m[k].z()});
  r.set_table("room_path", path);
  return r;
}

Record solver_findings(const ThrowResult& t) {
  Record r;
  r.set("solver", t.solver);
  r.set("bounces", t.bounces);
  r.set("contacts", t.contacts.size());
  r.set("outcome", std::string(to_string(t.outcome)));
  r.set("outcome_detail", t.outcome_detail);
  r.set("distance_m", t.distance_m);
  r.set("cpu_s", t.stats.cpu_s);
  r.set("wall_s", t.stats.wall_s);
  // The largest rise of the total energy over a contact (> 0: the water created energy, as the
  // paper convention's printed equations can, model/README.md §1.6), and how many contacts gained.
  r.set("max_energy_gain_J", t.max_energy_gain_J);
  r.set("contacts_gaining_energy",
        std::count_if(t.contacts.begin(), t.contacts.end(), [](const ContactRecord& k) { return k.exit_energy_J > k.entry_energy_J; }));
  Table path{{"t_s", "x_m", "y_m", "z_m"}, {}};
  for (const auto& p : t.trajectory) path.add_row({p.t_s, p.state.position_m.x(), p.state.position_m.y(), p.state.position_m.z()});
  r.set_table("trajectory", path);
  Table c{{"start_s", "end_s", "entry_speed_m_s", "exit_speed_m_s", "x_m", "bounced"}, {}};
  for (const auto& k : t.contacts)
    c.add_row({k.start_s, k.end_s, k.entry_speed_m_s, k.exit_speed_m_s, k.entry_position_m.x(), double(k.bounced)});
  r.set_table("contact_list", c);
  return r;
}

std::string bounce_words(double n) { return num(n) + (n == 1 ? " bounce" : " bounces"); }

Record simulation_findings(const CaptureSimulation& sim, const CaptureFindingsContext& c) {
  Record r;
  const bool ran = sim.realtime || sim.reference;
  r.set("ran", ran);
  r.set("case_file", c.case_file);
  r.set("stone_description", c.stone_description);
  r.set("convention", c.convention);
  r.set("water_law", c.water_law);
  if (sim.realtime) r.add_child("realtime", solver_findings(*sim.realtime));
  if (sim.reference) r.add_child("reference", solver_findings(*sim.reference));
  if (sim.realtime && sim.reference) {
    auto made = [](const ThrowResult& t) {
      return t.outcome == Outcome::failed ? "fails after " + bounce_words(t.bounces) : "makes " + bounce_words(t.bounces);
    };
    // A chaotic count: decided on ensembles of the nominal throw, never run against run.
    decide_nudged_agreement(r, "agreement", sim.agreement,
                            "the real-time model " + made(*sim.realtime) + " of the nominal throw, the reference (CVODE) " +
                                made(*sim.reference) + " (one run each)",
                            "the real-time model", "the reference");
  }
  if (!sim.ensemble_bounces.empty()) {
    Record& e = r.child("ensemble");
    e.set("members", sim.ensemble_bounces.size());
    e.set("failed", sim.ensemble_failed);
    e.set("cpu_s", sim.ensemble_cpu_s);
    e.set("wall_s", sim.ensemble_wall_s);
    // Every member failed: no count to take quantiles of (NaN, not the −1 that marks a failure).
    const bool none = sim.every_member_failed();
    auto count = [none](int n) { return none ? kNaN : double(n); };
    e.set("bounces_low", count(sim.bounces_low));
    e.set("bounces_median", count(sim.bounces_median));
    e.set("bounces_high", count(sim.bounces_high));
    e.set("low_percent", 100 * kIntervalLowQuantile);
    e.set("high_percent", 100 * kIntervalHighQuantile);
    Table h{{"bounces", "members"}, {}};
    for (const auto& [b, m] : sim.bounce_histogram) h.add_row({double(b), double(m)});
    e.set_table("histogram", h);
    Record in;
    in.set("bounces_low", count(sim.bounces_low)).set("bounces_high", count(sim.bounces_high)).set("failed_runs", sim.ensemble_failed);
    // Clipped: the nominal throw at the corners of the speed and height intervals, which the clipped
    // accelerometer's bounds widen past the members' range.
    std::string corners_why;
    if (!sim.corners.empty()) {
      Table k{{"speed_m_s", "height_m", "bounces_realtime"}, {}};
      for (const auto& x : sim.corners) k.add_row({x.speed_m_s, x.height_m, x.bounces >= 0 ? double(x.bounces) : kNaN});
      const auto [least, most, failed] = sim.corner_range();
      e.set_table("bound_corners", k);
      in.set("corner_failed", failed);
      if (most >= 0) in.set("corner_bounces_least", least).set("corner_bounces_most", most);
      const auto& cs = sim.corners;
      corners_why = "; the nominal throw at the corners of the speed interval (" + num(cs.front().speed_m_s) + " to " +
                    num(cs.back().speed_m_s) + " m/s) and the height interval (" + num(cs.front().height_m) + " to " +
                    num(cs.back().height_m) + " m), the clipped accelerometer's bounds joined with the members' range, " +
                    (most < 0 ? std::string("failed")
                              : (least == most ? "makes " + bounce_words(least) : "makes " + num(least) + " to " + bounce_words(most))) +
                    (failed > 0 && most >= 0 ? " (" + num(double(failed)) + " of " + num(double(cs.size())) + " failed)" : std::string());
    }
    const std::string range = sim.bounces_low == sim.bounces_high
                                  ? bounce_words(sim.bounces_low)
                                  : num(sim.bounces_low) + " to " + bounce_words(sim.bounces_high);
    const std::string why =
        (none ? "no member finished: all " + num(double(sim.ensemble_bounces.size())) +
                    " members of the capture's ensemble failed in the real-time model"
              : "the central " + num(100 * (kIntervalHighQuantile - kIntervalLowQuantile)) + " % of the " +
                   num(double(sim.ensemble_bounces.size())) + " members of the capture's ensemble make " + range +
                   " in the real-time model (median " + num(sim.bounces_median) + ")" +
                   (sim.ensemble_failed > 0 ? "; " + num(double(sim.ensemble_failed)) + " of the " +
                                                  num(double(sim.ensemble_bounces.size())) +
                                                  " runs failed and have no count, so the spread is that of the rest"
                                            : std::string())) +
        corners_why;
    decide_verdict(e, "spread", "bounce_spread", in, why);
  }
  return r;
}

}  // namespace

std::string capture_section_key(const std::string& file, std::vector<std::string>& used) {
  const std::size_t slash = file.find_last_of('/');
  std::string stem = slash == std::string::npos ? file : file.substr(slash + 1);
  for (char& ch : stem) {
    const unsigned char u = static_cast<unsigned char>(ch);
    ch = std::isalnum(u) && u < 128 ? static_cast<char>(std::tolower(u)) : '_';
  }
  if (stem.empty() || stem.front() == '_') stem = "capture" + stem;
  std::string key = stem;
  auto taken = [&](const std::string& k) {
    if (k == "index") return true;  // the index section's name
    for (const auto& u : used)
      if (u == k) return true;
    return false;
  };
  for (int k = 2; taken(key); ++k) key = stem + "_" + std::to_string(k);
  used.push_back(key);
  return key;
}

Record capture_findings(const CaptureAnalysis& a, const CaptureSimulation& sim, const CaptureFindingsContext& c) {
  Record r;
  r.set("file", a.source);
  r.set("format", a.format);
  decide_verdict(r, "verdict", "capture_verdict", capture_verdict_inputs(a, a.options.rules),
                 a.reasons.empty() ? "nothing in this capture limits the estimate beyond its intervals"
                                   : joined(a.reasons, "; "));
  r.set_strings("reasons", a.reasons);
  r.set_strings("notes", a.notes);
  const auto& w = a.trace.warnings;
  r.set_strings("reader_warnings",
                std::vector<std::string>(w.begin(), w.begin() + std::min<std::ptrdiff_t>(kWarningsKept, std::ptrdiff_t(w.size()))));
  r.set("reader_warnings_total", w.size());
  r.add_child("settings", settings_findings(a));
  r.add_child("timing", timing_findings(a));
  r.add_child("motion", motion_findings(a));
  r.add_child("throw", throw_findings(a, sim));
  r.add_child("simulation", simulation_findings(sim, c));
  return r;
}

Record capture_index_findings(const std::vector<std::pair<std::string, Record>>& captures,
                              const CaptureFindingsContext& c) {
  Record r;
  r.set("case_file", c.case_file);
  r.set("stone_description", c.stone_description);
  r.set("convention", c.convention);
  r.set("water_law", c.water_law);
  r.set("low_percent", 100 * kIntervalLowQuantile);
  r.set("high_percent", 100 * kIntervalHighQuantile);
  std::vector<std::string> keys;
  double usable = 0, caveats = 0, unusable = 0;
  for (const auto& [key, rec] : captures) {
    keys.push_back(key);
    const Verdict v = verdict_from_phrase(rec.at("verdict").text("verdict"));
    (v == Verdict::usable ? usable : v == Verdict::usable_with_caveats ? caveats : unusable) += 1;
  }
  r.set_strings("captures", keys);
  r.set("count", captures.size());
  r.set("usable", usable);
  r.set("usable_with_caveats", caveats);
  r.set("unusable", unusable);
  return r;
}

}  // namespace stoneskip
