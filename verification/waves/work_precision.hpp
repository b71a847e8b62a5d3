#pragma once
// Speed against error: the fixed wave problem solved by one stencil over a range of grids and
// Courant numbers, each run's error against the continuum reference beside its CPU time. The
// question it answers (Lee & Baek 2013, §3.2): does a stencil reach a given error for less work?
#include <string>
#include <vector>

#include "model/water/stencil.hpp"
#include "verification/study/progress.hpp"
#include "verification/waves/wave_problem.hpp"

namespace stoneskip {



struct WaveWorkPoint {
  int n = 0;
  double sigma = 0;
  long steps = 0;
  double l2_m = 0, max_m = 0;
  double cpu_s = 0;
};

struct WaveWorkPrecisionOptions {
  WaveProblem problem;
  std::vector<int> grids{32, 48, 64, 96, 128, 192, 256, 384};
  std::vector<double> sigma_fractions{0.3, 0.6, 0.95};  // of the stencil's own stability limit
  double stability_limit = 0.7;  // set per stencil by the caller (from stability_limit())
  double min_cpu_s = 0.02;       // short runs are repeated until this much CPU is spent
};

std::vector<WaveWorkPoint> run_work_precision(const Stencil& stencil, const WaveWorkPrecisionOptions& options,
                                          ProgressTicker* progress = nullptr);
std::size_t work_precision_work(const WaveWorkPrecisionOptions& options);

// The least CPU time among points whose RMS error is at most `target_m` (NaN if none reaches it).
double cpu_to_reach(const std::vector<WaveWorkPoint>& points, double target_m);

}  // namespace stoneskip
