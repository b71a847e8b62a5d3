// The mesh section (mesh_section.cpp) says at which level each kind of verdict was tested. Oracle:
// the levels' definitions (mesh_study.hpp: 95 % against the reference; the cuts' and the mirror
// pairs' families held to 95 % together, Bonferroni), for hand-made counts whose family sizes are
// known; and a record written before the levels, whose old sentence must stay.
#include <boost/test/unit_test.hpp>

#include "reports/stones/report_sections.hpp"
#include "verification/stones/mesh_study.hpp"
#include "verification/stones/mesh_study_fixture.hpp"

namespace stoneskip {
namespace {

// Both cuts at N = 11 and 16, spins ±40 at one attack angle: 2 cut comparisons (one per throw)
// and 4 mirror pairs (one per mesh), so each cut verdict at 97.5 % and each mirror verdict at
// 98.75 %.
Record mesh_record() {
  MeshStudyOptions o;
  o.meshes = {test_prism_variant(16, RimSplit::centre), test_prism_variant(11, RimSplit::diagonal),
              test_prism_variant(16, RimSplit::diagonal), test_prism_variant(11, RimSplit::centre)};
  o.spins_rev_s = {-40, 40};
  o.attack_angles_deg = {10};
  o.members = 6;
  std::vector<MeshThrowRuns> runs(2);
  runs[0] = {-40, 10, {{5, 5, 5, 5, 5, 5}, {11, 12, 12, 12, 12, 11}, {6, 6, 6, 6, 6, 6}, {8, 9, 8, 9, 8, 9}}};
  runs[1] = {40, 10, {{5, 5, 5, 5, 5, 5}, {9, 9, 8, 9, 9, 9}, {5, 5, 5, 5, 5, 5}, {9, 8, 9, 8, 9, 8}}};
  return mesh_study_findings(runs, o, "test");
}

BOOST_AUTO_TEST_SUITE(mesh_section_)

BOOST_AUTO_TEST_CASE(the_section_says_each_family_s_level) {
  const std::string md = mesh_section(mesh_record()).markdown;
  BOOST_TEST(md.find("Against its cut's reference each verdict is at 95 % on its own") != std::string::npos, md);
  BOOST_TEST(md.find("The 2 comparisons of the two cuts claim a difference where they find one, so they are one family "
                     "held to 95 % together (Bonferroni): each at 97.5 %.") != std::string::npos, md);
  BOOST_TEST(md.find("The 4 mirror-pair comparisons claim a difference where they find one, so they are one family "
                     "held to 95 % together (Bonferroni): each at 98.75 %.") != std::string::npos, md);
  BOOST_TEST(md.find("98.75 % interval") != std::string::npos);  // the mirror reasons print their level
  // Where no pair's difference varies the exact test decides, and its reason says so: N = 16
  // diagonal's mirror pair differs by one in all 6 members, p = 2/2⁶ = 0.031, above 0.0125.
  BOOST_TEST(md.find("mean difference -1, 98.75 % interval [-1, -1] (paired t); no pair's difference varies, so the exact "
                     "sign-flip test decides: p = 0.03125 against α = 0.0125") != std::string::npos, md);
  BOOST_TEST(md.find("could say \"different\" by chance") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_record_written_before_the_levels_keeps_its_sentence) {
  // Without the stored levels (records before them): every verdict at 95 % on its own, said so.
  const Record r = mesh_record();
  Record older;
  for (const auto& [k, v] : r.numbers())
    if (k.find("confidence") == std::string::npos) older.set(k, v);
  for (const auto& [k, v] : r.texts()) older.set(k, v);
  for (const auto& [k, v] : r.tables()) older.set_table(k, v);
  for (const auto& [k, v] : r.string_lists()) older.set_strings(k, v);
  for (const std::string& k : r.child_names()) older.add_child(k, r.at(k));
  const std::string md = mesh_section(older).markdown;
  const double verdicts = r.number("verdict_count");
  BOOST_TEST(verdicts == 4 + 2 + 4);  // 2 meshes below their references × 2 throws, 2 cut, 4 mirror
  BOOST_TEST(md.find("Each verdict holds at 95 %: of this section's 10 verdicts, about 0.5 could say \"different\" by "
                     "chance") != std::string::npos, md);
  BOOST_TEST(md.find("each at 98.75 %") == std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
