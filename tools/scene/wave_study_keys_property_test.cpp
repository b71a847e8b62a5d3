// Property: every key of the shipped waves study file refuses a value no key can take,
// in one line naming it. Oracle: cases/README.md, "Study files" (tools/scene/study_keys_property.hpp).
#include "tools/scene/wave_study_file.hpp"
#include "tools/scene/study_keys_property.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/scratch_dir.hpp"

#include <fstream>
#include <iterator>
#include <string>

BOOST_AUTO_TEST_SUITE(documented_study_keys)

BOOST_AUTO_TEST_CASE(every_waves_study_key_refuses_a_value_no_key_can_take) {
  const std::string file = "cases/studies/waves.toml";
  const int checked = stoneskip::test::check_study_keys(
      file, [&](const std::vector<std::string>& set) { stoneskip::load_wave_study_file(file, set); });
  BOOST_TEST(checked >= 90);
}

BOOST_AUTO_TEST_CASE(a_refinement_study_of_an_impulse_is_refused) {
  // Oracle: the problem is refined, and an impulse (one cell's height at every spacing) has no
  // continuum limit: its volume shrinks as d². Run, the study called every stencil, paper_eq11
  // included, "converges" at order ≈ 1 on an absolute error that fell with the solution (relative
  // error ≈ 97 %). A Gaussian, which has one, is taken.
  const std::string file = "cases/studies/waves_quick.toml";
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string gaussian = "[problem.initial]\nkind = \"gaussian\"\namplitude_m = 0.01\nwidth_m = 0.1\n";
  BOOST_REQUIRE(text.find(gaussian) != std::string::npos);
  text.replace(text.find(gaussian), gaussian.size(), "[problem.initial]\nkind = \"impulse\"\namplitude_m = 0.01\n");
  stoneskip::ScratchDir dir("stoneskip_impulse_study");
  const std::string impulse_file = (dir.dir / "impulse.toml").string();
  std::ofstream(impulse_file) << text;
  try {
    stoneskip::load_wave_study_file(impulse_file, {});
    BOOST_ERROR("an impulse was taken");
  } catch (const stoneskip::InputError& e) {
    const std::string m = e.what();
    BOOST_TEST(m.find("problem.initial.kind") != std::string::npos, m);
    BOOST_TEST(m.find("no continuum limit") != std::string::npos, m);
  }
  BOOST_CHECK_NO_THROW(stoneskip::load_wave_study_file(file, {"problem.initial.kind=\"gaussian\""}));
}

BOOST_AUTO_TEST_CASE(a_study_past_the_cell_update_limit_is_refused_before_it_starts) {
  // Oracle: the limit `stoneskip wave` keeps (kMaxCellUpdates = 5e10). 4096² cells × 1e7 steps ×
  // 4 stencils is 6.7e14 updates (about two years here); the study once started at once.
  try {
    stoneskip::load_wave_study_file("cases/studies/waves_quick.toml",
                                    {"convergence.time_grid=4096", "convergence.time_steps=[64, 128, 10000000]"});
    BOOST_ERROR("the study was taken");
  } catch (const stoneskip::InputError& e) {
    const std::string m = e.what();
    BOOST_TEST(m.find("convergence.time_steps") != std::string::npos, m);
    BOOST_TEST(m.find("6.71e+14 cell updates") != std::string::npos, m);
  }
}

BOOST_AUTO_TEST_CASE(a_study_problem_whose_periodic_sum_stands_too_high_is_refused_naming_the_width) {
  // Oracle: model/water/disturbance.hpp, A π w² / L² for a wide Gaussian: 0.01 m × π × (1e6 m)² on
  // the study's domain is far above the 1000 m amplitude_m may reach (its 3 × 3 images made 9A).
  const std::string file = "cases/studies/waves_quick.toml";
  try {
    stoneskip::load_wave_study_file(file, {"problem.initial.width_m=1.0e6"});
    BOOST_ERROR("a surface of 1e10 m was taken");
  } catch (const stoneskip::InputError& e) {
    const std::string m = e.what();
    BOOST_TEST(m.find("problem.initial.width_m") != std::string::npos, m);
    BOOST_TEST(m.find("sums with its periodic images") != std::string::npos, m);
  }
}

BOOST_AUTO_TEST_SUITE_END()
