#include "verification/captures/capture_throw.hpp"

#include <algorithm>

#include "solvers/realtime/clocks.hpp"

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
  if (o.realtime && o.reference)
    sim.agreement = nudged_agreement(stone, env, s0, o.realtime_options, o.reference_options, o.agreement);
  if (o.ensemble && !a.ensemble.empty()) {
    RealtimeOptions ro = o.realtime_options;
    ro.record_trajectory = false;
    const CpuTimer cpu;
    const WallTimer wall;
    for (const ReleaseKinematics& m : a.ensemble) {
      const ThrowResult r = run_realtime(stone, env, capture_initial_state(stone, m), ro);
      // A failed run's bounces until the failure are not its count.
      const bool failed = r.outcome == Outcome::failed;
      sim.ensemble_bounces.push_back(failed ? -1 : r.bounces);
      if (failed) ++sim.ensemble_failed;
      else ++sim.bounce_histogram[r.bounces];
      if (o.progress) o.progress(sim.ensemble_bounces.size(), a.ensemble.size());
    }
    const double nominal_speed = a.nominal.velocity_m_s.norm();
    if (a.clipped)
      for (const double speed : {a.speed_m_s.low, a.speed_m_s.high})
        for (const double height : {a.height_m.low, a.height_m.high}) {
          if (!(nominal_speed > 0)) {  // no direction to scale: counted as failed, so nothing is decided
            sim.corners.push_back({speed, height, -1});
            continue;
          }
          ReleaseKinematics k = a.nominal;
          k.velocity_m_s *= speed / nominal_speed;  // the release's direction, the bound's speed
          k.height_m = height;
          const ThrowResult r = run_realtime(stone, env, capture_initial_state(stone, k), ro);
          sim.corners.push_back({speed, height, r.outcome == Outcome::failed ? -1 : r.bounces});
        }
    sim.ensemble_cpu_s = cpu.seconds();
    sim.ensemble_wall_s = wall.seconds();
    std::vector<int> b;
    for (int n : sim.ensemble_bounces)
      if (n >= 0) b.push_back(n);
    std::sort(b.begin(), b.end());
    auto at = [&](double p) { return b.empty() ? -1 : b[std::size_t(p * double(b.size() - 1) + 0.5)]; };
    sim.bounces_low = at(kIntervalLowQuantile);
    sim.bounces_high = at(kIntervalHighQuantile);
    sim.bounces_median = at(0.5);
  }
  return sim;
}

}  // namespace stoneskip
