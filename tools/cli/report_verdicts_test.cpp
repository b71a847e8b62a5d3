// `report render DIR` re-checks every stored verdict against its rule and stored inputs before it
// prints one. Oracle: contradicted_verdicts (verification/study/verdict_rules.hpp) on the page's
// own data.h5 — a freshly built page has none and renders (exit 0); the same page with one verdict
// phrase edited in data.h5 is refused: exit 2, one line naming data.h5 and the verdict's path,
// index.md left as it was.
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "tools/cli/hdf5_edit.hpp"
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
  stoneskip::test::set_attribute(page / "data.h5", path, "verdict", stored + " (edited)");
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
