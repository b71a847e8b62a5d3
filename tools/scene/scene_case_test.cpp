// The scene keys of a stone case ([water], [water.initial], [scene]; tools/scene/scene_case.hpp).
// Oracles: the strict-key rule (a misspelt key or value is named), the coupled stability limit of
// model/README.md §2.4 (refused at water.dt_s for two_way, accepted for one_way), and the defaults the
// README states.
#include <boost/test/unit_test.hpp>

#include "tools/io/input_error.hpp"
#include "tools/scene/scene_throw.hpp"

using namespace stoneskip;

namespace {

const char* kPond = R"([stone]
shape = "prism"
radius_m = 0.03
thickness_m = 0.008
segments = 11
density_kg_m3 = 2500.0
[throw]
speed_m_s = 8.0
path_angle_deg = 10.0
attack_angle_deg = 10.0
height_m = 0.1
[solver]
dt_s = 1.0e-3
contact_dt_s = 1.0e-5
t_max_s = 2.0
[water]
coupling = "two_way"
stencil = "nine_point_isotropic"
nx = 50
ny = 50
cell_m = 0.02
wave_speed_m_s = 1.0
dt_s = 0.0111111111111
origin_x_m = -0.1
origin_y_m = -0.5
)";

StoneCase pond(const std::vector<std::string>& sets, const std::string& extra = "") {
  return stone_case_from_document(parse_toml_text(std::string(kPond) + extra, "pond.toml", sets));
}

// A pond case with these overrides must be refused in one error naming `key` and saying `words`.
void refused_at(const std::string& key, const std::vector<std::string>& sets, const std::string& words) {
  try {
    pond(sets);
    BOOST_ERROR("no error for " << sets.back());
  } catch (const InputError& e) {
    const std::string m = e.what();
    BOOST_TEST(m.find(key) != std::string::npos, m);
    BOOST_TEST(m.find(words) != std::string::npos, m);
  }
}

bool names(const InputError& e, const std::string& key) { return std::string(e.what()).find(key) != std::string::npos; }

}  // namespace

BOOST_AUTO_TEST_SUITE(scene_case_)

BOOST_AUTO_TEST_CASE(defaults_are_the_documented_ones) {
  // Oracle: cases/README.md — still water without [water.initial], 8 samples per step, float64,
  // one thread, the full field, 90 frames per second, and a scene as long as the stone's t_max_s.
  const StoneCase c = pond({});
  BOOST_REQUIRE(c.water);
  BOOST_TEST(!c.water->initial);
  BOOST_TEST((c.water->coupling == Coupling::two_way));
  BOOST_TEST(c.water->draught_samples == 8);
  BOOST_TEST((c.water->field.precision == Precision::float64));
  BOOST_TEST(c.water->field.threads == 1);
  BOOST_TEST((c.water->field.mode == StepMode::full));
  BOOST_TEST(c.frames.frame_rate_hz == 90.0);
  BOOST_TEST((c.frames.free_water == FreeWater::to_the_next_frame));
  const SceneOptions o = scene_options(c, SceneEnd::at_duration);
  BOOST_TEST(o.frames() == 180);
  BOOST_TEST(o.water->initial_m.empty());
  BOOST_TEST((pond({"water.coupling=none"}).water->coupling == Coupling::none));
  BOOST_TEST(!scene_options(pond({"water.coupling=none"}), SceneEnd::at_duration).water);  // no field at all
}

BOOST_AUTO_TEST_CASE(scene_keys_are_read) {
  // Oracle: the values written in the file come back.
  const StoneCase c = pond({"water.precision=float32", "water.threads=2", "water.mode=active_tiles", "water.tile_cells=16",
                            "water.epsilon_m=1e-6", "water.forcing=displacement", "water.draught_samples=1"},
                           "[scene]\nframe_rate_hz = 60.0\nduration_s = 1.5\nfree_water = \"to_the_next_look\"\n");
  BOOST_TEST((c.water->field.precision == Precision::float32));
  BOOST_TEST(c.water->field.threads == 2);
  BOOST_TEST((c.water->field.mode == StepMode::active_tiles));
  BOOST_TEST(c.water->field.tiles.tile_cells == 16);
  BOOST_TEST(c.water->field.tiles.epsilon_m == 1e-6);
  BOOST_TEST(c.water->draught_samples == 1);
  BOOST_TEST(scene_options(c, SceneEnd::at_duration).frames() == 90);
  BOOST_TEST((scene_options(c, SceneEnd::at_duration).free_water == FreeWater::to_the_next_look));
  BOOST_TEST(c.resolved_settings().find("free_water = \"to_the_next_look\"") != std::string::npos);
  BOOST_TEST(c.resolved_settings().find("coupling = \"two_way\"") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_two_way_field_above_the_coupled_limit_is_refused_at_dt_s) {
  // Oracle: model/README.md §2.4 — σ = cΔt/d = 0.65 exceeds the isotropic stencil's coupled limit √6/4 =
  // 0.612 (but not its free limit 0.866): two_way is refused naming water.dt_s, one_way runs.
  BOOST_CHECK_EXCEPTION(pond({"water.dt_s=0.013"}), InputError, [](const InputError& e) {
    return names(e, "water.dt_s") && names(e, "coupled stability limit 0.6124");
  });
  BOOST_CHECK_NO_THROW(pond({"water.dt_s=0.013", "water.coupling=one_way"}));
}

BOOST_AUTO_TEST_CASE(bad_scene_values_are_named) {
  // Oracle: the strict-key rule: one line naming the key.
  auto fails_at = [](const std::vector<std::string>& sets, const std::string& extra, const std::string& key) {
    try {
      pond(sets, extra);
    } catch (const InputError& e) {
      BOOST_TEST(names(e, key), e.what());
      return;
    }
    BOOST_ERROR("no error for " << key);
  };
  fails_at({"water.coupling=two_ways"}, "", "water.coupling");
  fails_at({"water.precision=half"}, "", "water.precision");
  fails_at({"water.mode=sparse"}, "", "water.mode");
  fails_at({"water.threads=0"}, "", "water.threads");
  fails_at({"water.epsilon_m=-1.0"}, "", "water.epsilon_m");
  fails_at({"water.draught_samples=0"}, "", "water.draught_samples");
  fails_at({}, "[scene]\nframe_rate=90.0\n", "scene.frame_rate");
  fails_at({}, "[scene]\nduration_s = 0.001\n", "scene.duration_s");
  fails_at({}, "[scene]\nfree_water = \"blocked\"\n", "scene.free_water");
  fails_at({}, "[water.intial]\nkind = \"gaussian\"\n", "water.intial");
}

BOOST_AUTO_TEST_CASE(draught_samples_under_the_pressure_forcing_are_refused) {
  // The pressure forcing samples no draught: 1, 8 and 4096 samples gave bit-identical scenes, so
  // the key is refused there (naming it) rather than taken and ignored.
  try {
    pond({"water.draught_samples=4"});
    BOOST_ERROR("draught_samples was taken under the pressure forcing");
  } catch (const InputError& e) {
    const std::string m = e.what();
    BOOST_TEST(m.find("water.draught_samples") != std::string::npos, m);
    BOOST_TEST(m.find("forcing = \"displacement\"") != std::string::npos, m);
  }
  BOOST_TEST(pond({"water.forcing=displacement", "water.draught_samples=4"}).water->draught_samples == 4);
}

BOOST_AUTO_TEST_CASE(a_head_width_is_read_where_there_is_a_head_and_refused_where_not_or_too_wide) {
  // Oracle: solvers/scene/coupled_scene.hpp, pressure_smoothing_passes: a width up to 8 cells is
  // taken (0 by default: a fixed number of cells) and reaches the scene's options; above 8 cells
  // it is refused at its key with the widest it takes (8 × 2 cm = 0.16 m); without a head (one-way
  // or displacement forcing) it is refused rather than taken and ignored.
  BOOST_TEST(pond({}).water->head_width_m == 0.0);
  const StoneCase c = pond({"water.head_width_m=0.05"});
  BOOST_TEST(c.water->head_width_m == 0.05);
  BOOST_TEST(scene_options(c, SceneEnd::at_duration).head_width_m == 0.05);
  BOOST_TEST(pond({"water.head_width_m=0.16"}).water->head_width_m == 0.16);
  auto refused = [](const std::vector<std::string>& sets, const std::string& words) { refused_at("water.head_width_m", sets, words); };
  refused({"water.head_width_m=0.17"}, "take head_width_m <= 0.16");
  refused({"water.head_width_m=-0.01"}, "water.head_width_m");
  refused({"water.coupling=one_way", "water.head_width_m=0.05"}, "only with coupling = \"two_way\"");
  refused({"water.forcing=displacement", "water.head_width_m=0.05"}, "forcing = \"pressure\"");
}

BOOST_AUTO_TEST_CASE(the_level_in_time_is_read_where_there_is_water_and_refused_where_not_or_misspelt) {
  // Oracle: model/water/height_field_surface.hpp: held by default (the real-time loop's reading),
  // extrapolated when asked, and that reaches the scene's options; a value that is neither, or the
  // key on a case whose stone reads still water (coupling none), is refused at its key.
  BOOST_TEST((pond({}).water->level_in_time == LevelInTime::held));
  const StoneCase c = pond({"water.level_in_time=extrapolated"});
  BOOST_TEST((c.water->level_in_time == LevelInTime::extrapolated));
  BOOST_TEST((scene_options(c, SceneEnd::at_duration).level_in_time == LevelInTime::extrapolated));
  BOOST_TEST((pond({"water.coupling=one_way", "water.level_in_time=extrapolated"}).water->level_in_time == LevelInTime::extrapolated));
  auto refused = [](const std::vector<std::string>& sets, const std::string& words) { refused_at("water.level_in_time", sets, words); };
  refused({"water.level_in_time=extrapolate"}, "'extrapolate' is not one of held, extrapolated");
  refused({"water.coupling=none", "water.level_in_time=held"}, "with none the stone reads still water");
}

BOOST_AUTO_TEST_SUITE_END()
