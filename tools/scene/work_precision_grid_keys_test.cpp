// The [work_precision_grid] keys of the stones study files (cases/README.md, "Study files"): the
// shipped presets' grids, and strict one-line errors naming the key for a misspelt key or a bad value.
#include <boost/test/unit_test.hpp>

#include "tools/io/input_error.hpp"
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

}  // namespace

BOOST_AUTO_TEST_SUITE(work_precision_grid_keys)

BOOST_AUTO_TEST_CASE(the_shipped_presets_name_a_physical_base_and_a_small_quick_grid) {
  // Oracle: the shipped files as written (cases/studies/stones.toml and stones_quick.toml).
  const StoneStudyFile full = load_stone_study_file("cases/studies/stones.toml");
  const StoneStudiesOptions& f = full.options;
  BOOST_TEST(f.work_precision_grid_base.file == "../spin_sweep_base.toml");
  BOOST_TEST((f.work_precision_grid_base.problem.environment.convention == Convention::physical));
  BOOST_TEST(f.work_precision_grid.spins_rev_s.size() * f.work_precision_grid.attack_angles_deg.size() == 12u);
  BOOST_TEST(full.settings_text.find("# case ../spin_sweep_base.toml") != std::string::npos);  // resumes only if unchanged
  const StoneStudiesOptions q = load_stone_study_file(kQuick).options;
  BOOST_TEST(q.work_precision_grid.spins_rev_s.size() * q.work_precision_grid.attack_angles_deg.size() == 2u);
}

BOOST_AUTO_TEST_CASE(misspelt_keys_and_bad_values_are_one_line_errors_naming_the_key) {
  // Oracle: the strict-parsing rule of cases/README.md — file, key and what is wrong, one line.
  auto names = [](const std::string& message, const std::string& key) {
    BOOST_TEST(message.find(key) != std::string::npos, message);
    BOOST_TEST(message.find('\n') == std::string::npos, message);
  };
  names(error_of({"work_precision_grid.spin_rev_s=[0.0]"}), "spin_rev_s");  // spins_rev_s misspelt
  names(error_of({"work_precision_grid.attack_angle_deg=[10.0]"}), "attack_angle_deg");
  names(error_of({"work_precision_grid.base=\"../no_such_case.toml\""}), "work_precision_grid.base");
  names(error_of({"work_precision_grid.base=\"flat_drop.toml\""}), "physical convention");
  names(error_of({"work_precision_grid.spins_rev_s=[]"}), "work_precision_grid.spins_rev_s");
  names(error_of({"work_precision_grid.attack_angles_deg=[95.0]"}), "work_precision_grid.attack_angles_deg");
  names(error_of({"work_precision_grid.fixed_schemes=[\"bs32\"]"}), "work_precision_grid.fixed_schemes");
  names(error_of({"work_precision_grid.fixed_schemes=[\"euler\"]"}), "work_precision_grid.fixed_schemes");
  names(error_of({"work_precision_grid.dt_s=[-1e-3]"}), "work_precision_grid.dt_s");
  names(error_of({"work_precision_grid.contact_ratio=2.0"}), "work_precision_grid.contact_ratio");
  names(error_of({"work_precision_grid.method=\"rk45\""}), "work_precision_grid.method");
  names(error_of({"work_precision_grid.cvode_rtol=[0.0]"}), "work_precision_grid.cvode_rtol");
  names(error_of({"work_precision_grid.agreement_target=1.5"}), "work_precision_grid.agreement_target");
  names(error_of({"work_precision_grid.agreement_bound=\"lower\""}), "work_precision_grid.agreement_bound");
  names(error_of({"work_precision_grid.contact_time_threshold_s=-1e-4"}), "work_precision_grid.contact_time_threshold_s");
  names(error_of({"work_precision_grid.budget_rhs_per_frame=[2.0]"}), "work_precision_grid.budget_rhs_per_frame");
  names(error_of({"work_precision_grid.budget_rhs_per_frame=[64.5]"}), "work_precision_grid.budget_rhs_per_frame");
  names(error_of({"work_precision_grid.budget_frame_dt_s=0.0"}), "work_precision_grid.budget_frame_dt_s");
  names(error_of({"work_precision_grid.budget_rhs_per_fram=[64]"}), "budget_rhs_per_fram");
  BOOST_TEST(error_of({}).empty());
  BOOST_TEST(error_of({"work_precision_grid.agreement_bound=\"wilson_lower\""}).empty());
}

BOOST_AUTO_TEST_SUITE_END()
