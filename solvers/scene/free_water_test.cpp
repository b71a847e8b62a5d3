// The scene's free steps (SceneOptions::free_water) against the scene stepped one step at a time:
// HeightField::advance(n) is n calls of step() bit for bit, and a free step books nothing but its
// count, so every way of taking them must give the same field, frames and numbers exactly.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

#include "solvers/scene/coupled_scene.hpp"
#include "solvers/scene/seed_throw_scene.hpp"

using namespace stoneskip;

namespace {

// The paper's 8 m/s throw (it lands at x ≈ 0.5 m and sinks in its first contact) on a 300 × 300
// walled pond of 2 cm cells, large enough that advance(n ≥ 2) takes the temporal-blocked
// wavefront; frames at 30 Hz against water steps of 1/90 s, so three free steps per frame in the
// ring phase. μ = 0 with the energy budget on: the final energy E^{n+½} is a fingerprint of the
// final two levels (a scene without a recorder shows nothing else of them), and no step has to
// measure a damping loss.
SceneOptions ring_scene(Coupling coupling, Forcing forcing, FreeWater free_water) {
  SceneOptions o = seed_throw_scene(300, 300, -0.1, -3.0, 1.0, coupling, 0.5);
  o.water->field.damping_per_s = 0;
  o.frame_rate_hz = 30;
  o.forcing = forcing;
  o.energy_budget = coupling == Coupling::two_way;
  o.free_water = free_water;
  return o;
}

// The budget is an identity of the scheme (solvers/scene/wave_energy.hpp), left with the round-off
// of the transforms and the levels; as in pressure_coupling_test.cpp.
constexpr double kBudgetRoundoff = 1e-8;

struct Run {
  SceneSummary summary;
  std::vector<std::vector<double>> frames;  // the field at every frame (with a recorder)
};

Run run(const SceneOptions& o, bool record) {
  Run r;
  if (!record) {
    r.summary = run_scene(o);
    return r;
  }
  r.summary = run_scene(o, [&](const SceneFrame& f) {
    r.frames.emplace_back();
    f.field->heights(r.frames.back());
  });
  return r;
}

// Everything a scene reports but its clocks.
void require_same_scene(const SceneSummary& a, const SceneSummary& b) {
  BOOST_TEST(a.stone.end_time_s == b.stone.end_time_s);
  BOOST_TEST(a.stone.stats.steps == b.stone.stats.steps);
  BOOST_TEST(a.frames == b.frames);
  BOOST_TEST(a.water_steps == b.water_steps);
  BOOST_TEST(a.draught_samples == b.draught_samples);
  BOOST_TEST(a.draught_impulse_m3_s == b.draught_impulse_m3_s);
  BOOST_TEST(a.stone_vertical_impulse_N_s == b.stone_vertical_impulse_N_s);
  BOOST_TEST(a.water_vertical_impulse_N_s == b.water_vertical_impulse_N_s);
  BOOST_TEST(a.volume_end_m3 == b.volume_end_m3);
  BOOST_TEST(a.energy.measured == b.energy.measured);
  BOOST_TEST(a.energy.start_J == b.energy.start_J);
  BOOST_TEST(a.energy.end_J == b.energy.end_J);
  BOOST_TEST(a.energy.pressure_work_J == b.energy.pressure_work_J);
  BOOST_TEST(a.energy.damping_loss_J == b.energy.damping_loss_J);
  BOOST_TEST(a.energy.grid_scale_fraction == b.energy.grid_scale_fraction);
  BOOST_TEST(a.tiles.steps == b.tiles.steps);
  BOOST_TEST(a.tiles.tile_steps == b.tiles.tile_steps);
  BOOST_REQUIRE_EQUAL(a.frame_costs.size(), b.frame_costs.size());
  for (std::size_t k = 0; k < a.frame_costs.size(); ++k) {
    BOOST_TEST(a.frame_costs[k].t_s == b.frame_costs[k].t_s);
    BOOST_TEST(a.frame_costs[k].water_steps == b.frame_costs[k].water_steps);
    BOOST_TEST(a.frame_costs[k].stone_steps == b.frame_costs[k].stone_steps);
    BOOST_TEST(a.frame_costs[k].draught_samples == b.frame_costs[k].draught_samples);
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(free_water)

BOOST_AUTO_TEST_CASE(the_ring_is_blocked_where_the_test_looks_for_it) {
  // Oracle: HeightField::advance_is_blocked — the tests below compare the wavefront with single
  // steps only if the scene's field takes it; and the ring phase has steps to take together.
  const SceneOptions o = ring_scene(Coupling::two_way, Forcing::pressure, FreeWater::to_the_next_frame);
  BOOST_TEST(HeightField(o.water->field).advance_is_blocked());
  const SceneSummary s = run_scene(o);
  BOOST_TEST(s.stone.end_time_s < 0.5);  // it sinks: at least half the scene is ring
  BOOST_TEST(s.frame_costs.back().water_steps == 3);
}

BOOST_AUTO_TEST_CASE(free_steps_taken_together_give_the_step_by_step_scene_bit_for_bit) {
  // Oracle: the scene stepped one step at a time (FreeWater::one_at_a_time). With a recorder the
  // field at every frame must be equal bit for bit; without one (to_the_next_look runs the ring in
  // one advance) every number of the summary, the final energy included, and each frame's counts.
  struct Kind {
    Coupling coupling;
    Forcing forcing;
  };
  for (const Kind k : {Kind{Coupling::two_way, Forcing::pressure}, Kind{Coupling::two_way, Forcing::displacement},
                       Kind{Coupling::one_way, Forcing::pressure}}) {
    BOOST_TEST_CONTEXT(to_string(k.coupling) << ", " << to_string(k.forcing)) {
      const Run one = run(ring_scene(k.coupling, k.forcing, FreeWater::one_at_a_time), true);
      const Run frame = run(ring_scene(k.coupling, k.forcing, FreeWater::to_the_next_frame), true);
      BOOST_REQUIRE_EQUAL(one.frames.size(), 30u);
      BOOST_REQUIRE_EQUAL(frame.frames.size(), one.frames.size());
      bool same = true;
      for (std::size_t f = 0; f < one.frames.size(); ++f) same = same && one.frames[f] == frame.frames[f];
      BOOST_TEST(same);
      require_same_scene(one.summary, frame.summary);
      for (bool record : {false, true}) {
        const Run look = run(ring_scene(k.coupling, k.forcing, FreeWater::to_the_next_look), record);
        require_same_scene(one.summary, look.summary);
        if (record) BOOST_TEST(look.frames == one.frames);
      }
      const Run unrecorded = run(ring_scene(k.coupling, k.forcing, FreeWater::one_at_a_time), false);
      require_same_scene(one.summary, unrecorded.summary);
      if (k.coupling == Coupling::two_way) {
        BOOST_TEST(one.summary.energy.measured);
        BOOST_TEST(one.summary.energy.pressure_work_J > 0.0);  // the stone made the ring
        BOOST_TEST(frame.summary.energy.residual() <= kBudgetRoundoff);
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(frames_that_owe_their_steps_share_the_advance_by_their_steps) {
  // Oracle: the booking of FreeWater::to_the_next_look without a recorder — every frame keeps its
  // own water steps (as counted one at a time), the frames' parts add up to each one's wall time,
  // and the totals are the sums over the frames (to round-off of the shares).
  const SceneSummary s = run_scene(ring_scene(Coupling::two_way, Forcing::pressure, FreeWater::to_the_next_look));
  long steps = 0;
  double wall = 0, water = 0;
  for (const FrameCost& f : s.frame_costs) {
    steps += f.water_steps;
    wall += f.wall_s;
    water += f.water_wall_s;
    BOOST_TEST(f.stone_wall_s + f.draught_wall_s + f.water_wall_s + f.recording_wall_s <= f.wall_s * (1 + 1e-12) + 1e-12);
  }
  BOOST_TEST(steps == s.water_steps);
  BOOST_TEST(std::abs(wall - s.wall_s) <= 1e-12 * s.wall_s);
  BOOST_TEST(std::abs(water - s.water_wall_s) <= 1e-12 * s.wall_s);
  BOOST_TEST(s.frame_costs.back().water_wall_s > 0.0);  // the ring's last frame got its share
}

BOOST_AUTO_TEST_CASE(a_damped_scene_that_measures_its_budget_steps_one_at_a_time) {
  // Oracle: the budget's Dₙ is a quadratic form of each step's levels (solvers/scene/wave_energy.hpp),
  // so with energy_budget on a damped field every step is taken and measured alone: the budget
  // closes to round-off with D > 0, and the scene is the one-at-a-time scene bit for bit.
  SceneOptions o = ring_scene(Coupling::two_way, Forcing::pressure, FreeWater::to_the_next_look);
  o.water->field.damping_per_s = 0.2;
  SceneOptions reference = o;
  reference.free_water = FreeWater::one_at_a_time;
  const SceneSummary s = run_scene(o), r = run_scene(reference);
  require_same_scene(r, s);
  BOOST_TEST(s.energy.damping_loss_J > 0.0);
  BOOST_TEST(s.energy.residual() <= kBudgetRoundoff);
}

BOOST_AUTO_TEST_CASE(free_water_names_round_trip) {
  // Oracle: parse_free_water inverts to_string; an unknown name is refused.
  for (FreeWater f : {FreeWater::one_at_a_time, FreeWater::to_the_next_frame, FreeWater::to_the_next_look}) {
    FreeWater back = FreeWater::one_at_a_time;
    BOOST_TEST(parse_free_water(to_string(f), back));
    BOOST_TEST(static_cast<int>(back) == static_cast<int>(f));
  }
  FreeWater x;
  BOOST_TEST(!parse_free_water("blocked", x));
}

BOOST_AUTO_TEST_SUITE_END()
