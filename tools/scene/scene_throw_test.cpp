// A stone on a live water surface ([water] in a stone case). Oracles: still water (a flat field
// must give exactly the still-water throw), the closed-form fall onto a frozen crest, and the
// definition of a contact (model/README.md §1.8) on the swell scene, where the water moves under the stone.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tools/io/input_error.hpp"
#include "tools/scene/scene_throw.hpp"

using namespace stoneskip;

namespace {

const char* kDrop = R"([stone]
shape = "prism"
radius_m = 0.03
thickness_m = 0.008
segments = 11
density_kg_m3 = 2500.0
[environment]
air_density_kg_m3 = 0.0
[throw]
speed_m_s = 0.0
path_angle_deg = 0.0
attack_angle_deg = 0.0
height_m = 0.2
[solver]
scheme = "rk4"
dt_s = 1.0e-3
contact_dt_s = 1.0e-5
t_max_s = 0.25
[water]
stencil = "five_point"
nx = 100
ny = 100
cell_m = 0.02
wave_speed_m_s = WAVE_SPEED
boundary = "reflecting"
dt_s = 1.0e-3
origin_x_m = -1.0
origin_y_m = -1.0
[water.initial]
kind = "gaussian"
amplitude_m = AMPLITUDE
width_m = 0.5
x_m = 1.0
y_m = 1.0
)";

StoneCase drop_case(const std::string& amplitude, const std::string& wave_speed) {
  std::string text = kDrop;
  text.replace(text.find("AMPLITUDE"), 9, amplitude);
  text.replace(text.find("WAVE_SPEED"), 10, wave_speed);
  return stone_case_from_document(parse_toml_text(text, "drop.toml"));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(scene_throw)

BOOST_AUTO_TEST_CASE(a_flat_live_surface_gives_exactly_the_still_water_throw) {
  // Oracle: still water. A height field at rest with zero amplitude stays exactly zero, so the
  // depths η − z are the same numbers as with η = 0: the throws must agree bit for bit.
  StoneCase live = drop_case("0.0", "1.0");
  StoneCase still = live;
  still.water.reset();
  const ThrowResult a = run_scene_realtime(live).result, b = run_scene_realtime(still).result;
  BOOST_REQUIRE(!b.contacts.empty());
  BOOST_TEST(a.contacts.size() == b.contacts.size());
  BOOST_TEST(a.contacts[0].start_s == b.contacts[0].start_s);
  BOOST_TEST(a.end_time_s == b.end_time_s);
  BOOST_TEST((a.final_state.position_m - b.final_state.position_m).norm() == 0.0);
}

BOOST_AUTO_TEST_CASE(a_plate_falling_onto_a_frozen_crest_touches_it_at_the_closed_form_time) {
  // Oracle: free fall onto the crest of a Gaussian bump of amplitude A placed under the plate's
  // bottom centre vertex (a grid point, where bilinear interpolation is exact). The wave speed is
  // tiny (1e-4 m/s), so the crest moves by < 1e-9 m during the fall: first touch at
  // t = √(2 (z0 − h/2 − η_crest)/g), η_crest the field's initial height at the crest node (A
  // plus the 4e-7 A of the bump's periodic images). rk4 integrates the fall exactly; the linear
  // location of the crossing inside a 1e-5 s step errs by ~g dt²/(8 v) < 1e-10 s: tolerance
  // 1e-9 s. The first-touch point is the deepest vertex at the end of that step: within v dt.
  const double z0 = 0.2, h = 0.008, g = 9.81;
  const StoneCase c = drop_case("0.05", "1.0e-4");
  std::vector<double> z;
  sample_disturbance(*c.water->initial, 100, 100, 0.02, z);
  const double crest = z[50 * 100 + 50];
  BOOST_TEST(std::abs(crest - 0.05) <= 1e-6);
  const SceneThrow r = run_scene_realtime(c);
  BOOST_REQUIRE(!r.result.contacts.empty());
  const double exact = std::sqrt(2 * (z0 - h / 2 - crest) / g);
  BOOST_TEST(std::abs(r.result.contacts[0].start_s - exact) <= 1e-9);
  const double v = g * exact;
  BOOST_TEST(std::abs(r.result.contacts[0].first_touch_m.z() - crest) <= v * 1e-5);
  BOOST_TEST(r.water_steps > 100);  // the field really was stepped along
  // Still water would touch later, at √(2 (z0 − h/2)/g): the crest matters.
  BOOST_TEST(r.result.contacts[0].start_s < std::sqrt(2 * (z0 - h / 2) / g) - 0.01);
}

BOOST_AUTO_TEST_CASE(water_keys_are_checked_like_any_other) {
  // Oracle: the strict-key rule — a misspelt key inside [water] is named.
  std::string text = kDrop;
  text.replace(text.find("AMPLITUDE"), 9, "0.01");
  text.replace(text.find("WAVE_SPEED"), 10, "1.0");
  text.replace(text.find("origin_y_m"), 10, "origin_z_m");
  BOOST_CHECK_EXCEPTION(stone_case_from_document(parse_toml_text(text, "drop.toml")), InputError,
                        [](const InputError& e) { return std::string(e.what()).find("water.origin_z_m") != std::string::npos; });
}

BOOST_AUTO_TEST_CASE(on_the_swell_every_wet_moment_lies_inside_a_logged_contact) {
  // Oracle: model/README.md §1.8 — a contact is a maximal interval during which some S_i > 0, so every
  // sample with a wetted area lies inside a logged contact, and a stone that sinks ends a logged
  // contact at the time it sank. Regression: `stoneskip run cases/scenes/swell_8ms.toml
  // --set environment.convention=paper --set throw.height_m=0.121 --set throw.spin_rev_s=20`
  // printed 0 bounces, "sank at 0.08279 s" and no contacts although the stone is wet from
  // 0.0725 s: the water, not the stone, had crossed. Every step is sampled (output_dt_s = 0); the
  // 500 × 500 field is stepped for 83 ms (about 0.2 s of CPU).
  const StoneCase c = load_stone_case("cases/scenes/swell_8ms.toml",
                                      {"environment.convention=paper", "throw.height_m=0.121",
                                       "throw.spin_rev_s=20", "solver.output_dt_s=0.0"});
  const ThrowResult r = run_scene_realtime(c).result;
  BOOST_TEST_INFO(to_string(r.outcome) << " at " << r.end_time_s << " s, " << r.contacts.size() << " contacts");
  BOOST_REQUIRE(!r.contacts.empty());
  int wet_samples = 0;
  for (const auto& p : r.trajectory) {
    if (p.wetted_area_m2 <= 0) continue;
    ++wet_samples;
    bool inside = false;
    for (const auto& k : r.contacts) inside = inside || (p.t_s >= k.start_s && p.t_s <= k.end_s);
    BOOST_TEST(inside, "wet sample at t = " << p.t_s << " s (area " << p.wetted_area_m2 << " m²) outside every contact");
  }
  BOOST_TEST(wet_samples > 0);
  if (r.outcome == Outcome::sank) {
    BOOST_TEST(!r.contacts.back().bounced);
    BOOST_TEST(r.contacts.back().end_s == r.end_time_s);
  }
  // Contacts are disjoint and ordered: each starts after the previous one ended.
  for (std::size_t k = 0; k < r.contacts.size(); ++k) {
    BOOST_TEST(r.contacts[k].end_s >= r.contacts[k].start_s);
    if (k > 0) BOOST_TEST(r.contacts[k].start_s >= r.contacts[k - 1].end_s);
  }
}

BOOST_AUTO_TEST_SUITE_END()
