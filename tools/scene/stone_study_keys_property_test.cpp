// Property: every key of the shipped stones study file refuses a value no key can take,
// in one line naming it. Oracle: cases/README.md, "Study files" (tools/scene/study_keys_property.hpp).
#include "tools/scene/stone_study_file.hpp"
#include "tools/scene/study_keys_property.hpp"
#include "tools/io/input_error.hpp"

#include <string>

BOOST_AUTO_TEST_SUITE(documented_study_keys)

BOOST_AUTO_TEST_CASE(every_stones_study_key_refuses_a_value_no_key_can_take) {
  const std::string file = "cases/studies/stones.toml";
  const int checked = stoneskip::test::check_study_keys(
      file, [&](const std::vector<std::string>& set) { stoneskip::load_stone_study_file(file, set); });
  BOOST_TEST(checked >= 90);
}

BOOST_AUTO_TEST_CASE(a_study_step_below_a_cases_is_refused) {
  // Oracle: a case's step range ([1e-9, 1] s, cases/README.md, which `run` keeps): a study step of
  // 1e-9 s with contact_ratio 0.1 is a contact step of 1e-10 s; the study once sat on it for minutes.
  const std::string file = "cases/studies/stones_quick.toml";
  for (const std::string set : {"convergence.dt_s=[2e-3, 1e-3, 1e-9]", "convergence.dt_s=[2e-3, 2]"}) {
    try {
      stoneskip::load_stone_study_file(file, {set});
      BOOST_ERROR(set << ": taken");
    } catch (const stoneskip::InputError& e) {
      const std::string m = e.what();
      BOOST_TEST(m.find("convergence.dt_s") != std::string::npos, m);
    }
  }
  BOOST_CHECK_NO_THROW(stoneskip::load_stone_study_file(file, {"convergence.dt_s=[2e-3, 1e-8]"}));
}

BOOST_AUTO_TEST_SUITE_END()
