#include "verification/captures/capture_throw.hpp"

#include <algorithm>
#include <chrono>


namespace stoneskip {

RigidState capture_initial_state(const Stone& stone, const ReleaseKinematics& r) {
  RigidState s;
  s.position_m = Vec3(0, 0, r.height_m);
  s.velocity_m_s = r.velocity_m_s;
  s.orientation = r.stone_orientation.normalized();
  set_body_angular_velocity(stone, s, r.omega_body_rad_s);
  return s;
}

CaptureSimulation simulate_capture(const Stone& stone, const Environment& env, const CaptureAnalysis& a,
                                   const CaptureSimulationOptions& o) {
  CaptureSimulation sim;
  if (!a.can_throw()) return sim;
  const RigidState s0 = capture_initial_state(stone, a.nominal);
  if (o.realtime) sim.realtime = run_realtime(stone, env, s0, o.realtime_options);
  if (o.reference) sim.reference = run_reference(stone, env, s0, o.reference_options);
  if (o.ensemble && !a.ensemble.empty()) {
    RealtimeOptions ro = o.realtime_options;
    ro.record_trajectory = false;
    const auto start = std::chrono::steady_clock::now();
    for (const ReleaseKinematics& m : a.ensemble) {
      const ThrowResult r = run_realtime(stone, env, capture_initial_state(stone, m), ro);
      sim.ensemble_bounces.push_back(r.bounces);
      ++sim.bounce_histogram[r.bounces];
      if (o.progress) o.progress(sim.ensemble_bounces.size(), a.ensemble.size());
    }
    sim.ensemble_cpu_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::vector<int> b = sim.ensemble_bounces;
    std::sort(b.begin(), b.end());
    auto at = [&](double p) { return b[std::size_t(p * double(b.size() - 1) + 0.5)]; };
    sim.bounces_low = at(0.025);
    sim.bounces_high = at(0.975);
    sim.bounces_median = at(0.5);
  }
  return sim;
}

}  // namespace stoneskip
