// What a report build leaves when it stops (issue 10, items 8 and 10; reports/README.md "Reports"). Oracle:
// the folders on disk afterwards — a build stopped by an error before any section was finished
// leaves nothing (main left an empty work folder: exit 2 with a folder); one with finished
// sections keeps its work folder to be resumed, and the next build resumes them; a finished build
// leaves only the report. (Signals are sent to the command in tools/cli/signal_test.cpp.)
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "reports/common/report_build.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/signal_cleanup.hpp"

namespace stoneskip {
namespace {

namespace fs = std::filesystem;

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("report_build_" + std::to_string(::getpid()));
  Scratch() {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~Scratch() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

ReportBuildOptions options(const fs::path& out) { return ReportBuildOptions{out, "waves", "settings", "test", {}}; }

Record section(double v) {
  Record r;
  r.set("value", v);
  return r;
}

BOOST_AUTO_TEST_SUITE(report_build)

BOOST_AUTO_TEST_CASE(an_error_before_any_section_leaves_no_folder) {
  Scratch s;
  const fs::path out = s.dir / "out";
  const int registered = registered_temporary_count();
  try {
    ReportBuild b(options(out));
    BOOST_TEST(fs::is_directory(b.work_dir()));
    BOOST_TEST(registered_temporary_count() == registered + 1);  // the signal cleanup would remove it
    throw InputError("a bad case found late");
  } catch (const InputError&) {
  }
  BOOST_TEST(fs::is_empty(s.dir));
  BOOST_TEST(registered_temporary_count() == registered);
}

BOOST_AUTO_TEST_CASE(finished_sections_survive_an_error_and_are_resumed) {
  Scratch s;
  const fs::path out = s.dir / "out";
  try {
    ReportBuild b(options(out));
    b.store("first", section(1.5));
    throw std::runtime_error("an internal error in the second section");
  } catch (const std::runtime_error&) {
  }
  BOOST_TEST(fs::is_directory(s.dir / "out.partial"));
  BOOST_TEST(!fs::exists(out));
  {
    ReportBuild b(options(out));
    const auto resumed = b.resume("first");
    BOOST_REQUIRE(resumed.has_value());
    BOOST_TEST(resumed->number("value") == 1.5);
    b.store("second", section(2.5));
    b.assemble(Record{});
    b.commit();
  }
  BOOST_TEST(fs::is_regular_file(out / "data.h5"));
  BOOST_TEST(!fs::exists(s.dir / "out.partial"));
  BOOST_TEST(!fs::exists(out / "sections"));
  BOOST_TEST(is_report_folder(out));
}

BOOST_AUTO_TEST_CASE(a_file_link_or_empty_name_as_the_folder_is_refused_before_anything_is_made) {
  Scratch s;
  { std::ofstream(s.dir / "afile") << "x"; }
  fs::create_symlink(s.dir / "elsewhere", s.dir / "alink");
  for (const fs::path& p : {s.dir / "afile", s.dir / "alink", fs::path()}) {
    BOOST_TEST_CONTEXT(p) {
      BOOST_CHECK_THROW(ReportBuild b(options(p)), InputError);
    }
  }
  BOOST_TEST(!fs::exists(s.dir / "afile.partial"));
  BOOST_TEST(!fs::exists(s.dir / "alink.partial"));
  BOOST_TEST(fs::is_symlink(s.dir / "alink"));
}

BOOST_AUTO_TEST_CASE(a_report_folder_with_anything_of_the_users_in_it_is_not_replaced) {
  // Oracle: the files a report writes (index.md, data.h5, figures/ of .png/.svg/.gp/.dat); one
  // more file of any other name, a link among the figures or a folder inside figures/ makes the
  // folder the user's, and a build refuses to replace it.
  Scratch s;
  const fs::path out = s.dir / "rep";
  {
    ReportBuild b(options(out));
    b.store("first", section(1.5));
    b.assemble(Record{});
    b.commit();
  }
  fs::create_directories(out / "figures");
  std::ofstream(out / "figures" / "a.png") << "png";
  std::ofstream(out / "figures" / "a.png.tmp-123") << "left by a killed render";
  std::ofstream(out / "index.md") << "# report\n";
  BOOST_TEST(is_report_folder(out));
  std::ofstream(out / "notes.txt") << "mine\n";
  BOOST_TEST(!is_report_folder(out));
  BOOST_CHECK_THROW(ReportBuild b(options(out)), InputError);
  BOOST_TEST(fs::exists(out / "notes.txt"));
  fs::remove(out / "notes.txt");
  fs::create_symlink(s.dir / "elsewhere.png", out / "figures" / "b.png");
  BOOST_TEST(!is_report_folder(out));
  fs::remove(out / "figures" / "b.png");
  fs::create_directory(out / "figures" / "mine");
  BOOST_TEST(!is_report_folder(out));
  fs::remove(out / "figures" / "mine");
  BOOST_TEST(is_report_folder(out));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
