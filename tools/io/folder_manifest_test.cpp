// Oracle: the folder listing. A folder holding something that is not a plain file or folder (a
// link) gets no manifest, and nothing in it is touched: the refusal came after a killed writer's
// temporaries had been removed, so a refused folder had already been changed.
#include <boost/test/unit_test.hpp>

#include <filesystem>

#include "tools/io/folder_manifest.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/scratch_dir.hpp"

namespace fs = std::filesystem;
using namespace stoneskip;

BOOST_AUTO_TEST_SUITE(folder_manifest)

BOOST_AUTO_TEST_CASE(a_refused_folder_is_left_as_it_was) {
  ScratchDir s("stoneskip_manifest_refused");
  s.write("index.md", "page");
  s.write("data.h5.tmp-12345", "half a file");
  fs::create_symlink("/etc/hostname", s.dir / "a-link");
  BOOST_CHECK_THROW(write_folder_manifest(s.dir), InputError);
  BOOST_TEST(fs::exists(s.dir / "data.h5.tmp-12345"));  // not removed before the refusal
  BOOST_TEST(!fs::exists(s.dir / kFolderManifest));
  fs::remove(s.dir / "a-link");
  write_folder_manifest(s.dir);  // without the link: written, the temporary removed
  BOOST_TEST(!fs::exists(s.dir / "data.h5.tmp-12345"));
  BOOST_TEST(fs::exists(s.dir / kFolderManifest));
}

BOOST_AUTO_TEST_SUITE_END()
