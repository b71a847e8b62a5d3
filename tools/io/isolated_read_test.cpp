// read_in_child_first (isolated_read.hpp). Oracles: the child's fate, made on purpose — a read that
// crashes (SIGSEGV raised), one that exits, one that never ends (a 0.3 s limit), one that throws,
// one that succeeds — and the contract that the caller's own state is not touched by the child's read.
#include "tools/io/isolated_read.hpp"

#include <boost/test/unit_test.hpp>

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

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
