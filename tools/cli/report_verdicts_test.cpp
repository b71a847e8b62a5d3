// `report render DIR` re-checks every stored verdict against its rule and stored inputs before it
// prints one. Oracle: contradicted_verdicts (verification/study/verdict_rules.hpp) on the page's
// own data.h5 — a freshly built page has none and renders (exit 0); the same page with one verdict
// phrase edited in data.h5 is refused: exit 2, one line naming data.h5 and the verdict's path,
// index.md left as it was.
#include <boost/test/unit_test.hpp>

#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "tools/cli/test_support.hpp"
#include "verification/study/record.hpp"
#include "verification/study/verdict_rules.hpp"

namespace fs = std::filesystem;
using stoneskip::Record;
using stoneskip::test::read_file;
using stoneskip::test::RanApart;
using stoneskip::test::run_apart;

namespace {

constexpr int kTimeout_s = 60;  // a render of this report takes seconds

// The first record under r that holds a rule and a verdict.
const Record* first_verdict(const Record& r) {
  if (r.has_text("rule") && r.has_text("verdict")) return &r;
  for (const auto& c : r.child_names())
    if (const Record* v = first_verdict(r.at(c))) return v;
  return nullptr;
}

// Edits a text attribute as a hand with an HDF5 editor would (deleted and made again).
void set_text_attribute(const fs::path& file, const std::string& object, const char* name, const std::string& value) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  BOOST_REQUIRE(f >= 0);
  BOOST_REQUIRE(H5Adelete_by_name(f, object.c_str(), name, H5P_DEFAULT) >= 0);
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, H5T_VARIABLE);
  H5Tset_cset(type, H5T_CSET_UTF8);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t a = H5Acreate_by_name(f, object.c_str(), name, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  BOOST_REQUIRE(a >= 0);
  const char* text = value.c_str();
  BOOST_REQUIRE(H5Awrite(a, type, &text) >= 0);
  H5Aclose(a);
  H5Sclose(space);
  H5Tclose(type);
  H5Fclose(f);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(report_verdicts)

BOOST_AUTO_TEST_CASE(a_data_file_whose_verdict_contradicts_its_rule_is_refused_by_render) {
  const fs::path dir = fs::temp_directory_path() / ("stoneskip_report_verdicts_" + std::to_string(::getpid()));
  const fs::path page = dir / "rep";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const RanApart built = run_apart({"capture", "validate", "cases/captures/gentle_sidearm.log", "--no-simulate", "--out", page.string()});
  BOOST_REQUIRE_MESSAGE(built.status == 0, built.err);
  BOOST_TEST(run_apart({"report", "render", page.string()}, kTimeout_s).status == 0);

  std::string path, stored;
  {
    stoneskip::Hdf5Reader data(page / "data.h5");
    const Record sections = stoneskip::load_record(data.root().open_group("sections"));
    BOOST_REQUIRE(stoneskip::contradicted_verdicts(sections).empty());
    const Record* v = first_verdict(sections);
    BOOST_REQUIRE(v != nullptr);
    path = v->path();
    stored = v->text("verdict");
  }
  const std::string index = read_file(page / "index.md");
  set_text_attribute(page / "data.h5", path, "verdict", stored + " (edited)");
  const RanApart r = run_apart({"report", "render", page.string()}, kTimeout_s);
  BOOST_TEST(r.status == 2, "exit " << r.status << ": " << r.err);
  BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1, r.err);
  BOOST_TEST(r.err.find((page / "data.h5").string()) != std::string::npos, r.err);
  BOOST_TEST(r.err.find(path) != std::string::npos, r.err);
  BOOST_TEST(r.err.find("contradicts its rule") != std::string::npos, r.err);
  BOOST_TEST(read_file(page / "index.md") == index);
  std::error_code ec;
  fs::remove_all(dir, ec);
}

BOOST_AUTO_TEST_SUITE_END()
