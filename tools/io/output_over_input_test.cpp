// An output that is one of the command's inputs, or a folder holding one, is refused however it is
// spelt. Oracles: paths made here whose identity is known by construction (the same file through
// "./", "..", a symbolic link and a hard link; a folder two levels above the input; a sibling whose
// name only starts like the folder's).
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tools/io/scratch_dir.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/output_over_input.hpp"
#include "tools/io/shipped_files.hpp"

using namespace stoneskip;
namespace fs = std::filesystem;

namespace {

struct Scratch : ScratchDir {
  Scratch() : ScratchDir("stoneskip_over_input") {
    fs::create_directories(dir / "sp1" / "deep");
    fs::create_directories(dir / "sp10");
    std::ofstream(dir / "case.toml") << "x\n";
    std::ofstream(dir / "sp1" / "deep" / "results.h5") << "x\n";
    std::ofstream(dir / "sp10" / "results.h5") << "x\n";
  }
};

// The refusal's message, or "" if the output is allowed.
std::string refusal(const fs::path& out, OutputKind kind, const fs::path& input) {
  try {
    refuse_output_over_inputs(out, kind, {input});
    return "";
  } catch (const InputError& e) {
    return e.what();
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(output_over_input)

BOOST_AUTO_TEST_CASE(the_input_under_any_spelling_is_refused_as_an_output_file) {
  Scratch s;
  const fs::path in = s.dir / "case.toml";
  BOOST_TEST(refusal(in, OutputKind::file, in).find("is the input") != std::string::npos);
  BOOST_TEST(!refusal(s.dir / "." / "case.toml", OutputKind::file, in).empty());
  BOOST_TEST(!refusal(s.dir / "sp1" / ".." / "case.toml", OutputKind::file, in).empty());
  fs::create_symlink(in, s.dir / "link.toml");
  BOOST_TEST(!refusal(s.dir / "link.toml", OutputKind::file, in).empty());
  fs::create_hard_link(in, s.dir / "hard.toml");
  BOOST_TEST(!refusal(s.dir / "hard.toml", OutputKind::file, in).empty());
  // Another name, existing or not, is no input.
  BOOST_TEST(refusal(s.dir / "case.h5", OutputKind::file, in).empty());
  BOOST_TEST(refusal(s.dir / "sp10" / "results.h5", OutputKind::file, in).empty());
}

BOOST_AUTO_TEST_CASE(a_folder_holding_the_input_is_refused_a_sibling_is_not) {
  Scratch s;
  const fs::path in = s.dir / "sp1" / "deep" / "results.h5";
  const std::string why = refusal(s.dir / "sp1", OutputKind::folder, in);
  BOOST_TEST(why.find("holds the input") != std::string::npos, why);
  BOOST_TEST(why.find("--out") == 0u, why);
  BOOST_TEST(!refusal(s.dir / "sp1" / "deep", OutputKind::folder, in).empty());
  BOOST_TEST(!refusal(s.dir, OutputKind::folder, in).empty());
  BOOST_TEST(refusal(s.dir / "sp10", OutputKind::folder, in).empty());  // "sp10" only starts like "sp1"
  BOOST_TEST(refusal(s.dir / "sp1" / "other", OutputKind::folder, in).empty());
  // An output file is not a folder: a file named like a parent is simply another name.
  BOOST_TEST(refusal(s.dir / "sp2", OutputKind::file, in).empty());
}

BOOST_AUTO_TEST_CASE(a_shipped_case_read_from_elsewhere_is_not_in_the_current_folder) {
  // Oracle: tools/io/shipped_files.hpp — from a folder without cases/, "cases/captures/x.log" is
  // read from the shipped cases, so an output folder here does not hold it (main refused `--out .`
  // naming that input as inside "."); where the name exists here it is that file, and is held.
  Scratch s;
  WorkingFolder there(s.dir);
  const fs::path shipped = "cases/captures/gentle_sidearm.log";
  BOOST_REQUIRE(!fs::exists(shipped));
  BOOST_REQUIRE(!shipped_cases_dir().empty());  // the test binary knows the source tree
  BOOST_TEST(refusal(".", OutputKind::folder, shipped).empty());
  BOOST_TEST(refusal("cases", OutputKind::folder, shipped).empty());
  fs::create_directories("cases/captures");
  std::ofstream(shipped) << "x\n";
  BOOST_TEST(!refusal(".", OutputKind::folder, shipped).empty());
}

BOOST_AUTO_TEST_CASE(two_outputs_of_one_command_under_any_spelling_are_refused) {
  // Oracle: names made here, the same file by construction ("./", "..", a symbolic link) or not.
  Scratch s;
  auto why = [](const fs::path& a, const fs::path& b) {
    try {
      refuse_same_output(a, "--out", b, "--movie");
      return std::string();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
  };
  const fs::path movie = s.dir / "m.mp4";
  const std::string same = why(movie, movie);  // neither exists yet: still the same name
  BOOST_TEST(same.find("--out") == 0u, same);
  BOOST_TEST(same.find("also the --movie file") != std::string::npos, same);
  BOOST_TEST(!why(s.dir / "sp1" / ".." / "m.mp4", movie).empty());
  std::ofstream(movie) << "x\n";
  fs::create_symlink(movie, s.dir / "link.mp4");
  BOOST_TEST(!why(s.dir / "link.mp4", movie).empty());
  BOOST_TEST(why(s.dir / "m.h5", movie).empty());
  BOOST_TEST(why(s.dir / "m.h5", "").empty());  // no second output
}

BOOST_AUTO_TEST_SUITE_END()
