#pragma once
// A capture against its truth: for a synthetic capture (tools/capture/synthetic_capture.hpp) the
// generator writes what the remote recorded (`NAME.truth.toml`), and `capture validate` stores the
// recovered values beside it so the captures report shows each quantity's truth, estimate and
// interval, and whether the interval holds the truth.
//
// The lever-arm speed (angular rate × lever arm) sees the arm's turn about its pivot, not the
// pivot's own motion (the trunk's turn): it is compared with the truth's arm part
// (`arm_speed_m_s`, |Ω k × L| at the release) as well as with the whole speed, so a bias of the
// size of the pivot's share is shown with its cause, measured, rather than hidden.
#include <cmath>
#include <string>

#include "verification/captures/capture_analysis.hpp"
#include "verification/study/record.hpp"

namespace stoneskip {

struct CaptureTruth {
  std::string file;  // the truth file as found
  double speed_m_s = 0, attack_angle_deg = 0, path_angle_deg = 0, spin_rev_s = 0, rise_m = 0;
  // The arm's part of the velocity and the pivot's speed at the release (NaN when not written).
  double arm_speed_m_s = std::nan(""), pivot_speed_m_s = std::nan("");
};

// The record `truth` of a capture's findings: `file`; one child per compared quantity
// (speed_m_s, accel_speed_m_s, lever_speed_m_s, lever_arm_part_m_s, attack_angle_deg,
// path_angle_deg, spin_rev_s, rise_m) holding `truth`, `nominal`, `low`, `high`, `inside` (0/1)
// and `ratio` (nominal / truth); `pivot_speed_m_s` and `arm_speed_m_s` when known; `compared`
// (the number of quantities) and `inside_count`. Needs a computed throw (a.can_throw()).
Record truth_comparison(const CaptureAnalysis& a, const CaptureTruth& truth);

}  // namespace stoneskip
