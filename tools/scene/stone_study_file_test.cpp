// The keys of the stones study files (cases/README.md, "Study files") beyond the first ones: the water
// laws of the convergence and validation studies, "throw@law" in the work-precision and restart
// studies, the restart study, the
// validation's scored ranges, measured curve and ranking; strict one-line errors for bad values.
#include <boost/test/unit_test.hpp>

#include <filesystem>

#include "tools/io/input_error.hpp"
#include "tools/io/scratch_dir.hpp"
#include "tools/scene/scene_study_file.hpp"
#include "tools/scene/stone_study_file.hpp"

using namespace stoneskip;

namespace {

const char* kQuick = "cases/studies/stones_quick.toml";  // tests run in the source folder

// The one-line message of the InputError thrown, or "" if none.
std::string error_of(const std::vector<std::string>& overrides) {
  try {
    load_stone_study_file(kQuick, overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// An error message names `part` and is one line.
void names(const std::string& message, const std::string& part) {
  BOOST_TEST(message.find(part) != std::string::npos, "'" << part << "' not in: " << message);
  BOOST_TEST(message.find('\n') == std::string::npos, message);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(stone_study_file_keys)

BOOST_AUTO_TEST_CASE(the_shipped_study_files_load_from_a_folder_outside_the_source_tree) {
  // Oracle: the rule of tools/io/shipped_files.hpp — a "cases/…" path that does not exist where
  // the command runs is the shipped case. The stones and scene studies name their throws relative
  // to the study file ("cases/studies/../paper_8ms_spin.toml"); main checked those paths without
  // the lookup, so `report stones` and `report scene` failed outside the source folder ("no case
  // file"), while `report waves` ran.
  ScratchDir elsewhere("study_from_anywhere");
  WorkingFolder there(elsewhere.dir);
  BOOST_REQUIRE(!std::filesystem::exists("cases"));
  for (const char* f : {"cases/studies/stones.toml", "cases/studies/stones_quick.toml"})
    BOOST_CHECK_NO_THROW(load_stone_study_file(f));
  for (const char* f : {"cases/studies/scene.toml", "cases/studies/scene_quick.toml"})
    BOOST_CHECK_NO_THROW(load_scene_study_file(f));
  const StoneStudiesOptions full = load_stone_study_file("cases/studies/stones.toml").options;
  BOOST_TEST(!full.hard.empty());  // the "../hard" folder's cases, listed from the shipped copy
}

BOOST_AUTO_TEST_CASE(the_shipped_presets_name_their_laws_ranges_and_curve) {
  // Oracle: the shipped files as written (cases/studies/stones.toml and stones_quick.toml).
  const StoneStudiesOptions full = load_stone_study_file("cases/studies/stones.toml").options;
  const std::vector<WaterLaw> all{WaterLaw::newtonian, WaterLaw::planing, WaterLaw::nagahiro_hayakawa};
  BOOST_TEST((full.validation.laws == all));
  BOOST_TEST((full.convergence_laws == std::vector<WaterLaw>{WaterLaw::planing, WaterLaw::newtonian, WaterLaw::nagahiro_hayakawa}));
  BOOST_TEST((full.convergence_distributions ==
              std::vector<PressureDistribution>{PressureDistribution::savitsky_wagner, PressureDistribution::uniform,
                                                PressureDistribution::savitsky}));
  BOOST_TEST(full.work_precision_throws.size() == 6u);  // three throws, and three under another law
  BOOST_TEST((full.flat_drop.problem.environment.convention == Convention::paper));
  BOOST_TEST(full.restarts.strategies.size() == 4u);
  BOOST_TEST((full.restarts.throws ==
              std::vector<std::string>{"clanet", "spin", "nospin", "spin@newtonian", "nospin@newtonian", "flat_drop"}));
  int scored = 0;
  for (const auto& m : full.validation.measured) scored += m.score ? 1 : 0;
  BOOST_TEST(scored == 5);
  BOOST_TEST_REQUIRE(full.validation.curves.size() == 1u);
  BOOST_TEST(full.validation.curves[0].low[0] == 2.5);
  BOOST_TEST(full.validation.curves[0].high[0] == 2.6);
  const StoneStudiesOptions quick = load_stone_study_file(kQuick).options;
  BOOST_TEST((quick.validation.laws == std::vector<WaterLaw>{WaterLaw::planing}));
  BOOST_TEST((quick.validation.distributions ==
              std::vector<PressureDistribution>{PressureDistribution::uniform, PressureDistribution::savitsky_wagner}));
  BOOST_TEST(full.validation.distributions.size() == 3u);
  BOOST_TEST(full.validation.ranking.bounds.min_speed_fraction == 0.10);
  BOOST_TEST(full.validation.ranking.bounds.attitude_deg == 5.0);
  int models = 0;
  for (const auto& m : full.validation.measured) models += m.kind == "model" ? 1 : 0;
  BOOST_TEST(models == 6);  // Bocquet's three rows and the seed's three: model beside model
  int peers = 0;
  for (const auto& m : full.validation.measured) peers += m.peer.empty() ? 0 : 1;
  BOOST_TEST(peers == 3);  // the peer simulator's U_min, β_max and contact time (model/README.md §3)
  BOOST_TEST(!full.validation.peer_description.empty());
  BOOST_TEST(quick.validation.ranking.held_spin_rev_s == 65.0);
  BOOST_TEST(full.convergence.correction_term);  // written out in both presets
  BOOST_TEST(quick.convergence.correction_term);
  BOOST_TEST(!load_stone_study_file(kQuick, {"convergence.correction_term=false"}).options.convergence.correction_term);
}

BOOST_AUTO_TEST_CASE(bad_laws_ranges_and_strategies_are_one_line_errors_naming_the_key) {
  // Oracle: the strict-parsing rule of cases/README.md — file, key and what is wrong, one line.
  names(error_of({"validation.laws=[\"newtonian\", \"planning\"]"}), "validation.laws");
  names(error_of({"convergence.laws=[\"planing\", \"planing\"]"}), "convergence.laws");
  names(error_of({"validation.ranking.held_spin_rev_s=30.0"}), "validation.ranking.held_spin_rev_s");
  names(error_of({"validation.ranking.cost_throws=[\"bocquet\"]"}), "validation.ranking.cost_throws");
  names(error_of({"validation.ranking.colour=1"}), "colour");
  names(error_of({"validation.distributions=[\"uniform\", \"wagner\"]"}), "validation.distributions");
  names(error_of({"validation.distributions=[\"uniform\", \"uniform\"]"}), "validation.distributions");
  names(error_of({"validation.distributions=[\"savitsky\"]"}), "validation.distributions");
  names(error_of({"validation.trout_spin_rev_s=12.0"}), "validation.trout_spin_rev_s");
  names(error_of({"validation.ranking.attitude_bound_deg=-1.0"}), "attitude_bound_deg");
  names(error_of({R"(validation.measured=[{key = "seed_spin", quantity = "q", measured = "m", source = "s", kind = "guess"}])"}),
        "kind");
  // A peer's value without saying what the peer is.
  names(error_of({"validation.peer_description=\"\"",
                  R"(validation.measured=[{key = "seed_spin", quantity = "q", measured = "m", source = "s", kind = "model", peer = "3"}])"}),
        "validation.measured[0].peer");
  names(error_of({"restarts.strategies=[\"at_jumps\", \"never\"]"}), "restarts.strategies");
  names(error_of({"restarts.throws=[\"nospin@planning\"]"}), "restarts.throws");
  // The seed's cases are planing already: "nospin@planing" beside "nospin" is one throw twice.
  names(error_of({"restarts.throws=[\"nospin\", \"nospin@planing\"]"}), "the same throw under the same law");
  names(error_of({"work_precision.throws=[\"nospin\", \"nospin@planing\"]"}), "the same throw under the same law");
  names(error_of({"work_precision.throws=[\"spin_paper@planing\"]"}), "work_precision.throws");
  names(error_of({"work_precision.throws=[\"sidespin\"]"}), "work_precision.throws");
  names(error_of({"restarts.throws=[\"flat_drop@planing\"]"}), "paper convention");  // the case is the paper's
  names(error_of({"restarts.strategies=[\"every_event\", \"sometimes\"]"}), "restarts.strategies");
  names(error_of({"convergence.correction_term=\"yes\""}), "convergence.correction_term");
  // A check run at the reference's own tolerance is the reference: its error bound was 0 and the
  // reference's error was called the stepper's divergence (f = 1; f ≥ 2 bounds it, |f − 1| e ≥ e).
  names(error_of({"convergence.check_factor=1.0"}), "convergence.check_factor: must be at least 2 (got 1)");
  names(error_of({"convergence.check_factor=1.5"}), "convergence.check_factor");
  BOOST_TEST(error_of({"convergence.check_factor=2.0"}).empty());
  // The work–precision truth's check likewise (f = 1: its uncertainty 0, no chaotic throw set aside).
  names(error_of({"work_precision.truth_check_factor=1.0"}), "work_precision.truth_check_factor: must be at most 0.5 or at least 2");
  BOOST_TEST(error_of({"work_precision.truth_check_factor=0.5"}).empty());
  // A measured row: a range on a row the ranking cannot score, half a range, a range across zero.
  const std::string row = R"(validation.measured=[{key = "seed_spin", quantity = "q", measured = "m", source = "s", )";
  names(error_of({row + R"(score_low = 1.0, score_high = 2.0, score_unit = ""}])"}), "score_low");
  const std::string scorable = R"(validation.measured=[{key = "clanet_min_speed", quantity = "q", measured = "m", source = "s", )";
  names(error_of({scorable + R"(score_low = 2.5}])"}), "score_high");
  names(error_of({scorable + R"(score_low = -1.0, score_high = 1.0, score_unit = ""}])"}), "score_low");
  names(error_of({scorable + R"(score_low = 2.5, score_high = 2.6}])"}), "score_unit");
  // A measured curve whose points do not pair up.
  names(error_of({R"(validation.curve=[{key = "clanet_min_speed", label = "l", source = "s", x = [20.0, 25.0], low = [2.5], high = [2.6, 2.7]}])"}),
        "low");
  // An axis's from/to/step whose step does not move its values: summed without end before (until
  // the memory ran out). Refused on the step, naming why.
  const std::string tiny = error_of(
      {R"(sweeps.axis=[{parameter = "spin_rev_s", from = 1e20, to = 1e20, step = 1.0, tolerance = 0.25}])"});
  names(tiny, "step");
  names(tiny, "below the values' resolution");
  BOOST_TEST(error_of({}).empty());
}

BOOST_AUTO_TEST_CASE(the_mesh_study_reads_its_meshes_and_refuses_bad_ones) {
  // The quick preset's [mesh]: segments 11 and 16 × both cuts, in that order (the centre cut: 6N
  // triangles, the diagonal 4N); each mesh's reference is its cut's at N = 16.
  const StoneStudyFile f = load_stone_study_file(kQuick);
  const MeshStudyOptions& m = f.options.mesh;
  BOOST_REQUIRE_EQUAL(m.meshes.size(), 4u);
  BOOST_TEST(m.meshes[0].stone.body_mesh.triangles.size() == 44u);  // the paper's stone
  BOOST_TEST(m.meshes[1].stone.body_mesh.triangles.size() == 66u);
  BOOST_TEST(m.meshes[3].stone.body_mesh.triangles.size() == 96u);
  BOOST_TEST(m.reference_of(0) == 2u);
  BOOST_TEST(m.reference_of(1) == 3u);
  BOOST_TEST(m.reference_of(3) == 3u);
  // One solid, two cuts: the same mass to round-off.
  BOOST_TEST(m.meshes[0].stone.mass.mass_kg == m.meshes[1].stone.mass.mass_kg, boost::test_tools::tolerance(1e-12));
  names(error_of({"mesh.segments=[11, 11]"}), "mesh.segments");
  names(error_of({"mesh.segments=[11.5]"}), "mesh.segments");
  names(error_of({"mesh.segments=[2]"}), "mesh.segments");
  names(error_of({"mesh.rim_splits=[\"diagonal\", \"middle\"]"}), "mesh.rim_splits");
  names(error_of({"mesh.segments=[11]", "mesh.rim_splits=[\"centre\"]"}), "at least 2 meshes");
  names(error_of({"mesh.members=3"}), "mesh.members");
  names(error_of({"mesh.spins_rev_s=[500.0]"}), "mesh.spins_rev_s");
  names(error_of({"mesh.perturbation_largest=0.5"}), "mesh.perturbation_largest");
  names(error_of({"mesh.base=\"../hard/tumbling_asymmetric.toml\""}), "mesh.base");  // a mesh file, not a prism
  names(error_of({"mesh.colour=1"}), "colour");
  names(error_of({"mesh.spins_rev_s=[40.0, -40.0, 40.0]"}), "mesh.spins_rev_s");
  names(error_of({"mesh.base=\"../hard/paper_high_spin.toml\""}), "physical convention");
}

BOOST_AUTO_TEST_CASE(the_families_confidence_is_a_key_of_its_own_and_held_to_its_range) {
  // Oracle: the defaults of count_ensembles.hpp and mesh_study.hpp (0.95) where the file names none,
  // the value given where it does, and the range [0.5, 0.999] (stone_study_file.cpp), its ends kept.
  const StoneStudiesOptions plain = load_stone_study_file(kQuick).options;
  BOOST_TEST(plain.count_ensembles.family_confidence == 0.95);
  BOOST_TEST(plain.mesh.family_confidence == 0.95);
  const StoneStudiesOptions set =
      load_stone_study_file(kQuick, {"sweeps.ensemble_family_confidence=0.9", "mesh.family_confidence=0.999"}).options;
  BOOST_TEST(set.count_ensembles.family_confidence == 0.9);
  BOOST_TEST(set.mesh.family_confidence == 0.999);
  BOOST_TEST(error_of({"sweeps.ensemble_family_confidence=0.5", "mesh.family_confidence=0.5"}).empty());
  names(error_of({"sweeps.ensemble_family_confidence=1.0"}), "sweeps.ensemble_family_confidence");
  names(error_of({"sweeps.ensemble_family_confidence=0.49"}), "sweeps.ensemble_family_confidence");
  names(error_of({"mesh.family_confidence=0.9995"}), "mesh.family_confidence");
  names(error_of({"mesh.family_confidence=\"high\""}), "mesh.family_confidence");
  names(error_of({"mesh.family_confidance=0.9"}), "family_confidance");  // a misspelt key is refused
}

BOOST_AUTO_TEST_SUITE_END()
