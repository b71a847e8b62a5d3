// Cost of the real-time stone model: one step in contact (the 44-triangle stone half in the
// water: clipping, forces, torques) and one whole throw (the shipped 8 m/s case, both
// conventions). Run: build/solvers/stoneskip_realtime_bench
#include <benchmark/benchmark.h>

#include "model/stone/throw.hpp"
#include "solvers/realtime/stone_stepper.hpp"

using namespace stoneskip;

namespace {

Stone paper_stone() {
  const Mesh m = make_prism(0.03, 0.008, 11);  // the paper's 44 triangles
  return make_stone(m, mass_properties_from_density(m, 2500), 0.03, "prism");
}

const ThrowParameters kThrow{8.0, 10.0, 10.0, 10.0, 0.1, 0.0};

void BM_StepInContact(benchmark::State& state) {
  const Stone s = paper_stone();
  Environment env;
  RigidState st = initial_state(s, kThrow);
  st.position_m.z() = 0.0;  // half the stone under water
  const Scheme scheme = static_cast<Scheme>(state.range(0));
  for (auto _ : state) {
    RigidState next = realtime_step(s, env, st, 1e-5, scheme);
    benchmark::DoNotOptimize(next);
  }
  state.SetLabel(to_string(scheme));
}
BENCHMARK(BM_StepInContact)->Arg(0)->Arg(1)->Arg(2);

void BM_StepInFlight(benchmark::State& state) {
  const Stone s = paper_stone();
  Environment env;
  const RigidState st = initial_state(s, kThrow);  // 0.1 m above the water
  for (auto _ : state) {
    RigidState next = realtime_step(s, env, st, 1e-3, Scheme::semi_implicit_euler);
    benchmark::DoNotOptimize(next);
  }
}
BENCHMARK(BM_StepInFlight);

void BM_WholeThrow(benchmark::State& state) {
  const Stone s = paper_stone();
  Environment env;
  env.convention = state.range(0) ? Convention::paper : Convention::physical;
  RealtimeOptions o;
  o.dt_s = 1e-3;
  o.contact_dt_s = 1e-5;
  o.t_max_s = 10.0;
  o.record_trajectory = false;
  const RigidState s0 = initial_state(s, kThrow);
  long steps = 0;
  for (auto _ : state) {
    const ThrowResult r = run_realtime(s, env, s0, o);
    steps = r.stats.steps;
    benchmark::DoNotOptimize(r.bounces);
  }
  state.counters["steps"] = static_cast<double>(steps);
  state.SetLabel(env.convention == Convention::paper ? "paper convention (7 bounces, 10 s)" : "physical convention (sinks at 0.07 s)");
}
BENCHMARK(BM_WholeThrow)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
