// The height field's step against the memory bandwidth of the same binary, for
// each stencil at 500 × 500 (in cache) and 2048 × 2048 cells (in memory), on one and two threads,
// in float64 and float32 storage. Each benchmark is one call of measure_stencil_throughput
// (verification/waves/stencil_throughput.hpp), which samples the step and a copy kernel alternately
// and reports the best and median of each (wall clock).
//
//   build/verification/stoneskip_wave_studies_bench --benchmark_counters_tabular=true
//   build/verification/stoneskip_wave_studies_bench --benchmark_filter='five_point/2048/2/0' --benchmark_counters_tabular=true
//
// Arguments: n / threads / precision (0 = float64, 1 = float32) / clock (0 = wall, 1 = thread CPU,
// one thread only). Counters: cells_per_s (best),
// bound_cells_per_s = copy bytes/s ÷ (3 values per cell), bandwidth_fraction (best/best),
// fraction_median (median/median: how disturbed the run was), copy_GB_s.
#include <benchmark/benchmark.h>

#include "verification/waves/stencil_throughput.hpp"

namespace stoneskip {
namespace {

void step_throughput(benchmark::State& state, const char* stencil) {
  ThroughputOptions o;
  o.n = static_cast<int>(state.range(0));
  o.threads = static_cast<int>(state.range(1));
  o.precision = state.range(2) ? Precision::float32 : Precision::float64;
  o.stencil = named_stencil(stencil);
  o.clock = state.range(3) ? ThroughputClock::cpu : ThroughputClock::wall;
  if (o.clock == ThroughputClock::cpu && o.threads != 1) {
    state.SkipWithError("the cpu clock needs one thread");
    for (auto _ : state) {
    }
    return;
  }
  ThroughputSummary s;
  for (auto _ : state) s = measure_stencil_throughput(o);
  state.counters["cells_per_s"] = s.cells_per_s;
  state.counters["bound_cells_per_s"] = s.bound_cells_per_s;
  state.counters["bandwidth_fraction"] = s.fraction;
  state.counters["fraction_median"] = s.fraction_median;
  state.counters["copy_GB_s"] = s.copy_bytes_per_s * 1e-9;
  state.SetLabel(s.kernel_isa + ", " + s.clock + " clock");
}

#define STONESKIP_THROUGHPUT(name)                                                                     \
  BENCHMARK_CAPTURE(step_throughput, name, #name)                                                      \
      ->ArgsProduct({{500, 2048}, {1, 2}, {0, 1}, {0, 1}})                                             \
      ->Iterations(1)                                                                                  \
      ->Unit(benchmark::kMillisecond)
STONESKIP_THROUGHPUT(five_point);
STONESKIP_THROUGHPUT(nine_point_half);
STONESKIP_THROUGHPUT(nine_point_isotropic);
STONESKIP_THROUGHPUT(paper_eq11);

}  // namespace
}  // namespace stoneskip
