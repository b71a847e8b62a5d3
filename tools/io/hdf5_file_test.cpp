// An HDF5 call that fails is reported for its own cause. Oracle: a conversion HDF5 has no path
// for (variable-length strings read as doubles) fails inside the library without any system
// call failing, so it is not a full disk whatever errno held before it.
#include <boost/test/unit_test.hpp>

#include <cerrno>
#include <stdexcept>
#include <string>
#include <system_error>

#include "tools/io/hdf5_file.hpp"
#include "tools/io/scratch_dir.hpp"

using namespace stoneskip;

BOOST_AUTO_TEST_SUITE(hdf5_file)

BOOST_AUTO_TEST_CASE(a_failed_call_is_not_blamed_on_an_earlier_full_disk) {
  ScratchDir dir("stoneskip_hdf5");
  const auto path = dir.dir / "strings.h5";
  {
    Hdf5Writer w(path);
    w.root().write_strings("names", {"a", "b"});
    w.commit();
  }
  Hdf5Reader r(path);
  errno = ENOSPC;  // left by some earlier, unrelated failure
  bool system_error = false, other_error = false;
  try {
    r.root().read_vector("names");
  } catch (const std::system_error&) {
    system_error = true;  // would send the user to free disk space (exit 2, "no room")
  } catch (const std::runtime_error&) {
    other_error = true;
  }
  BOOST_TEST(!system_error);
  BOOST_TEST(other_error);
}

BOOST_AUTO_TEST_SUITE_END()
