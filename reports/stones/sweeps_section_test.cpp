// The bounce-count section (sweeps_section.cpp) states the mesh study's verdict on the base stone's
// mesh beside its counts. Oracle: hand-made mesh-study counts whose verdicts are known (the rule's
// paired interval, mesh_study_test.cpp): the numbers in the words are those of the stored tables.
#include <boost/test/unit_test.hpp>

#include "reports/stones/report_sections.hpp"
#include "verification/stones/mesh_study.hpp"
#include "verification/stones/mesh_study_fixture.hpp"

namespace stoneskip {
namespace {

// The diagonal cut at N = 11 (44 triangles) and 16 (64): two throws of 6 paired members, N = 11
// different at the first (9 against 3 in every member) and the same at the second.
Record mesh_record(int count_at_11) {
  MeshStudyOptions o;
  o.meshes = {test_prism_variant(11, RimSplit::diagonal), test_prism_variant(16, RimSplit::diagonal)};
  o.spins_rev_s = {20, 40};
  o.attack_angles_deg = {10};
  o.members = 6;
  std::vector<MeshThrowRuns> runs(2);
  const std::vector<double> c11(6, count_at_11), three(6, 3), two(6, 2);
  runs[0] = {20, 10, {c11, three}};
  runs[1] = {40, 10, {two, two}};
  return mesh_study_findings(runs, o, "test");
}

// The base throw's record; its stone that of the N = 11 diagonal prism above unless said.
Record sweeps_record(double triangles, double mass_kg = test_prism_variant(11, RimSplit::diagonal).stone.mass.mass_kg) {
  Record r;
  Record& b = r.child("base");
  b.set("label", std::string("test throw")).set("stone", std::string("prism")).set("mass_kg", mass_kg);
  b.set("speed_m_s", 8.0).set("path_angle_deg", 10.0).set("attack_angle_deg", 10.0).set("spin_rev_s", 0.0);
  b.set("scheme", std::string("bs32")).set("adaptive", 1.0).set("rtol", 1e-9).set("atol_m", 1e-9).set("dt_s", 0.01);
  b.set("contact_dt_s", 1e-4);
  if (triangles > 0) b.set("triangles", triangles);
  r.set_strings("parameters", {});
  return r;
}

BOOST_AUTO_TEST_SUITE(sweeps_section_)

BOOST_AUTO_TEST_CASE(the_counts_are_said_to_be_the_mesh_s_where_the_mesh_study_finds_them_unsettled) {
  Record fig9;  // no histories: the Fig. 9 part renders empty
  fig9.set_strings("histories", {});
  const Record unsettled = mesh_record(9);
  const std::string md = sweeps_section(sweeps_record(44), fig9, &unsettled).markdown;
  BOOST_TEST(md.find("**These counts are the base stone's mesh's** (N = 11, diagonal cut, 44 triangles)") != std::string::npos, md);
  BOOST_TEST(md.find("against N = 16, diagonal cut, 64 triangles, this mesh's count differs on 1 of the 2") != std::string::npos, md);
  BOOST_TEST(md.find("not shown to have settled at N = 11") != std::string::npos, md);
  // Where N = 11 agrees with N = 16 at both throws, the cut settles from 11: said, with no warning.
  const Record settled = mesh_record(3);
  const std::string ok = sweeps_section(sweeps_record(44), fig9, &settled).markdown;
  BOOST_TEST(ok.find("differs on 0 of the 2") != std::string::npos, ok);
  BOOST_TEST(ok.find("from N = 11 that cut's counts show no difference from N = 16") != std::string::npos, ok);
  BOOST_TEST(ok.find("not shown to be the solid's") == std::string::npos);
  // A base throw stored before its triangles were (or another mesh): nothing is said.
  BOOST_TEST(sweeps_section(sweeps_record(0), fig9, &unsettled).markdown.find("These counts") == std::string::npos);
  BOOST_TEST(sweeps_section(sweeps_record(66), fig9, &unsettled).markdown.find("These counts") == std::string::npos);
  // 44 triangles of another solid (a heavier stone): not the study's mesh either.
  BOOST_TEST(sweeps_section(sweeps_record(44, 1.0), fig9, &unsettled).markdown.find("These counts") == std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
