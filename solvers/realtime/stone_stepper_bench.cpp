// Cost of the real-time stone model: one step in contact (the 44-triangle stone half in the
// water: clipping, forces, torques) and one whole throw (the shipped 8 m/s case, both
// conventions), the contact right-hand side on the states of a real contact under the default
// water model, and whole adaptive (bs32) throws of the bench sweep's kind.
// Run: build/solvers/stoneskip_realtime_bench
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
  o.scheme = Scheme::semi_implicit_euler;  // a fixed-step study (the default is bs32)
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

// The states of a whole bs32 throw that are in contact (every step recorded), under the default
// physical water model (planing, savitsky_wagner): what the sweep's right-hand sides see.
std::vector<RigidState> contact_states(const Stone& s, const Environment& env) {
  RealtimeOptions o;
  o.scheme = Scheme::bs32;
  o.rtol = o.atol_m = 1e-8;
  o.output_dt_s = 0;
  const ThrowParameters p{8.0, 10.0, 10.0, 20.0, 0.1, 0.0};
  const ThrowResult r = run_realtime(s, env, initial_state(s, p), o);
  std::vector<RigidState> out;
  for (const TrajectorySample& x : r.trajectory)
    if (x.wetted_area_m2 > 0) out.push_back(x.state);
  return out;
}

void BM_ContactRhsDefaultModel(benchmark::State& state) {
  const Stone s = paper_stone();
  Environment env;
  set_default_water_model(env);
  const std::vector<RigidState> states = contact_states(s, env);
  std::size_t k = 0;
  for (auto _ : state) {
    const StateDerivative d = rigid_body_rhs(s, env, states[k]);
    benchmark::DoNotOptimize(d);
    if (++k == states.size()) k = 0;
  }
  state.counters["states"] = static_cast<double>(states.size());
}
BENCHMARK(BM_ContactRhsDefaultModel);

// A whole bs32 throw (spin_rev_s, attack_angle_deg from the arguments) under the default model.
void BM_WholeThrowBs32(benchmark::State& state) {
  const Stone s = paper_stone();
  Environment env;
  set_default_water_model(env);
  RealtimeOptions o;
  o.scheme = Scheme::bs32;
  o.rtol = o.atol_m = 1e-8;
  o.record_trajectory = false;
  const ThrowParameters p{8.0, 10.0, static_cast<double>(state.range(1)), static_cast<double>(state.range(0)), 0.1, 0.0};
  const RigidState s0 = initial_state(s, p);
  long rhs = 0;
  for (auto _ : state) {
    const ThrowResult r = run_realtime(s, env, s0, o);
    rhs = r.stats.rhs_evaluations;
    benchmark::DoNotOptimize(r.bounces);
  }
  state.counters["rhs"] = static_cast<double>(rhs);
}
BENCHMARK(BM_WholeThrowBs32)->Args({20, 10})->Args({60, 25})->Unit(benchmark::kMillisecond);

}  // namespace
