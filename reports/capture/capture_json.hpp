#pragma once
// One JSON object per capture for `stoneskip capture validate --json`: the verdict with its
// reasons, the timing and saturation figures, and the estimated throw with its intervals (and
// the solvers' bounce counts when they ran).
#include <nlohmann/json.hpp>

#include "verification/captures/capture_throw.hpp"

namespace stoneskip {

nlohmann::json capture_json(const CaptureAnalysis& a, const CaptureSimulation* sim);

}  // namespace stoneskip
