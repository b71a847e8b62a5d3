#pragma once
// The estimation chain of capture_analysis.hpp on the kept samples: from the still part to the
// release state, optionally on a perturbed copy (the ensemble). Internal to the capture module.
#include <cstdint>
#include <vector>

#include "verification/captures/capture_analysis.hpp"

namespace stoneskip {

struct ChainInput {
  std::vector<double> t_s;                 // de-jittered, from the first kept sample
  std::vector<Vec3> accel_g;
  std::vector<Vec3> rate_deg_s;            // as recorded
  std::vector<std::array<bool, 3>> fast;
  std::vector<unsigned> buttons;
  std::vector<std::uint32_t> flags;        // with saturation from the threshold
  double period_s = 0;                     // typical interval (only to extend a span at the file's edge)
  double stamp_noise_s = 0;                // half-width of the stamps' noise (stamps used as given)
  double fast_factor = 4.5;
  std::array<double, 3> accel_lsb_g{};     // quantisation step per axis
  std::array<double, 3> gyro_lsb_deg_s{};  // slow mode
  Mounting mounting;
  std::size_t still_begin = 0, still_end = 0, release_sample = 0;
  double release_t_s = 0, release_t_low_s = 0, release_t_high_s = 0;
  bool use_lever = false;                  // clipped: the throw takes the lever-arm velocity …
  double speed_floor_m_s = 0;              // … scaled up to this speed where it is slower (the
                                           // accelerometer's own lower bound, clipped spans as recorded)
  // Rate in slow-mode deg/s (for still detection and bias).
  Vec3 rate_slow_deg_s(std::size_t k) const {
    Vec3 w = rate_deg_s[k];
    for (int i = 0; i < 3; ++i)
      if (fast[k][i]) w[i] /= fast_factor;
    return w;
  }
};

ChainInput make_chain_input(const Trace& trace, const TimedSamples& timing, const CaptureOptions& options);
std::vector<SaturatedSpan> saturated_spans(const ChainInput& in);
int count_range_switches(const ChainInput& in);

struct ChainDiagnostics {
  double still_accel_g = 0;
  Vec3 gyro_bias_deg_s = Vec3::Zero();
};

// The still part (capture_analysis.hpp, step 4): the latest stretch ending at or before `last`,
// at least o.min_still_s long and at most 2 s, where every sample stays within the tolerances of
// the stretch's means. Kept indices [begin, end].
bool find_still(const ChainInput& in, const CaptureOptions& o, std::size_t last, std::size_t& begin, std::size_t& end);

// Runs the chain. `series` (nominal run) receives the world acceleration, the remote's velocity
// and the stone's speed per sample.
ReleaseKinematics run_chain(const ChainInput& in, const CaptureOptions& options, const Perturbation& p,
                            ProcessedSeries* series, ChainDiagnostics* diagnostics);

}  // namespace stoneskip
