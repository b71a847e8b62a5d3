// An HDF5 call that fails is reported for its own cause. Oracle: a conversion HDF5 has no path
// for (variable-length strings read as doubles) fails inside the library without any system
// call failing, so it is not a full disk whatever errno held before it.
#include <boost/test/unit_test.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>
#include <stdexcept>
#include <string>
#include <system_error>

#include "tools/io/hdf5_file.hpp"
#include "tools/io/input_error.hpp"
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

BOOST_AUTO_TEST_CASE(a_dataset_write_that_does_not_fit_names_the_file) {
  // Oracle: the bad-output rule (one line naming the file). A dataset larger than HDF5's cache goes
  // to the disk at its write, before the commit: past a file-size limit (RLIMIT_FSIZE with SIGXFSZ
  // ignored; a full disk fails the same way with ENOSPC) the write fails with EFBIG. It said
  // "HDF5: write trajectory: File too large", naming no file; and nothing is left behind.
  // In a child process: after a failed write HDF5 may still hold the file, and its clean-up at
  // exit can crash on it (the CLI's main ends without that clean-up; the child ends with _exit).
  ScratchDir dir("stoneskip_hdf5_full");
  const auto path = dir.dir / "big.h5";
  int fds[2];
  BOOST_REQUIRE(::pipe(fds) == 0);
  const pid_t child = ::fork();
  BOOST_REQUIRE(child >= 0);
  if (child == 0) {
    ::close(fds[0]);
    rlimit old{};
    ::getrlimit(RLIMIT_FSIZE, &old);
    const rlimit small{20000, old.rlim_max};
    std::signal(SIGXFSZ, SIG_IGN);
    ::setrlimit(RLIMIT_FSIZE, &small);
    std::string m;
    try {
      Hdf5Writer w(path);
      w.root().write_vector("big", std::vector<double>(1 << 20, 1.0));  // 8 MiB
      w.commit();
    } catch (const InputError& e) {
      m = e.what();
    } catch (const std::exception& e) {
      m = std::string("not an InputError: ") + e.what();
    }
    [[maybe_unused]] const auto n = ::write(fds[1], m.data(), m.size());
    ::_exit(0);
  }
  ::close(fds[1]);
  std::string message;
  char buf[512];
  for (ssize_t n; (n = ::read(fds[0], buf, sizeof buf)) > 0;) message.append(buf, static_cast<std::size_t>(n));
  ::close(fds[0]);
  int status = 0;
  ::waitpid(child, &status, 0);
  BOOST_TEST(WIFEXITED(status));
  BOOST_TEST(message.find(path.string() + ": cannot write the HDF5 file (File too large") == 0u, message);
  BOOST_TEST(!std::filesystem::exists(path));
  std::size_t left = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.dir)) ++left;
  BOOST_TEST(left == 0u);
}

BOOST_AUTO_TEST_CASE(an_attribute_of_many_values_read_as_one_is_an_error_not_a_stack_overwrite) {
  // main: attr_double, attr_int and attr_string read the whole attribute into one value, so a crafted
  // file's array of 1000 (a run file's `bounces`, read by `report front`) was written over the stack.
  // Oracle: the element count, which the library states; a scalar still reads.
  ScratchDir dir("stoneskip_hdf5_many");
  const auto path = dir.dir / "many.h5";
  {
    Hdf5Writer w(path);
    w.root().set_attr("one", 2.5);
    const hsize_t n = 1000;
    H5Id space(H5Screate_simple(1, &n, nullptr), H5Sclose);
    const std::vector<double> d(n, 1.0);
    const std::vector<long long> k(n, 7);
    H5Id a(H5Acreate2(w.root().id(), "d", H5T_NATIVE_DOUBLE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    BOOST_REQUIRE(H5Awrite(a.get(), H5T_NATIVE_DOUBLE, d.data()) >= 0);
    H5Id b(H5Acreate2(w.root().id(), "k", H5T_NATIVE_LLONG, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    BOOST_REQUIRE(H5Awrite(b.get(), H5T_NATIVE_LLONG, k.data()) >= 0);
    H5Id t = vlen_string_type();
    H5Id c(H5Acreate2(w.root().id(), "s", t.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    std::vector<const char*> texts(n, "many");
    BOOST_REQUIRE(H5Awrite(c.get(), t.get(), texts.data()) >= 0);
    w.commit();
  }
  const Hdf5Reader r(path);
  const auto error_of = [](const auto& read) {
    try {
      read();
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  BOOST_TEST(r.root().attr_double("one") == 2.5);
  BOOST_TEST(error_of([&] { r.root().attr_double("d"); }) == "HDF5: attribute d holds 1000 values, not one");
  BOOST_TEST(error_of([&] { r.root().attr_int("k"); }) == "HDF5: attribute k holds 1000 values, not one");
  BOOST_TEST(error_of([&] { r.root().attr_string("s"); }) == "HDF5: attribute s holds 1000 values, not one");
}

BOOST_AUTO_TEST_CASE(a_value_changed_in_a_files_metadata_is_an_error_not_read_as_stored) {
  // main wrote the library's earliest format, whose object headers carry no checksum: one bit of an
  // attribute (kept in its object's header) flipped on disk read back as another number. The 1.8
  // format's object headers end in a checksum the library verifies (HDF5 File Format Specification,
  // version 2 object header, "Checksum"). Oracle: that checksum; the value's bytes are found by
  // their pattern (once in the file), and the file as written reads back exactly. (A dataset's
  // values are raw data, which no HDF5 format checksums: the Fletcher-32 filter does, below.)
  ScratchDir dir("stoneskip_hdf5_checksum");
  const auto path = dir.dir / "sums.h5";
  const double value = 1234.5678901234;
  {
    Hdf5Writer w(path);
    w.root().create_group("g").set_attr("x", value);
    w.commit();
  }
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  BOOST_REQUIRE(bytes.size() > 9);
  BOOST_TEST(static_cast<int>(bytes[8]) == 2);  // the superblock's version: 2, the 1.8 format's (checksummed)
  const std::string pattern(reinterpret_cast<const char*>(&value), sizeof value);
  const std::size_t at = bytes.find(pattern);
  BOOST_REQUIRE(at != std::string::npos);
  BOOST_REQUIRE(bytes.find(pattern, at + 1) == std::string::npos);
  BOOST_TEST(Hdf5Reader(path).root().open_group("g").attr_double("x") == value);
  bytes[at] = static_cast<char>(bytes[at] ^ 0x01);  // the lowest bit of the mantissa: 1234.5678901234002
  const auto bad = dir.dir / "flipped.h5";
  std::ofstream(bad, std::ios::binary) << bytes;
  std::string read = "no error";
  try {
    read = std::to_string(Hdf5Reader(bad).root().open_group("g").attr_double("x"));
  } catch (const std::exception& e) {
    read = std::string("error: ") + e.what();
  }
  BOOST_TEST(read.rfind("error: ", 0) == 0u, read);
}

BOOST_AUTO_TEST_CASE(a_value_changed_in_a_datasets_raw_data_is_an_error_not_read_as_stored) {
  // A table's, a vector's, an integer list's and a 3-D array's values are raw data. main wrote
  // them contiguous and unchecked: one bit flipped on disk read back as another number. Each is now
  // written in chunks with the Fletcher-32 checksum, which the library verifies on reading (HDF5
  // User's Guide, "Filters"). Oracle: that checksum; each value's bytes are found by their pattern
  // (once in the file), and the file as written reads back exactly.
  ScratchDir dir("stoneskip_hdf5_raw_checksum");
  const auto path = dir.dir / "raw.h5";
  const double in_table = 2345.6789012345, in_vector = 3456.7890123456;
  const long long in_ints = 0x0123456789abcdefLL;
  const float in_floats = 4567.891f;
  {
    Hdf5Writer w(path);
    H5Group g = w.root().create_group("g");
    Table t;
    t.columns = {"a_m", "b_s"};
    t.add_row({1.0, in_table});
    t.add_row({3.0, 4.0});
    g.write_table("t", t);
    g.write_vector("v", {5.0, in_vector, 6.0});
    g.write_ints("i", {7, in_ints});
    g.write_floats_3d("f", {1.0f, 2.0f, in_floats, 3.0f}, {1, 2, 2}, "m");
    g.write_table("empty", Table{{"x_m"}, {}});  // no values: no chunk, nothing to check, still read
    w.commit();
  }
  std::string bytes;
  {
    std::ifstream in(path, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  {
    const Hdf5Reader r(path);
    const H5Group g = r.root().open_group("g");
    BOOST_TEST(g.read_table("t").column("b_s")[0] == in_table);
    BOOST_TEST(g.read_vector("v")[1] == in_vector);
    BOOST_TEST(g.read_ints("i")[1] == in_ints);
    BOOST_TEST(g.read_vector("f")[2] == double(in_floats));
    BOOST_TEST(g.read_table("empty").rows() == 0u);
  }
  auto pattern_of = [](const void* p, std::size_t n) { return std::string(static_cast<const char*>(p), n); };
  const std::vector<std::pair<std::string, std::string>> cases = {{"t", pattern_of(&in_table, sizeof in_table)},
                                                                   {"v", pattern_of(&in_vector, sizeof in_vector)},
                                                                   {"i", pattern_of(&in_ints, sizeof in_ints)},
                                                                   {"f", pattern_of(&in_floats, sizeof in_floats)}};
  for (const auto& [name, pattern] : cases) {
    const std::size_t at = bytes.find(pattern);
    BOOST_REQUIRE_MESSAGE(at != std::string::npos, name);
    BOOST_REQUIRE_MESSAGE(bytes.find(pattern, at + 1) == std::string::npos, name);
    std::string flipped = bytes;
    flipped[at] = static_cast<char>(flipped[at] ^ 0x01);  // the value's lowest bit
    const auto bad = dir.dir / ("flipped_" + name + ".h5");
    std::ofstream(bad, std::ios::binary) << flipped;
    std::string read = "no error";
    try {
      const Hdf5Reader r(bad);
      const H5Group g = r.root().open_group("g");
      if (name == "t") read = std::to_string(g.read_table("t").column("b_s")[0]);
      if (name == "v") read = std::to_string(g.read_vector("v")[1]);
      if (name == "i") read = std::to_string(g.read_ints("i")[1]);
      if (name == "f") read = std::to_string(g.read_vector("f")[2]);  // all four, converted to double
    } catch (const std::exception& e) {
      read = std::string("error: ") + e.what();
    }
    BOOST_TEST(read.rfind("error: ", 0) == 0u, name << ": " << read);
  }
}

BOOST_AUTO_TEST_SUITE_END()
