// Property: every key of the shipped stones study file refuses a value no key can take,
// in one line naming it. Oracle: cases/README.md, "Study files" (tools/scene/study_keys_property.hpp).
#include "tools/scene/stone_study_file.hpp"
#include "tools/scene/study_keys_property.hpp"

BOOST_AUTO_TEST_SUITE(documented_study_keys)

BOOST_AUTO_TEST_CASE(every_stones_study_key_refuses_a_value_no_key_can_take) {
  const std::string file = "cases/studies/stones.toml";
  const int checked = stoneskip::test::check_study_keys(
      file, [&](const std::vector<std::string>& set) { stoneskip::load_stone_study_file(file, set); });
  BOOST_TEST(checked >= 90);
}

BOOST_AUTO_TEST_SUITE_END()
