// Cost of one throw: the CVODE reference (BDF and Adams, rtol 1e-8 and 1e-10, atol 1e-12) beside
// the real-time stepper with its default options, on the typical throw: prism R = 3 cm,
// h = 6 mm, N = 11, density 2500 kg/m³, U = 8 m/s, β = 10°, α = 10°, Ω = 10 rev/s, z0 = 0.1 m,
// t_max = 10 s, in both conventions (physical: sinks in the first contact; paper: bounces).
//   build-*/solvers/stoneskip_reference_bench
// Counters: steps, rhs (right-hand-side evaluations), segments (restarts at located events),
// bounces, end_s (when the throw ended) — per throw.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "model/stone/throw.hpp"
#include "solvers/realtime/stone_stepper.hpp"
#include "solvers/reference/cvode_stone.hpp"

using namespace stoneskip;

namespace {

const Stone& typical_stone() {
  static const Stone s = [] {
    const Mesh m = make_prism(0.03, 0.006, 11);
    return make_stone(m, mass_properties_from_density(m, 2500), 0, "prism R=0.03 h=0.006 N=11");
  }();
  return s;
}

RigidState typical_throw() {
  ThrowParameters p;
  p.speed_m_s = 8;
  p.path_angle_deg = 10;
  p.attack_angle_deg = 10;
  p.spin_rev_s = 10;
  p.height_m = 0.1;
  return initial_state(typical_stone(), p);
}

Environment environment(int convention) {
  Environment env;
  env.convention = convention == 0 ? Convention::physical : Convention::paper;
  return env;
}

void report(benchmark::State& state, const ThrowResult& r) {
  state.counters["steps"] = static_cast<double>(r.stats.steps);
  state.counters["rhs"] = static_cast<double>(r.stats.rhs_evaluations);
  state.counters["segments"] = static_cast<double>(r.stats.segments);
  state.counters["bounces"] = r.bounces;
  state.counters["end_s"] = r.end_time_s;
  if (r.outcome == Outcome::failed) state.SkipWithError(r.outcome_detail.c_str());
}

// Args: convention (0 physical, 1 paper), method (0 BDF, 1 Adams), −log10 rtol.
void BM_ReferenceThrow(benchmark::State& state) {
  const Environment env = environment(static_cast<int>(state.range(0)));
  ReferenceOptions o;
  o.method = state.range(1) == 0 ? ReferenceMethod::bdf : ReferenceMethod::adams;
  o.rtol = std::pow(10.0, -static_cast<double>(state.range(2)));
  o.atol = 1e-12;
  const RigidState s0 = typical_throw();
  ThrowResult r;
  for (auto _ : state) {
    r = run_reference(typical_stone(), env, s0, o);
    benchmark::DoNotOptimize(r.final_state);
  }
  state.SetLabel(std::string(to_string(env.convention)) + " " + r.solver);
  report(state, r);
}
BENCHMARK(BM_ReferenceThrow)
    ->ArgNames({"paper", "adams", "mlog10rtol"})
    ->ArgsProduct({{0, 1}, {0, 1}, {8, 10}})
    ->Unit(benchmark::kMillisecond);

// Arg: convention (0 physical, 1 paper). Default RealtimeOptions (semi-implicit Euler, 1 ms
// flight step, 0.1 ms contact step).
void BM_RealtimeThrow(benchmark::State& state) {
  const Environment env = environment(static_cast<int>(state.range(0)));
  const RealtimeOptions o;
  const RigidState s0 = typical_throw();
  ThrowResult r;
  for (auto _ : state) {
    r = run_realtime(typical_stone(), env, s0, o);
    benchmark::DoNotOptimize(r.final_state);
  }
  state.SetLabel(std::string(to_string(env.convention)) + " " + r.solver);
  report(state, r);
}
BENCHMARK(BM_RealtimeThrow)->ArgName("paper")->DenseRange(0, 1)->Unit(benchmark::kMillisecond);

}  // namespace
