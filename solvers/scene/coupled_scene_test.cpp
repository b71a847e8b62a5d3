// The coupled scene against the spec's closed forms and identities (model/README.md §2.4): still water and
// c = 0 equal to the still-water throw bit for bit; a stone held still on the water settles the
// field to the held-plate closed form; water volume unchanged by a stone skipping over a walled
// pond; active tiles at ε = 0 bit-identical to the full field; the water's step count and the
// frame count from the clocks' definitions; the coupled stability limit refused.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "model/stone/throw.hpp"
#include "solvers/scene/coupled_scene.hpp"
#include "solvers/scene/draught_window.hpp"
#include "solvers/scene/seed_throw_scene.hpp"

namespace stoneskip {
inline std::ostream& operator<<(std::ostream& o, Outcome x) { return o << to_string(x); }
}  // namespace stoneskip

using namespace stoneskip;

namespace {

Stone prism_stone(double R = 0.03, double h = 0.008) {
  const Mesh m = make_prism(R, h, 11);
  return make_stone(m, mass_properties_from_density(m, 2500), R, "prism");
}

// The paper's 8 m/s throw (physical convention: it lands at x ≈ 0.5 m and sinks in its first
// contact) onto a 64 × 48 pond of 2 cm cells around the landing point.
SceneOptions skipping_scene(Coupling coupling, double wave_speed_m_s = 0.5) {
  return seed_throw_scene(64, 48, -0.1, -0.47, 0.3, coupling, wave_speed_m_s);
}

void require_same_throw(const ThrowResult& a, const ThrowResult& b) {
  BOOST_REQUIRE(!b.contacts.empty());
  BOOST_REQUIRE_EQUAL(a.contacts.size(), b.contacts.size());
  for (std::size_t k = 0; k < a.contacts.size(); ++k) {
    BOOST_TEST(a.contacts[k].start_s == b.contacts[k].start_s);
    BOOST_TEST(a.contacts[k].end_s == b.contacts[k].end_s);
    BOOST_TEST((a.contacts[k].first_touch_m - b.contacts[k].first_touch_m).norm() == 0.0);
  }
  BOOST_TEST(a.outcome == b.outcome);
  BOOST_TEST(a.end_time_s == b.end_time_s);
  BOOST_TEST((a.final_state.position_m - b.final_state.position_m).norm() == 0.0);
  BOOST_TEST((a.final_state.velocity_m_s - b.final_state.velocity_m_s).norm() == 0.0);
  BOOST_TEST(a.stats.steps == b.stats.steps);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(coupled_scene_)

BOOST_AUTO_TEST_CASE(no_field_is_the_still_water_throw_bit_for_bit) {
  // Oracle: coupling = none builds no field, so the stone must take exactly the steps of
  // run_realtime on still water (η = 0).
  const SceneOptions o = skipping_scene(Coupling::none);
  const SceneSummary s = run_scene(o);
  RealtimeOptions steps = o.stone_steps;
  steps.t_max_s = o.end_s();
  require_same_throw(s.stone, run_realtime(o.stone, o.environment, o.initial, steps));
  BOOST_TEST(s.water_steps == 0);
  BOOST_TEST(s.frames == 27);
}

BOOST_AUTO_TEST_CASE(two_way_with_c_zero_is_one_way_on_still_water_bit_for_bit) {
  // Oracle: model/README.md §2.4 — with c = 0 the forced leapfrog adds 2c²Δt² L[z + b] = 0, so still water
  // stays exactly still while the stone presses on it: the two-way throw must equal the one-way
  // throw on still water, and that one the still-water throw, bit for bit. The draught must really
  // have been sampled under the stone, so the identity is not vacuous.
  SceneOptions displaced = skipping_scene(Coupling::two_way, 0.0);
  displaced.forcing = Forcing::displacement;
  const SceneSummary two = run_scene(displaced);
  const SceneSummary pressed = run_scene(skipping_scene(Coupling::two_way, 0.0));
  const SceneSummary one = run_scene(skipping_scene(Coupling::one_way, 0.0));
  const SceneSummary none = run_scene(skipping_scene(Coupling::none, 0.0));
  require_same_throw(two.stone, one.stone);
  require_same_throw(pressed.stone, one.stone);
  require_same_throw(one.stone, none.stone);
  BOOST_TEST(two.max_draught_volume_m3 > 1e-6);  // a good part of the 21 cm³ stone under water
  BOOST_TEST(two.draught_impulse_m3_s > 0.0);
  BOOST_TEST(pressed.water_vertical_impulse_N_s > 0.01);  // the stone pressed on the water
  BOOST_TEST(two.volume_end_m3 == 0.0);
  BOOST_TEST(pressed.volume_end_m3 == 0.0);
}

BOOST_AUTO_TEST_CASE(the_adaptive_stepper_on_a_flat_field_is_the_still_water_throw_bit_for_bit) {
  // Oracle: as above, with the default stepper (bs32, at the scenes' rtol = atol_m = 1e-8), whose
  // flight steps are bounded by the closing speed: on still water the sinking speed, on live water
  // |v| (the surface may rise to meet the stone). Given the field's surface, one-way on a flat pond
  // took the live bound (2.7 % more steps, the paper-convention seed scene 10 contacts against 14):
  // a field that nothing moves is still water, and must give its throw bit for bit.
  auto adaptive = [](Coupling coupling, double c) {
    SceneOptions o = skipping_scene(coupling, c);
    o.stone_steps = RealtimeOptions{};
    o.stone_steps.rtol = o.stone_steps.atol_m = 1e-8;
    return o;
  };
  const SceneSummary none = run_scene(adaptive(Coupling::none, 0.5));
  require_same_throw(run_scene(adaptive(Coupling::one_way, 0.5)).stone, none.stone);
  require_same_throw(run_scene(adaptive(Coupling::two_way, 0.0)).stone, none.stone);
  BOOST_TEST(none.stone.contacts.size() >= 1u);  // the stone came down to the water (the bounds differ there)
}

BOOST_AUTO_TEST_CASE(with_c_above_zero_the_stone_makes_waves_and_no_water) {
  // Oracle: model/README.md §2.4 (volume) — on a walled pond with a consistent stencil Σ L[z + b] = 0 and the
  // damped leapfrog keeps Σ z, so Σ z d² stays 0 to round-off (1e-12 of the displaced volume
  // Σ |z| d², as in model/coupling/two_way_test.cpp) while the stone, sinking on its first
  // contact, leaves waves; and the two-way throw is no longer the one-way one's bit for bit
  // (the stone meets its own depression: at least its sinking time differs).
  double displaced = 0;
  const SceneSummary two = run_scene(skipping_scene(Coupling::two_way), [&](const SceneFrame& f) {
    if (f.index != 27) return;
    for (int j = 0; j < f.field->ny(); ++j)
      for (int i = 0; i < f.field->nx(); ++i) displaced += std::abs(f.field->height(i, j)) * 0.02 * 0.02;
  });
  const SceneSummary one = run_scene(skipping_scene(Coupling::one_way));
  BOOST_TEST(displaced > 1e-7);
  BOOST_TEST(std::abs(two.volume_end_m3 - two.volume_start_m3) <= 1e-12 * displaced);
  BOOST_TEST(two.stone.end_time_s != one.stone.end_time_s);
  BOOST_TEST_MESSAGE("two-way: sank at " << two.stone.end_time_s << " s (one-way " << one.stone.end_time_s
                                         << " s); displaced " << displaced << " m³, volume change "
                                         << two.volume_end_m3 - two.volume_start_m3 << " m³");
}

BOOST_AUTO_TEST_CASE(a_stone_held_on_the_water_settles_the_field_to_the_closed_form) {
  // Oracle: model/README.md §2.4 (a plate held still) — with no gravity and no motion every face has
  // u = v·n = 0, so the physical convention's water force is exactly 0 and the stone stays where
  // it is: bottom at s = −1 cm on a periodic 1 m² field, K grid points under it. The field settles
  // to z = C off the plate and (C + s)/2 under it, C = −K s/(2N − K). μ = 12/s damps every mode at
  // least as e^{−μt/2} (μ²/4 < λ_min ≈ 4π²): after 8 s the transient is ~1e-2 m · e^{−48};
  // tolerance 1e-12 m, round-off of cm-sized values summed over the run. The scene samples b
  // K = 8 times per step, always against the same surface, so the window's mean is b itself.
  SceneOptions o;
  o.stone = prism_stone(0.15, 0.02);
  o.environment.gravity_m_s2 = 0;
  o.environment.air_density_kg_m3 = 0;
  const double s = -0.01;
  o.initial.position_m = Vec3(0.5 + 0.3 / 32, 0.5 + 0.1 / 32, s + 0.01);
  o.stone_steps.dt_s = 0.01;
  o.stone_steps.contact_dt_s = 0.01;
  o.coupling = Coupling::two_way;
  o.forcing = Forcing::displacement;
  SceneWater w;
  w.field.nx = w.field.ny = 32;
  w.field.cell_m = 1.0 / 32;
  w.field.wave_speed_m_s = 1;
  w.field.damping_per_s = 12;
  w.field.dt_s = 0.45 / 32;  // σ = 0.45, below the five-point coupled limit 0.5
  w.field.stencil = named_stencil("five_point");
  w.field.boundary = Boundary::periodic;
  o.water = w;
  o.frame_rate_hz = 10;
  o.duration_s = 8;
  double worst = -1, C = 0;
  int points = 0;
  const SceneSummary r = run_scene(o, [&](const SceneFrame& f) {
    if (f.index != 80) return;
    BOOST_TEST((f.stone.position_m - o.initial.position_m).norm() == 0.0);  // held by nothing but the model
    StoneDraught plate(o.stone.body_mesh);
    DraughtPatch p;
    points = plate.compute(f.stone, *f.field, f.placement, p).points;
    const double N = 32 * 32;
    C = -points * s / (2 * N - points);
    worst = 0;
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 32; ++i) {
        const int a = i - p.i0, c = j - p.j0;
        const bool under = a >= 0 && a < p.ni && c >= 0 && c < p.nj && p.at(a, c) > 0;
        worst = std::max(worst, std::abs(f.field->height(i, j) - (under ? 0.5 * (C + s) : C)));
      }
  });
  BOOST_TEST(r.stone.outcome == Outcome::time_limit);
  BOOST_TEST(points > 50);  // a 15 cm 11-gon over 3.1 cm cells: about 65 points
  BOOST_TEST(worst >= 0.0);
  BOOST_TEST(worst <= 1e-12, "largest departure " << worst << " m, C = " << C << " m, K = " << points);
}

BOOST_AUTO_TEST_CASE(active_tiles_at_zero_epsilon_give_the_same_scene_bit_for_bit) {
  // Oracle: model/README.md §2.6 — a tile whose cells and neighbours are all zero stays zero, so stepping only
  // active tiles with ε = 0 is the full field exactly: the same throw and the same surface at
  // every frame.
  SceneOptions full = skipping_scene(Coupling::two_way), tiled = full;
  tiled.water->field.mode = StepMode::active_tiles;
  tiled.water->field.tiles.tile_cells = 8;
  std::vector<std::vector<double>> a, b;
  auto keep = [](std::vector<std::vector<double>>& out) {
    return [&out](const SceneFrame& f) {
      out.emplace_back();
      f.field->heights(out.back());
    };
  };
  const SceneSummary rf = run_scene(full, keep(a)), rt = run_scene(tiled, keep(b));
  require_same_throw(rt.stone, rf.stone);
  BOOST_REQUIRE_EQUAL(a.size(), b.size());
  bool same = true;
  for (std::size_t k = 0; k < a.size(); ++k) same = same && a[k] == b[k];
  BOOST_TEST(same);
  BOOST_TEST(rt.tiles.fraction() < 1.0);  // tiles really were skipped
}

BOOST_AUTO_TEST_CASE(water_steps_and_frames_follow_from_the_clocks) {
  // Oracle: the loop's definitions — with the displacement forcing level n is seen on
  // [t_n − Δt/2, t_n + Δt/2), so by the end T = N/rate the field has taken ⌊T/Δt + ½⌋ steps;
  // with the pressure forcing on [t_n, t_n+1) (step n needs the hat up to t_n+1): ⌊T/Δt⌋;
  // N = ⌊duration · rate⌋ frames, frame k ending at k/rate; every frame's parts add up to its
  // wall time (the stone's is the remainder, never negative). Water Δt = 7 ms against 1/90 s
  // frames, so steps and frames do not line up.
  SceneOptions pressed = skipping_scene(Coupling::two_way);
  pressed.water->field.dt_s = 0.007;
  pressed.duration_s = 0.25;
  BOOST_TEST(run_scene(pressed).water_steps == static_cast<long>(std::floor(22.0 / 90 / 0.007)));
  SceneOptions o = pressed;
  o.forcing = Forcing::displacement;
  const SceneSummary s = run_scene(o);
  BOOST_TEST(s.frames == 22);
  BOOST_TEST(s.water_steps == static_cast<long>(std::floor(22.0 / 90 / 0.007 + 0.5)));
  long steps = 0;
  for (std::size_t k = 0; k < s.frame_costs.size(); ++k) {
    const FrameCost& f = s.frame_costs[k];
    BOOST_TEST(f.t_s == (k + 1) / 90.0);
    steps += f.water_steps;
    BOOST_TEST(f.stone_wall_s + f.draught_wall_s + f.water_wall_s + f.recording_wall_s <= f.wall_s * (1 + 1e-12) + 1e-12);
  }
  BOOST_TEST(steps == s.water_steps);
}

BOOST_AUTO_TEST_CASE(a_two_way_scene_above_the_coupled_limit_is_refused) {
  // Oracle: model/README.md §2.4 — the coupled limit is the free limit / √2 (√3/2 / √2 = 0.612 for the
  // isotropic 9-point stencil): σ = 0.65 is refused for two-way coupling, with the limit named,
  // and accepted for one-way coupling (below the free limit 0.866).
  SceneOptions o = skipping_scene(Coupling::two_way, 1.0);
  o.water->field.dt_s = 0.65 * 0.02;
  std::string why;
  BOOST_TEST(!o.valid(&why));
  BOOST_TEST(why.find("coupled stability limit 0.6124") != std::string::npos, why);
  o.coupling = Coupling::one_way;
  BOOST_TEST(o.valid(&why));
  BOOST_CHECK_THROW(run_scene(skipping_scene(Coupling::two_way, 2.0)), std::invalid_argument);  // σ = 1.1
}

BOOST_AUTO_TEST_CASE(the_draught_window_sums_weighted_samples_wrapping_or_clipping_at_the_edge) {
  // Oracle: hand sums. Two samples of weights ¼ and ¾ over overlapping boxes, one crossing the
  // seam of a periodic 8 × 8 grid (wraps to the other side) and the edge of a walled one (clipped).
  DraughtPatch p;
  p.reset(6, 3, 3, 1);  // points (6,3), (7,3), (8,3) → (0,3) when periodic
  p.at(0, 0) = 1;
  p.at(1, 0) = 2;
  p.at(2, 0) = 4;
  DraughtPatch q;
  q.reset(7, 3, 1, 1);
  q.at(0, 0) = 8;
  for (bool periodic : {true, false}) {
    DraughtWindow w(8, 8, periodic);
    w.add(p, 0.25);
    w.add(q, 0.75);
    DraughtPatch out;
    w.take(out);
    BOOST_TEST(w.empty());
    auto b = [&](int i, int j) {
      const int a = i - out.i0, c = j - out.j0;
      return a >= 0 && a < out.ni && c >= 0 && c < out.nj ? out.at(a, c) : 0.0;
    };
    BOOST_TEST(b(6, 3) == 0.25);
    BOOST_TEST(b(7, 3) == 0.5 + 6.0);
    BOOST_TEST(b(0, 3) == (periodic ? 1.0 : 0.0));
    BOOST_TEST(out.volume_m3(1.0) == (periodic ? 7.75 : 6.75));
    w.take(out);
    BOOST_TEST(out.empty());
  }
}

BOOST_AUTO_TEST_SUITE_END()
