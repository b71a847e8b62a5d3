#include "verification/captures/capture_truth.hpp"

namespace stoneskip {

Record truth_comparison(const CaptureAnalysis& a, const CaptureTruth& t) {
  Record r;
  r.set("file", t.file);
  int compared = 0, inside = 0;
  auto row = [&](const char* key, double truth, const Interval& v) {
    Record& c = r.child(key);
    c.set("truth", truth).set("nominal", v.nominal).set("low", v.low).set("high", v.high);
    c.set("inside", v.contains(truth) ? 1.0 : 0.0);
    c.set("ratio", truth != 0 ? v.nominal / truth : std::nan(""));
    ++compared;
    inside += v.contains(truth) ? 1 : 0;
  };
  row("speed_m_s", t.speed_m_s, a.measured_speed_m_s);
  row("accel_speed_m_s", t.speed_m_s, a.accel_speed_m_s);
  row("lever_speed_m_s", t.speed_m_s, a.lever_speed_m_s);
  if (std::isfinite(t.arm_speed_m_s)) row("lever_arm_part_m_s", t.arm_speed_m_s, a.lever_speed_m_s);
  row("attack_angle_deg", t.attack_angle_deg, a.attack_angle_deg);
  row("path_angle_deg", t.path_angle_deg, a.path_angle_deg);
  row("spin_rev_s", t.spin_rev_s, a.measured_spin_rev_s);
  row("rise_m", t.rise_m, a.rise_m);
  r.set("arm_speed_m_s", t.arm_speed_m_s);
  r.set("pivot_speed_m_s", t.pivot_speed_m_s);
  r.set("compared", compared).set("inside_count", inside);
  return r;
}

}  // namespace stoneskip
