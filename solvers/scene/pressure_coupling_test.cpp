// The pressure coupling of model/README.md §2.4 in a running scene: the water receives the
// stone's vertical impulse, and the waves' energy budget closes.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "solvers/scene/coupled_scene.hpp"
#include "solvers/scene/seed_throw_scene.hpp"

using namespace stoneskip;

namespace {

// The paper's 8 m/s throw onto a 64 × 48 walled pond around its landing point (it lands at
// x ≈ 0.5 m and sinks in its first contact), without air, so that the stone's vertical momentum
// changes by its water impulse and its weight alone.
SceneOptions pressed_scene(Forcing forcing) {
  SceneOptions o = seed_throw_scene(64, 48, -0.1, -0.47, 0.3, Coupling::two_way, 0.5);
  o.environment.air_density_kg_m3 = 0;
  o.forcing = forcing;
  o.energy_budget = true;
  return o;
}

// Round-off of sums over ≈ 10⁴ stone steps and ≈ 30 water steps of terms of one size (relative).
constexpr double kImpulseRoundoff = 1e-9;
// The run ends at a located sinking: the final state is the step's cubic Hermite interpolant at
// the sink time, not the scheme's own update to it, so the momentum differs from the sum of the
// steps' impulses by the interpolant's error on the last partial step, O(h² |dF/dt| / m) — measured
// 1.7e-8 of the impulse here; bounded at 1e-7.
constexpr double kFinalStateInterpolation = 1e-7;
// The budget is an identity of the scheme (solvers/scene/wave_energy.hpp): what is left is the
// round-off of the transforms and of the leapfrog's levels (≈ 1e-13 of the levels, summed).
constexpr double kBudgetRoundoff = 1e-8;

}  // namespace

BOOST_AUTO_TEST_SUITE(pressure_coupling)

BOOST_AUTO_TEST_CASE(the_water_receives_the_stones_vertical_impulse) {
  // Oracle: the stone's momentum. The semi-implicit stepper changes v by Δt (F + m g)/m with F the
  // water force at the step's start, so m Δv_z + m g T is the stone's hydrodynamic vertical
  // impulse, computed without the coupling. The water must receive the same through its steps,
  // after the rasterisation (conservative) and the hat weights (which sum to one over each stone
  // step), to round-off; and the per-contact sums too. The steps' sum meets the momentum to the
  // interpolation of the final, located state (kFinalStateInterpolation).
  const SceneOptions o = pressed_scene(Forcing::pressure);
  const SceneSummary s = run_scene(o);
  const double m = o.stone.mass.mass_kg, g = o.environment.gravity_m_s2;
  const double stone = m * (s.stone.final_state.velocity_m_s.z() - o.initial.velocity_m_s.z()) + m * g * s.stone.end_time_s;
  BOOST_TEST_MESSAGE("stone " << stone << " N s by its momentum, " << s.stone_vertical_impulse_N_s << " by its steps; water "
                              << s.water_vertical_impulse_N_s << " N s");
  BOOST_TEST(stone > 0.01);  // a real contact: the 19 g stone's 1.4 m/s vertical speed and more
  BOOST_TEST(std::abs(s.stone_vertical_impulse_N_s - stone) <= kFinalStateInterpolation * stone);
  BOOST_TEST(std::abs(s.water_vertical_impulse_N_s - s.stone_vertical_impulse_N_s) <= kImpulseRoundoff * s.stone_vertical_impulse_N_s);
  BOOST_REQUIRE(!s.contact_impulses.empty());
  double sum = 0;
  for (const ContactImpulse& c : s.contact_impulses) {
    BOOST_TEST(std::abs(c.water_N_s - c.stone_N_s) <= kImpulseRoundoff * std::abs(c.stone_N_s) + 1e-15);
    sum += c.stone_N_s;
  }
  BOOST_TEST(std::abs(sum - s.stone_vertical_impulse_N_s) <= kImpulseRoundoff * s.stone_vertical_impulse_N_s);
}

BOOST_AUTO_TEST_CASE(the_balance_holds_under_every_scheme_and_with_air) {
  // Oracle: the stone's momentum, as above, under the default adaptive bs32 (the shipped scenes'
  // stepper, rtol 1e-8) and rk4, whose steps do not apply the force at the step's start: the water
  // must still receive what the stone gave up. Before each step's head was scaled to the stone's
  // own impulse, bs32 gave the water 0.4 % more than the stone lost on the shipped scene. With air
  // the momentum oracle needs the air's impulse, which the scene does not record: there the water
  // must meet the stone's own sum to round-off (the air is taken out of both alike).
  struct Variant {
    Scheme scheme;
    bool air;
  };
  for (const Variant v : {Variant{Scheme::bs32, false}, Variant{Scheme::rk4, false}, Variant{Scheme::bs32, true}}) {
    SceneOptions o = pressed_scene(Forcing::pressure);
    o.stone_steps.scheme = v.scheme;
    o.stone_steps.rtol = o.stone_steps.atol_m = 1e-8;
    if (v.air) o.environment.air_density_kg_m3 = 1.2;
    const SceneSummary s = run_scene(o);
    const double m = o.stone.mass.mass_kg, g = o.environment.gravity_m_s2;
    const double stone = m * (s.stone.final_state.velocity_m_s.z() - o.initial.velocity_m_s.z()) + m * g * s.stone.end_time_s;
    BOOST_TEST_MESSAGE(to_string(v.scheme) << (v.air ? " with air" : "") << ": stone " << stone << " N s by its momentum, "
                                           << s.stone_vertical_impulse_N_s << " by its steps; water " << s.water_vertical_impulse_N_s);
    BOOST_TEST(s.stone_vertical_impulse_N_s > 0.01);
    if (!v.air) BOOST_TEST(std::abs(s.stone_vertical_impulse_N_s - stone) <= kFinalStateInterpolation * stone);
    BOOST_TEST(std::abs(s.water_vertical_impulse_N_s - s.stone_vertical_impulse_N_s) <= kImpulseRoundoff * s.stone_vertical_impulse_N_s);
    for (const ContactImpulse& c : s.contact_impulses)
      BOOST_TEST(std::abs(c.water_N_s - c.stone_N_s) <= kImpulseRoundoff * std::abs(c.stone_N_s) + 1e-15);
  }
}

BOOST_AUTO_TEST_CASE(a_scene_ending_in_a_contact_holds_the_rest_of_the_stones_impulse_as_pending) {
  // Oracle: the hat weights give each stone piece's impulse wholly to the water steps whose hats
  // cover it, so at any end the pressings' water impulses are what the steps taken received plus
  // what the windows of the steps not taken hold (to round-off). The seed throw's first contact runs
  // from about 0.055 to 0.08 s: a scene cut at 0.07 s (6.3 water steps of 1/90 s) ends inside it,
  // and the pending part is then that of the last water step or two, a material share; cut at
  // 0.3 s, long after the stone sank, nothing is pending.
  for (const double duration : {0.07, 0.3}) {
    SceneOptions o = pressed_scene(Forcing::pressure);
    o.duration_s = duration;
    o.stone_steps.t_max_s = duration;
    const SceneSummary s = run_scene(o);
    BOOST_REQUIRE(!s.contact_impulses.empty());
    double contacts = 0;
    for (const ContactImpulse& c : s.contact_impulses) contacts += c.water_N_s;
    BOOST_TEST_MESSAGE("cut at " << duration << " s: contacts' water " << contacts << " N s, received " << s.water_vertical_impulse_N_s
                                 << ", pending " << s.water_impulse_pending_N_s);
    BOOST_TEST(std::abs(contacts - (s.water_vertical_impulse_N_s + s.water_impulse_pending_N_s)) <= kImpulseRoundoff * contacts);
    if (duration < 0.1)
      BOOST_TEST(s.water_impulse_pending_N_s > 0.01 * contacts);
    else
      BOOST_TEST(s.water_impulse_pending_N_s == 0.0);
  }
}

BOOST_AUTO_TEST_CASE(a_pond_narrower_than_the_pressing_stays_inside_its_storage_and_balances) {
  // A pond a few cells wide across the throw (the smoothed head reaches past both rims): the
  // forced step's work term once read heights at the head's unwrapped indices, outside the field's
  // storage (a crash on a 13-cell pond, garbage elsewhere), and a periodic pond's budget then did
  // not close (0.16 of the energy at 7 cells). Oracles: the stone's footprint lies on the pond
  // (|y| ≤ 3 cm), so the water must receive all of the stone's impulse to round-off: on a walled
  // pond what the smoothing spills past a wall is reflected back onto the grid
  // (fold_onto_walled_grid), on a periodic one wrapped; and the energy identity holds to round-off.
  for (Boundary b : {Boundary::reflecting, Boundary::fixed, Boundary::periodic})
    for (int ny : {4, 7, 13}) {
      SceneOptions o = seed_throw_scene(64, ny, -0.1, -0.01 * (ny - 1), 0.3, Coupling::two_way, 0.5);  // cells over |y| ≤ ny cm
      o.environment.air_density_kg_m3 = 0;
      o.forcing = Forcing::pressure;
      o.energy_budget = true;
      o.water->field.boundary = b;
      const SceneSummary s = run_scene(o);
      BOOST_TEST_MESSAGE(to_string(b) << " pond of " << ny << " cells: stone " << s.stone_vertical_impulse_N_s << " N s, water "
                                      << s.water_vertical_impulse_N_s << " N s, budget residual " << s.energy.residual());
      BOOST_TEST(s.stone_vertical_impulse_N_s > 0.01);
      BOOST_TEST(std::abs(s.water_vertical_impulse_N_s - s.stone_vertical_impulse_N_s) <= kImpulseRoundoff * s.stone_vertical_impulse_N_s);
      BOOST_REQUIRE(s.energy.measured);
      BOOST_TEST(s.energy.residual() <= kBudgetRoundoff);
    }
}

BOOST_AUTO_TEST_CASE(a_pressing_beyond_the_ponds_rim_gives_the_water_only_what_the_grid_keeps) {
  // Oracle: the field's rule (model/water/draught_patch.hpp): points beyond a walled pond's rim are
  // dropped, so each pressing's water impulse is the part of its head inside the grid, and the
  // pressings' sum is the water's total impulse (summed over the water steps) to round-off. The
  // same throw over a pond moved so that its rim (x = 0.44 m) cuts the contact's footprint, and over
  // one beyond the whole contact (x ≥ 1 m): there the water receives nothing at all.
  for (double origin_x_m : {0.44, 1.0}) {
    SceneOptions o = seed_throw_scene(64, 48, origin_x_m, -0.47, 0.3, Coupling::two_way, 0.5);
    o.environment.air_density_kg_m3 = 0;
    o.forcing = Forcing::pressure;
    const SceneSummary s = run_scene(o);
    BOOST_REQUIRE(!s.contact_impulses.empty());
    double water = 0;
    for (const ContactImpulse& c : s.contact_impulses) water += c.water_N_s;
    BOOST_TEST_MESSAGE("pond from x = " << origin_x_m << " m: stone " << s.stone_vertical_impulse_N_s << " N s, water "
                                        << s.water_vertical_impulse_N_s << " N s, pressings' water " << water << " N s");
    BOOST_TEST(s.stone_vertical_impulse_N_s > 0.01);
    BOOST_TEST(std::abs(water - s.water_vertical_impulse_N_s) <= kImpulseRoundoff * s.stone_vertical_impulse_N_s);
    if (origin_x_m < 1) {
      BOOST_TEST(s.water_vertical_impulse_N_s > 0.01 * s.stone_vertical_impulse_N_s);  // the rim cuts, not misses
      BOOST_TEST(s.water_vertical_impulse_N_s < 0.99 * s.stone_vertical_impulse_N_s);
    } else {
      BOOST_TEST(s.water_vertical_impulse_N_s == 0.0);
      BOOST_TEST(water == 0.0);
    }
  }
}

BOOST_AUTO_TEST_CASE(the_displacement_model_gives_the_water_far_less_than_the_stone) {
  // Oracle: model/README.md §2.4 — the draught's head ρ g b is millimetres against the law's
  // dynamic pressure of ≈ ½ ρ U² sin² (a head of decimetres): the water receives under a tenth of
  // the stone's impulse (37× less on the shipped 500 × 500 scene).
  const SceneSummary s = run_scene(pressed_scene(Forcing::displacement));
  BOOST_TEST(s.stone_vertical_impulse_N_s > 0.01);
  BOOST_TEST(s.water_vertical_impulse_N_s < 0.1 * s.stone_vertical_impulse_N_s);
}

BOOST_AUTO_TEST_CASE(the_waves_energy_budget_closes_for_both_forcings) {
  // Oracle: the discrete energy identity of solvers/scene/wave_energy.hpp, E_end − E_start =
  // W − D, exact for the damped, forced leapfrog on a walled pond; W > 0 (the stone pushes the
  // water down where it sinks) and D > 0 (μ = 0.2/s).
  for (Forcing f : {Forcing::pressure, Forcing::displacement}) {
    const SceneSummary s = run_scene(pressed_scene(f));
    const EnergyBudget& e = s.energy;
    BOOST_TEST_MESSAGE(to_string(f) << ": E " << e.start_J << " → " << e.end_J << " J, W " << e.pressure_work_J << " J, D "
                                    << e.damping_loss_J << " J, residual " << e.residual() << ", grid scale "
                                    << e.grid_scale_fraction);
    BOOST_REQUIRE(e.measured);
    BOOST_TEST(e.pressure_work_J > 0.0);
    BOOST_TEST(e.damping_loss_J > 0.0);
    BOOST_TEST(e.residual() <= kBudgetRoundoff);
  }
}

BOOST_AUTO_TEST_SUITE_END()
