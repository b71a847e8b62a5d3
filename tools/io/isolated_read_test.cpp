// read_in_child_first (isolated_read.hpp). Oracles: the child's fate, made on purpose — a read that
// crashes (SIGSEGV raised), one that exits, one that never ends (a 0.3 s limit), one that throws,
// one that succeeds — and the contract that the caller's own state is not touched by the child's read;
// the output variant's bytes, bound and time.
#include "tools/io/isolated_read.hpp"

#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "tools/io/input_error.hpp"

namespace stoneskip {
namespace {

// The message of the InputError read_in_child_first throws, or "" when it returns.
std::string refusal(const std::function<void()>& read, double timeout_s = 5) {
  try {
    read_in_child_first("damaged.h5", read, IsolatedReadOptions{timeout_s});
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

BOOST_AUTO_TEST_SUITE(isolated_read)

BOOST_AUTO_TEST_CASE(a_read_that_crashes_or_never_ends_is_refused_naming_the_file) {
  const std::string crashed = refusal([] { std::raise(SIGSEGV); });
  BOOST_TEST(crashed == "damaged.h5: is a damaged HDF5 file: reading it crashed the HDF5 library (signal 11, SIGSEGV); nothing was written");
  const std::string aborted = refusal([] { std::abort(); });
  BOOST_TEST(aborted.find("(signal 6, SIGABRT)") != std::string::npos, aborted);
  // An exit from inside the read (ASan ends a process with status 1 on a heap overflow in the HDF5
  // library; the first report of this was a sanitized build reading a damaged sweep file).
  const std::string exited = refusal([] { std::_Exit(1); });
  BOOST_TEST(exited == "damaged.h5: is a damaged HDF5 file: reading it ended the reading process with exit status 1 (inside the HDF5 library); nothing was written");
  // Limit 0.3 s: the child is killed after it, not waited for.
  const std::string looped = refusal(
      [] {
        volatile long i = 0;
        for (;;) i = i + 1;
      },
      0.3);
  BOOST_TEST(looped == "damaged.h5: is a damaged HDF5 file: reading it did not end within 0.3 s (the HDF5 library loops on it); nothing was written");
}

BOOST_AUTO_TEST_CASE(a_read_that_ends_or_throws_leaves_the_caller_to_read_and_changes_nothing_here) {
  int touched = 0;
  BOOST_TEST(refusal([&] { touched = 1; }) == "");
  BOOST_TEST(touched == 0);  // the child's memory, not ours
  BOOST_TEST(refusal([] { throw std::runtime_error("not a sweep result file"); }) == "");
  BOOST_TEST(refusal([] { throw InputError("x"); }) == "");
}

BOOST_AUTO_TEST_CASE(what_the_child_writes_comes_back_whole_and_within_its_bound) {
  // Oracle: the bytes written, and the bound's contract (past it, a refusal naming the bound).
  const auto write_n = [](std::size_t n) {
    return [n](int fd) {
      const std::string chunk(1000, 'x');
      for (std::size_t left = n; left > 0;) {
        const std::size_t k = std::min(left, chunk.size());
        if (::write(fd, chunk.data(), k) != static_cast<ssize_t>(k)) std::_Exit(3);
        left -= k;
      }
    };
  };
  // 300 000 bytes: more than a pipe holds (64 KiB), so the caller must read while the child writes.
  const auto got = read_in_child_first("big.h5", write_n(300000), 300000, IsolatedReadOptions{5});
  BOOST_REQUIRE(got.has_value());
  BOOST_TEST(*got == std::string(300000, 'x'));
  try {
    read_in_child_first("big.h5", write_n(300001), 300000, IsolatedReadOptions{5});
    BOOST_ERROR("past the bound, not refused");
  } catch (const InputError& e) {
    BOOST_TEST(std::string(e.what()) == "big.h5: is a damaged HDF5 file: its strings come to more than 300000 bytes; nothing was written");
  }
  // The child knows it is one (a reader there reads for itself, hdf5_strings_apart.hpp); we are not.
  const auto flag = read_in_child_first("f.h5", [](int fd) { (void)!::write(fd, in_isolated_child() ? "1" : "0", 1); }, 10);
  BOOST_TEST(flag.value_or("") == "1");
  BOOST_TEST(!in_isolated_child());
  // A child that writes for ever is stopped at its time, not read for ever.
  try {
    read_in_child_first("loop.h5", [](int fd) { for (;;) (void)!::write(fd, "y", 1); }, std::size_t{1} << 40, IsolatedReadOptions{0.3});
    BOOST_ERROR("a child writing for ever was not stopped");
  } catch (const InputError& e) {
    BOOST_TEST(std::string(e.what()).find("did not end within 0.3 s") != std::string::npos, e.what());
  }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
