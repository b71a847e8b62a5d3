// Cost of one throw: the CVODE reference (BDF and Adams, rtol 1e-8 and 1e-10, atol 1e-12, restarts
// at every event or at jumps only) beside the real-time stepper with its default options, on the
// typical throw: prism R = 3 cm, h = 6 mm, N = 11, density 2500 kg/m³, U = 8 m/s, β = 10°, α = 10°,
// Ω = 10 rev/s, z0 = 0.1 m, t_max = 10 s, in both conventions (physical: sinks in the first
// contact; paper: bounces); and the reference on Clanet's disk (R 2.5 cm, h 2.75 mm, N = 32,
// 2700 kg/m³) thrown at 3.5 m/s, α = β = 20°, with 65 rev/s or none, under each water law, with
// each restart strategy.
//   build-*/solvers/stoneskip_reference_bench
//   build-*/solvers/stoneskip_reference_bench --benchmark_filter=Clanet
// Counters: steps, rhs (right-hand-side evaluations), segments (restarts at located events),
// bounces, end_s (when the throw ended) — per throw.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "model/stone/throw.hpp"
#include "model/stone/water_laws.hpp"
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

constexpr RestartStrategy kRestarts[] = {RestartStrategy::every_event, RestartStrategy::every_crossing,
                                         RestartStrategy::at_jumps, RestartStrategy::never};

// Args: convention (0 physical, 1 paper), method (0 BDF, 1 Adams), −log10 rtol, restart (0 every
// event, 2 at jumps).
void BM_ReferenceThrow(benchmark::State& state) {
  const Environment env = environment(static_cast<int>(state.range(0)));
  ReferenceOptions o;
  o.method = state.range(1) == 0 ? ReferenceMethod::bdf : ReferenceMethod::adams;
  o.rtol = std::pow(10.0, -static_cast<double>(state.range(2)));
  o.atol = 1e-12;
  o.restart = kRestarts[state.range(3)];
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
    ->ArgNames({"paper", "adams", "mlog10rtol", "restart"})
    ->ArgsProduct({{0, 1}, {0, 1}, {8, 10}, {0, 2}})
    ->Unit(benchmark::kMillisecond);

// Clanet's disk, the whole throw (t_max 3 s). Args: spin (rev/s), water law (0 newtonian,
// 1 planing, 2 nagahiro_hayakawa), restart (0 every_event, 1 every_crossing, 2 at_jumps, 3 never).
void BM_ClanetDisk(benchmark::State& state) {
  static const Stone disk = [] {
    const Mesh m = make_prism(0.025, 0.00275, 32);
    return make_stone(m, mass_properties_from_density(m, 2700), 0, "Clanet's disk");
  }();
  ThrowParameters p;
  p.speed_m_s = 3.5;
  p.path_angle_deg = 20;
  p.attack_angle_deg = 20;
  p.spin_rev_s = static_cast<double>(state.range(0));
  p.height_m = 0.03;
  Environment env;
  const WaterLaw laws[] = {WaterLaw::newtonian, WaterLaw::planing, WaterLaw::nagahiro_hayakawa};
  set_water_law(env, laws[state.range(1)]);
  ReferenceOptions o;
  o.t_max_s = 3;
  o.record_trajectory = false;
  o.restart = kRestarts[state.range(2)];
  const RigidState s0 = initial_state(disk, p);
  ThrowResult r;
  for (auto _ : state) {
    r = run_reference(disk, env, s0, o);
    benchmark::DoNotOptimize(r.final_state);
  }
  state.SetLabel(std::string(to_string(env.water_law)) + " " + r.solver);
  report(state, r);
}
BENCHMARK(BM_ClanetDisk)
    ->ArgNames({"spin", "law", "restart"})
    ->ArgsProduct({{0, 65}, {0, 1, 2}, {0, 1, 2, 3}})
    ->Unit(benchmark::kMillisecond);

// Arg: convention (0 physical, 1 paper). Semi-implicit Euler, 1 ms flight step, 0.1 ms contact step.
void BM_RealtimeThrow(benchmark::State& state) {
  const Environment env = environment(static_cast<int>(state.range(0)));
  RealtimeOptions o;
  o.scheme = Scheme::semi_implicit_euler;
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
