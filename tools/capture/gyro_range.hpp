#pragma once
// Inferring the MotionPlus range mode when the file does not record it (the wiiuse gesture format,
// model/README.md §4): a slow→fast switch shows as a sudden 4–5× drop of |raw − zero| inside a swing. Per axis,
// the mode sequence is the one whose rate bends least: a Viterbi path over pairs of modes (the modes
// at k − 1 and k) minimising
//   Σ (s_k − s_{k−1})² + s_1² + switch_cost · (number of switches),   s_k = ω_k − ω_{k−1}
// with ω_k = (raw_k − zero)·(fast ? fast_factor : 1) in slow-mode counts, starting in slow mode.
// The rate's slope, not the rate, is what the device's switch leaves smooth: judged by first
// differences, a swing still speeding up when the record ends (a gesture file ends at the release)
// reads smoother in slow mode, every later step 4.5× smaller, than with its one true switch
// (gyro_range_test.cpp). With sample times, each difference is divided by its step in typical steps
// (the rate's change per typical step), so an irregular capture is judged by its slope, not by how
// far apart its rows are.
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
