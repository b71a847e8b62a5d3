// One leapfrog step of each stencil at 500 × 500 and 2048 × 2048 cells, and a memory-copy kernel of
// the same size, so that the step's speed can be stated against the machine's bandwidth bound.
//
//   build-*/verification/stoneskip_wave_studies_bench --benchmark_counters_tabular=true
//
// Counters: cells_per_s — cell updates per second; bandwidth_fraction — the step's rate divided by
// the bound a copy-measured bandwidth allows: a step must read z and z⁻ and write z⁺ (in place of
// z⁻), 24 bytes per cell, so the bound is (copy bytes per second) / 24. The copy kernel counts
// 16 bytes per element (read + write, as STREAM does).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <vector>

#include "model/water/disturbance.hpp"
#include "model/water/height_field.hpp"

namespace stoneskip {
namespace {

constexpr double kStepBytesPerCell = 24;  // read z, read z⁻, write z⁺
constexpr double kCopyBytesPerElement = 16;

// Copy bandwidth (bytes/s) for arrays of n doubles: the best of several timed copies.
double copy_bandwidth(std::size_t n) {
  static std::map<std::size_t, double> cache;
  auto it = cache.find(n);
  if (it != cache.end()) return it->second;
  std::vector<double> a(n, 1.0), b(n, 0.0);
  double best = 1e300;
  for (int r = 0; r < 20; ++r) {
    auto t0 = std::chrono::steady_clock::now();
    std::copy(a.begin(), a.end(), b.begin());
    benchmark::DoNotOptimize(b.data());
    benchmark::ClobberMemory();
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    std::swap(a, b);
  }
  return cache[n] = kCopyBytesPerElement * static_cast<double>(n) / best;
}

void step_benchmark(benchmark::State& state, const char* stencil) {
  const int n = static_cast<int>(state.range(0));
  HeightFieldOptions o;
  o.nx = o.ny = n;
  o.cell_m = 1.0 / n;
  o.dt_s = 0.5 * o.cell_m;
  o.damping_per_s = 0.5;
  o.stencil = named_stencil(stencil);
  HeightField f(o);
  Disturbance d;
  d.x_m = d.y_m = 0.5;
  std::vector<double> z0;
  sample_disturbance(d, n, n, o.cell_m, z0);
  f.set_state(z0);
  const auto t0 = std::chrono::steady_clock::now();
  for (auto _ : state) {
    f.step();
    benchmark::ClobberMemory();
  }
  const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cells = static_cast<double>(n) * n;
  const double rate = cells * static_cast<double>(state.iterations()) / elapsed_s;
  const double bound = copy_bandwidth(static_cast<std::size_t>(n + 2) * (n + 2)) / kStepBytesPerCell;
  state.counters["cells_per_s"] = rate;
  state.counters["bound_cells_per_s"] = bound;
  state.counters["bandwidth_fraction"] = rate / bound;
}

void copy_benchmark(benchmark::State& state) {
  const std::size_t n = static_cast<std::size_t>(state.range(0)) * state.range(0);
  std::vector<double> a(n, 1.0), b(n, 0.0);
  for (auto _ : state) {
    std::copy(a.begin(), a.end(), b.begin());
    benchmark::DoNotOptimize(b.data());
    benchmark::ClobberMemory();
  }
  state.SetBytesProcessed(static_cast<int64_t>(kCopyBytesPerElement * n * state.iterations()));
  state.counters["elements_per_s"] = benchmark::Counter(static_cast<double>(n) * state.iterations(), benchmark::Counter::kIsRate);
}

BENCHMARK_CAPTURE(step_benchmark, five_point, "five_point")->Arg(500)->Arg(2048)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(step_benchmark, nine_point_half, "nine_point_half")->Arg(500)->Arg(2048)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(step_benchmark, nine_point_isotropic, "nine_point_isotropic")->Arg(500)->Arg(2048)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(step_benchmark, paper_eq11, "paper_eq11")->Arg(500)->Arg(2048)->Unit(benchmark::kMicrosecond);
BENCHMARK(copy_benchmark)->Arg(500)->Arg(2048)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace stoneskip
