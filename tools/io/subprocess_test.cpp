// A program started by run_program gets its arguments as data, never as a command. Oracles: what
// coreutils print for the arguments they are given (printf '%s\n' echoes each one byte for byte,
// pwd names the working folder), their documented exit statuses, and the absence of a file that a
// shell would have made from the words `$(touch PWNED)`.
#include <boost/test/unit_test.hpp>

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "tools/io/scratch_dir.hpp"
#include "tools/io/subprocess.hpp"

using namespace stoneskip;
namespace fs = std::filesystem;

namespace {

struct Scratch : ScratchDir {
  Scratch() : ScratchDir("stoneskip_subprocess") {}
};

// Words a shell would act on: quotes, a command separator, substitutions, a newline, an option.
const std::vector<std::string> kHostileWords = {"z'; touch PWNED; echo '", "\"; touch PWNED; \"", "$(touch PWNED)",
                                                "`touch PWNED`", "a\nb", "-n", "x > PWNED"};

}  // namespace

BOOST_AUTO_TEST_SUITE(subprocess)

BOOST_AUTO_TEST_CASE(hostile_words_reach_the_program_byte_for_byte_and_run_nothing) {
  // Oracle: printf '%s\n' prints each argument followed by a newline, so the output is the words
  // joined by newlines exactly; a shell would have run `touch` and made PWNED in the working folder.
  Scratch s;
  SubprocessOptions o;
  o.working_dir = s.dir;
  std::vector<std::string> argv = {"printf", "%s\\n"};
  std::string expected;
  for (const auto& w : kHostileWords) {
    argv.push_back(w);
    expected += w + "\n";
  }
  const SubprocessResult r = run_program(argv, o);
  BOOST_TEST(r.ok());
  BOOST_TEST(r.out == expected);
  BOOST_TEST(!fs::exists(s.dir / "PWNED"));
  BOOST_TEST(!fs::exists("PWNED"));
}

BOOST_AUTO_TEST_CASE(the_child_starts_in_the_working_folder_and_reads_an_empty_stdin) {
  // Oracle: pwd prints the canonical working folder; cat copies stdin, which is /dev/null (empty:
  // it returns at once instead of waiting on the test's terminal).
  Scratch s;
  SubprocessOptions o;
  o.working_dir = s.dir;
  BOOST_TEST(run_program({"pwd", "-P"}, o).out == fs::canonical(s.dir).string() + "\n");
  const SubprocessResult cat = run_program({"cat"});
  BOOST_TEST(cat.ok());
  BOOST_TEST(cat.out.empty());
}

BOOST_AUTO_TEST_CASE(exit_status_and_stderr_come_back_apart_merged_or_dropped) {
  // Oracle: `false` exits 1; `ls` of a missing name exits 2 and writes its complaint on stderr only.
  BOOST_TEST(run_program({"false"}).exit_status == 1);
  BOOST_TEST(run_program({"true"}).ok());
  const std::string missing = "/no/such/stoneskip_file";
  const SubprocessResult apart = run_program({"ls", missing});
  BOOST_TEST(apart.exit_status == 2);
  BOOST_TEST(apart.out.empty());
  BOOST_TEST(apart.err.find(missing) != std::string::npos);
  SubprocessOptions merged;
  merged.stderr_to = SubprocessOptions::Stderr::merged;
  BOOST_TEST(run_program({"ls", missing}, merged).out.find(missing) != std::string::npos);
  SubprocessOptions dropped;
  dropped.stderr_to = SubprocessOptions::Stderr::discarded;
  const SubprocessResult d = run_program({"ls", missing}, dropped);
  BOOST_TEST(d.out.empty());
  BOOST_TEST(d.err.empty());
}

BOOST_AUTO_TEST_CASE(lines_are_handed_to_the_callback_one_by_one) {
  // Oracle: printf 'a\nb\r\nc' is three lines, the last without its newline, the CR dropped.
  std::vector<std::string> lines;
  SubprocessOptions o;
  o.on_line = [&](const std::string& l) { lines.push_back(l); };
  const SubprocessResult r = run_program({"printf", "a\nb\r\nc"}, o);
  BOOST_TEST(r.ok());
  BOOST_TEST(r.out.empty());
  BOOST_TEST((lines == std::vector<std::string>{"a", "b", "c"}));
}

BOOST_AUTO_TEST_CASE(a_missing_program_or_folder_is_a_clear_failure_not_a_status) {
  // Oracle: no program of this name exists in PATH, and no such folder exists.
  const SubprocessResult r = run_program({"stoneskip-no-such-program", "--version"});
  BOOST_TEST(!r.started);
  BOOST_TEST(r.error == "stoneskip-no-such-program: not found");
  BOOST_TEST(!program_runs({"stoneskip-no-such-program"}));
  SubprocessOptions o;
  o.working_dir = "/no/such/stoneskip_folder";
  const SubprocessResult d = run_program({"true"}, o);
  BOOST_TEST(!d.started);
  BOOST_TEST(d.error.find("/no/such/stoneskip_folder") != std::string::npos);
  BOOST_TEST(!run_program({}).started);
}

BOOST_AUTO_TEST_CASE(a_child_past_its_time_limit_is_killed) {
  // Oracle: sleep 30 cannot end by itself within the 0.2 s limit; killed, it ends by SIGKILL, and
  // the call returns long before 30 s (10 s allows a loaded machine).
  SubprocessOptions o;
  o.timeout_s = 0.2;
  const auto t0 = std::chrono::steady_clock::now();
  const SubprocessResult r = run_program({"sleep", "30"}, o);
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  BOOST_TEST(r.timed_out);
  BOOST_TEST(r.signal == SIGKILL);
  BOOST_TEST(!r.ok());
  BOOST_TEST(wall_s < 10.0);
}

BOOST_AUTO_TEST_CASE(a_relative_name_starting_with_a_dash_is_made_a_path) {
  // Oracle: "./-x" names the same file as "-x" and cannot be read as an option; other names are
  // left as they are.
  BOOST_TEST(safe_file_argument("-x.gp") == "./-x.gp");
  BOOST_TEST(safe_file_argument("-y.mp4") == "./-y.mp4");
  BOOST_TEST(safe_file_argument("a/-y.mp4") == "a/-y.mp4");
  BOOST_TEST(safe_file_argument("/tmp/-y.mp4") == "/tmp/-y.mp4");
  BOOST_TEST(safe_file_argument("plain.gp") == "plain.gp");
  // And a program sees it as a file: ls names it instead of refusing an option.
  Scratch s;
  SubprocessOptions o;
  o.working_dir = s.dir;
  BOOST_TEST(run_program({"touch", safe_file_argument("-x.gp")}, o).ok());
  BOOST_TEST(fs::exists(s.dir / "-x.gp"));
}

BOOST_AUTO_TEST_SUITE_END()
