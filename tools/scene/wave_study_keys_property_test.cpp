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

// The refusal's message, or "" if the study file (with these overrides) is taken.
static std::string refusal(const std::vector<std::string>& overrides) {
  try {
    stoneskip::load_wave_study_file("cases/studies/waves_quick.toml", overrides);
    return "";
  } catch (const stoneskip::InputError& e) {
    return e.what();
  }
}

BOOST_AUTO_TEST_CASE(a_convergence_run_above_the_stability_limit_is_refused) {
  // Oracle: five_point's limit 1/√2 (model/README.md §2.2). both_sigma = 0.75 ran the space–time
  // sequence at σ ≈ 0.75 and reported a 2.8e6 m error as "order not established"; the time
  // sequence's 16 steps on the 64² grid of the quick study's 0.5 s problem are σ = 2.
  std::string m = refusal({"convergence.both_sigma=0.75"});
  BOOST_TEST(m.find("convergence.both_sigma") != std::string::npos, m);
  BOOST_TEST(m.find("five_point's stability limit 0.7071") != std::string::npos, m);
  m = refusal({"convergence.time_steps=[16, 32, 64, 128]"});
  BOOST_TEST(m.find("convergence.time_steps") != std::string::npos, m);
  BOOST_TEST(m.find("unstable") != std::string::npos, m);
  // Just inside every shipped stencil's limit (nine_point_isotropic's √3/2 is not the lowest):
  BOOST_TEST(refusal({"convergence.both_sigma=0.7"}) == "");
  // The problem alone can make the default sequence unstable: checked once every table is read
  // (t_end_s = 1.5 put the quick study's 64 steps on 64² at σ = 1.5, with no [convergence] change).
  std::ifstream in("cases/studies/waves_quick.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto from = text.find("[convergence]"), to = text.find("\n[", from + 1);
  BOOST_REQUIRE(from != std::string::npos && to != std::string::npos);
  text.erase(from, to + 1 - from);  // no [convergence]: its defaults
  stoneskip::ScratchDir dir("stoneskip_study_no_convergence");
  const auto file = dir.write("s.toml", text);
  try {
    stoneskip::load_wave_study_file(file.string(), {"problem.t_end_s=1.5"});
    BOOST_ERROR("an unstable default sequence was taken");
  } catch (const stoneskip::InputError& e) {
    m = e.what();
    BOOST_TEST(m.find("convergence.time_steps") != std::string::npos, m);
  }
}

BOOST_AUTO_TEST_CASE(a_refinement_sequence_out_of_order_or_repeated_is_refused) {
  // The fits and the GCI take the last entries as the finest: [128, 64, 32] fitted the coarsest.
  for (const char* o : {"convergence.both_grids=[128, 64, 32]", "convergence.both_grids=[32, 64, 64]",
                        "convergence.space_grids=[64, 32, 128]", "convergence.time_steps=[512, 256, 128, 64]"}) {
    const std::string m = refusal({o});
    BOOST_TEST(m.find("increase strictly") != std::string::npos, o << ": " << m);
  }
}

BOOST_AUTO_TEST_CASE(an_inconsistent_baseline_stencil_is_refused) {
  // Oracle: paper_eq11's weights sum to −1/3 (Lee & Baek 2013 Eq. 11 as printed), so the isotropy
  // and speed studies leave it out; as the baseline every ratio was "–".
  for (const char* key : {"isotropy", "speed"}) {
    const std::string m = refusal({std::string(key) + ".baseline_stencil=\"paper_eq11\""});
    BOOST_TEST(m.find(std::string(key) + ".baseline_stencil 'paper_eq11' is inconsistent") != std::string::npos, m);
  }
}

BOOST_AUTO_TEST_CASE(a_consistency_fit_outside_its_trusted_range_is_refused) {
  // Oracle: the fit's error bounds (verification/waves/stencil_consistency_test.cpp checks the
  // verdicts at both ends): max_kd 0.5 and 1e-3, and a tolerance below the fit's own error, are refused.
  for (const char* o : {"consistency.max_kd=0.5", "consistency.max_kd=0.001", "consistency.tolerance=1e-12"}) {
    const std::string m = refusal({o});
    BOOST_TEST(m.find(std::string(o).substr(0, std::string(o).find('='))) != std::string::npos, o << ": " << m);
  }
  BOOST_TEST(refusal({"consistency.max_kd=0.15", "consistency.tolerance=1e-9"}) == "");
}

BOOST_AUTO_TEST_SUITE_END()
