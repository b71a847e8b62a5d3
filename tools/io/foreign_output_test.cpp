// Which existing files `--out` may replace (tools/io/foreign_output.hpp): only stoneskip's own,
// of the writing command's kind.
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <filesystem>
#include <string>

#include "tools/io/foreign_output.hpp"
#include "tools/io/hdf5_file.hpp"
#include "tools/io/scratch_dir.hpp"

namespace fs = std::filesystem;
using namespace stoneskip;

namespace {

// A stamped HDF5 file with one extra root attribute (none when name is empty).
fs::path stamped(const fs::path& p, const std::string& name) {
  Hdf5Writer w(p);
  stamp_provenance(w.root());
  if (!name.empty()) w.root().set_attr(name, std::string("x"));
  w.commit();
  return p;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(foreign_output)

BOOST_AUTO_TEST_CASE(an_hdf5_file_is_replaced_only_by_a_command_of_its_kind) {
  // Oracle: the kinds as the writers mark them. A throw's file (run, scene, capture throw) carries
  // neither `sweep_file` (a sweep's result, sweep_result.cpp) nor `report` (a report's data.h5,
  // report_build.cpp); `run --out` once replaced both, the code_version stamp being all it looked at.
  ScratchDir s("stoneskip_foreign_output");
  const fs::path throw_file = stamped(s.dir / "t.h5", "");
  const fs::path sweep_file = stamped(s.dir / "s.h5", "sweep_file");
  const fs::path report_data = stamped(s.dir / "data.h5", "report");
  const fs::path sweep_page = stamped(s.dir / "page.h5", "source");  // a sweep page's data.h5
  BOOST_TEST(!stoneskip_wrote(sweep_page, OutputFormat::hdf5));
  BOOST_TEST(stoneskip_wrote(throw_file, OutputFormat::hdf5));
  BOOST_TEST(!stoneskip_wrote(throw_file, OutputFormat::hdf5_sweep));
  BOOST_TEST(stoneskip_wrote(sweep_file, OutputFormat::hdf5_sweep));
  BOOST_TEST(!stoneskip_wrote(sweep_file, OutputFormat::hdf5));
  BOOST_TEST(!stoneskip_wrote(report_data, OutputFormat::hdf5));
  BOOST_TEST(!stoneskip_wrote(report_data, OutputFormat::hdf5_sweep));
  BOOST_CHECK_THROW(refuse_foreign_output(report_data, OutputFormat::hdf5), std::exception);
  BOOST_CHECK_NO_THROW(refuse_foreign_output(throw_file, OutputFormat::hdf5));
}

BOOST_AUTO_TEST_SUITE_END()
