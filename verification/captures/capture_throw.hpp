#pragma once
// A capture's throw through the solvers (model/README.md §1.7: a throw given as a full state): the nominal
// release state through the real-time model and/or the CVODE reference, and the ensemble of
// perturbed release states (capture_analysis.hpp) through the real-time model only (cheap), which
// turns the capture's uncertainty into a distribution of bounce counts.
#include <algorithm>
#include <functional>
#include <map>
#include <optional>

#include "solvers/realtime/stone_stepper.hpp"
#include "solvers/reference/cvode_stone.hpp"
#include "verification/captures/capture_analysis.hpp"
#include "verification/captures/nudged_agreement.hpp"

namespace stoneskip {

// The stone's initial state from a release: position (0, 0, height), the release velocity, the
// stone's orientation and its body angular velocity (rigid_state.hpp).
RigidState capture_initial_state(const Stone& stone, const ReleaseKinematics& r);

struct CaptureSimulationOptions {
  bool realtime = true;
  bool reference = true;
  bool ensemble = true;        // the ensemble through the real-time model
  RealtimeOptions realtime_options;
  ReferenceOptions reference_options;
  // Called after each ensemble member (done, total); empty: no progress. Nothing here prints.
  std::function<void(std::size_t done, std::size_t total)> progress;
  // The real-time model against the reference on the nominal throw's bounce count, decided on
  // ensembles of it (nudged_agreement.hpp): with both solvers only.
  NudgedAgreementOptions agreement;
};

struct CaptureSimulation {
  std::optional<ThrowResult> realtime;   // nominal throw
  std::optional<ThrowResult> reference;  // nominal throw
  NudgedAgreement agreement;             // both solvers on the nominal throw's speed × 1 ± ε
  std::vector<int> ensemble_bounces;     // one per ensemble member (real-time model); −1: the run failed
  std::map<int, int> bounce_histogram;   // bounces → members, over the members that did not fail
  int ensemble_failed = 0;               // members whose run failed (they have no count)
  // Clipped captures: the accelerometer only bounds the speed and the rise, and the members (the
  // lever arm's speed, each raised to its own bound) need not reach those bounds. The nominal throw
  // at the four corners of the speed and height intervals, through the real-time model, so that a
  // count the bounds allow is not missed (bounces −1: the run failed, or the nominal throw has no
  // speed to scale). Empty when not clipped.
  struct Corner {
    double speed_m_s = 0, height_m = 0;
    int bounces = 0;
  };
  std::vector<Corner> corners;
  // The corners' counts: least and most over the runs that finished (−1, −1 when none did), and
  // how many failed.
  struct CornerRange {
    int least = -1, most = -1, failed = 0;
  };
  CornerRange corner_range() const {
    CornerRange r;
    for (const auto& c : corners) {
      if (c.bounces < 0) {
        ++r.failed;
        continue;
      }
      r.least = r.least < 0 ? c.bounces : std::min(r.least, c.bounces);
      r.most = std::max(r.most, c.bounces);
    }
    return r;
  }
  // An ensemble ran and every member failed: no count to take quantiles of.
  bool every_member_failed() const {
    return !ensemble_bounces.empty() && ensemble_failed == static_cast<int>(ensemble_bounces.size());
  }
  double ensemble_cpu_s = 0;   // thread CPU time of the ensemble's runs (solvers/realtime/clocks.hpp)
  double ensemble_wall_s = 0;  // … and wall-clock time
  // The interval quantiles and the median over the members that did not fail (−1: none did).
  int bounces_low = 0, bounces_high = 0, bounces_median = 0;
};

CaptureSimulation simulate_capture(const Stone& stone, const Environment& env, const CaptureAnalysis& a,
                                   const CaptureSimulationOptions& options);

}  // namespace stoneskip
