#include "reports/capture/capture_json.hpp"

#include <cmath>

namespace stoneskip {

namespace {
nlohmann::json number(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }
// valid: the value exists; interval: an ensemble drew its bounds (null otherwise, not the value twice).
void put(nlohmann::json& j, const std::string& key, const Interval& v, bool valid, bool interval = true) {
  j[key] = valid ? number(v.nominal) : nlohmann::json(nullptr);
  j[key + "_low"] = valid && interval ? number(v.low) : nlohmann::json(nullptr);
  j[key + "_high"] = valid && interval ? number(v.high) : nlohmann::json(nullptr);
}
}  // namespace

nlohmann::json capture_json(const CaptureAnalysis& a, const CaptureSimulation* sim) {
  const TimingStats& t = a.timing.stats;
  const bool ok = a.can_throw();
  nlohmann::json j;
  j["file"] = a.source;
  j["format"] = a.format;
  j["verdict"] = to_string(a.verdict);
  j["reasons"] = a.reasons;
  j["notes"] = a.notes;
  j["warnings"] = a.trace.warnings;
  j["samples"] = t.samples;
  j["repeated_reports"] = t.repeated;
  j["rate_hz"] = number(t.rate_hz);
  j["clock_rate_hz"] = t.clock == ClockModel::regular_reports ? number(t.clock_rate_hz) : nlohmann::json(nullptr);
  j["jitter_ms"] = number(1e3 * t.jitter_s);
  j["gaps"] = t.gaps;
  j["dropped_reports"] = t.dropped_reports;
  j["nominal_timestamps"] = t.nominal;
  j["saturated_fraction"] = number(a.saturated_fraction);
  j["clipped_during_swing"] = a.clipped;
  j["still_part_found"] = a.still_found;
  j["still_accel_g"] = a.still_found ? number(a.still_accel_g) : nlohmann::json(nullptr);
  j["gyro_bias_deg_s"] = {a.gyro_bias_deg_s.x(), a.gyro_bias_deg_s.y(), a.gyro_bias_deg_s.z()};
  j["release_found"] = a.release_found;
  j["release_t_s"] = a.release_found ? number(a.release_t_s) : nlohmann::json(nullptr);
  put(j, "release_speed_m_s", a.speed_m_s, ok, !a.ensemble.empty());
  // Clipped during the swing: the accelerometer's speed is a lower bound, and the release speed
  // is the lever arm's, raised to that bound where slower (verification/captures/capture_analysis.hpp).
  j["accelerometer_speed_is_lower_bound_only"] = a.clipped;
  j["release_speed_source"] = !a.clipped                   ? "accelerometer"
                              : a.nominal.speed_floored ? "lever_arm_raised_to_accelerometer_bound"
                                                        : "lever_arm";
  put(j, "accelerometer_speed_m_s", a.accel_speed_m_s, ok, !a.ensemble.empty());
  put(j, "lever_arm_speed_m_s", a.lever_speed_m_s, ok, !a.ensemble.empty());
  put(j, "attack_angle_deg", a.attack_angle_deg, ok, !a.ensemble.empty());
  put(j, "path_angle_deg", a.path_angle_deg, ok, !a.ensemble.empty());
  put(j, "spin_rev_s", a.spin_rev_s, ok, !a.ensemble.empty());
  put(j, "release_height_m", a.height_m, ok, !a.ensemble.empty());
  j["ensemble_members"] = a.ensemble.size();
  if (sim) {
    j["bounces_realtime"] = sim->realtime ? nlohmann::json(sim->realtime->bounces) : nlohmann::json(nullptr);
    j["bounces_reference"] = sim->reference ? nlohmann::json(sim->reference->bounces) : nlohmann::json(nullptr);
    if (sim->realtime) j["realtime_outcome"] = to_string(sim->realtime->outcome);
    if (sim->reference) j["reference_outcome"] = to_string(sim->reference->outcome);
    if (!sim->ensemble_bounces.empty()) {
      nlohmann::json h = nlohmann::json::object();
      for (const auto& [b, n] : sim->bounce_histogram) h[std::to_string(b)] = n;
      j["ensemble_bounce_histogram"] = h;
      // null where every member failed (no count to take quantiles of).
      const bool none = sim->every_member_failed();
      j["ensemble_bounces_low"] = none ? nlohmann::json(nullptr) : nlohmann::json(sim->bounces_low);
      j["ensemble_bounces_high"] = none ? nlohmann::json(nullptr) : nlohmann::json(sim->bounces_high);
      j["ensemble_bounces_median"] = none ? nlohmann::json(nullptr) : nlohmann::json(sim->bounces_median);
      j["ensemble_failed"] = sim->ensemble_failed;
    }
    // Clipped: the nominal throw at the corners of the speed and height intervals (null: failed).
    if (!sim->corners.empty()) {
      nlohmann::json corners = nlohmann::json::array();
      for (const auto& c : sim->corners)
        corners.push_back({{"speed_m_s", c.speed_m_s},
                           {"height_m", c.height_m},
                           {"bounces", c.bounces >= 0 ? nlohmann::json(c.bounces) : nlohmann::json(nullptr)}});
      j["bound_corners"] = corners;
    }
  }
  return j;
}

}  // namespace stoneskip
