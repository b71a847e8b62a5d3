#pragma once
// Inferring the MotionPlus range mode when the file does not record it (the wiiuse gesture format,
// model/README.md §4): a slow→fast switch shows as a sudden 4–5× drop of |raw − zero| inside a swing. Per axis,
// the mode sequence is the one that makes the rate smoothest: a two-state Viterbi path minimising
//   Σ (ω_k − ω_{k−1})² + switch_cost · (number of switches)
// with ω_k = (raw_k − zero)·(fast ? fast_factor : 1) in slow-mode counts, starting in slow mode.
// With sample times, each difference is divided by its step in typical steps (the rate's change per
// typical step), so an irregular capture is judged by its slope, not by how far apart its rows are.
#include <array>
#include <vector>

namespace stoneskip {

struct GyroRangeInference {
  std::vector<std::array<bool, 3>> fast;  // per sample, per axis (X pitch, Y roll, Z yaw)
  int switches = 0;                        // mode changes over all axes
};

// counts[k][axis] = raw − zero (slow-mode counts from zero).
// t_s: the sample times, or empty for a regular rate.
GyroRangeInference infer_gyro_range(const std::vector<std::array<double, 3>>& counts, double fast_factor,
                                    const std::vector<double>& t_s = {}, double switch_cost_counts2 = 4.0e6);

}  // namespace stoneskip
