// What a report build leaves when it stops (reports/README.md "Reports"). Oracle:
// the folders on disk afterwards — a build stopped by an error before any section was finished
// leaves nothing (main left an empty work folder: exit 2 with a folder); one with finished
// sections keeps its work folder to be resumed, and the next build resumes them; a finished build
// leaves only the report. (Signals are sent to the command in tools/cli/signal_test.cpp.)
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "tools/io/scratch_dir.hpp"
#include "reports/common/report_build.hpp"
#include "tools/io/folder_manifest.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/signal_cleanup.hpp"

namespace stoneskip {
namespace {

namespace fs = std::filesystem;

struct Scratch : ScratchDir {
  Scratch() : ScratchDir("report_build") {}
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

BOOST_AUTO_TEST_CASE(a_resumed_build_ships_no_temporary_the_killed_run_left) {
  // A run killed while writing leaves "data.h5.tmp-PID" (or a figure's) in the work folder; the
  // resumed build once moved it into the report and listed it in the manifest (1.2 MB of truncated
  // HDF5). Oracle: the finished folder holds no temporary name and its manifest lists none.
  Scratch s;
  const fs::path out = s.dir / "out";
  try {
    ReportBuild b(options(out));
    b.store("first", section(1.5));
    throw std::runtime_error("killed");
  } catch (const std::runtime_error&) {
  }
  const fs::path work = s.dir / "out.partial";
  std::ofstream(work / "data.h5.tmp-24940") << "truncated";
  fs::create_directories(work / "figures");
  std::ofstream(work / "figures" / "a.png.tmp-24761-2") << "truncated";
  {
    ReportBuild b(options(out));
    BOOST_REQUIRE(b.resume("first").has_value());
    b.assemble(Record{});
    b.commit();
  }
  BOOST_TEST(!fs::exists(out / "data.h5.tmp-24940"));
  BOOST_TEST(!fs::exists(out / "figures" / "a.png.tmp-24761-2"));
  std::ifstream m(out / kFolderManifest);
  const std::string manifest((std::istreambuf_iterator<char>(m)), std::istreambuf_iterator<char>());
  BOOST_TEST(manifest.find(".tmp-") == std::string::npos, manifest);
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

BOOST_AUTO_TEST_CASE(a_trailing_slash_names_the_folder_and_the_current_folder_is_refused) {
  // Oracle: the folders on disk. `--out out/` names the folder out: its work folder is the sibling
  // out.partial and the report lands in out (main made out/.partial, inside the report's own
  // folder, and at commit refused out as "not a stoneskip report folder" after all the work). ".",
  // ".." and "/" name folders that hold more than the report: refused before anything is made.
  Scratch s;
  for (const std::string slash : {"/", "//", "/./"}) {
    BOOST_TEST_CONTEXT(slash) {
      const fs::path out = s.dir / ("out" + std::to_string(slash.size()));
      {
        ReportBuild b(options(fs::path(out.string() + slash)));
        b.store("a", section(1));
        b.assemble(Record{});
        BOOST_TEST(fs::exists(fs::path(out.string() + ".partial")));
        b.commit();
      }
      BOOST_TEST(is_report_folder(out));
      BOOST_TEST(!fs::exists(out / ".partial"));
      BOOST_TEST(!fs::exists(fs::path(out.string() + ".partial")));
    }
  }
  for (const fs::path& p : {fs::path("."), fs::path("./"), fs::path(".."), fs::path("../"), fs::path("/"), fs::path("a/.."), fs::path("a/../")}) {
    BOOST_TEST_CONTEXT(p) {
      BOOST_CHECK_THROW(ReportBuild b(options(p)), InputError);
    }
  }
  BOOST_TEST(!fs::exists("..partial"));  // what main made for "."
  BOOST_TEST(!fs::exists("../..partial"));
}

BOOST_AUTO_TEST_CASE(a_report_folder_with_anything_of_the_users_in_it_is_not_replaced) {
  // Oracle: the folder's manifest (tools/io/folder_manifest.hpp), written by commit(): what the
  // build wrote. A file of the user's dropped in — even one named like a figure, which a list of
  // report file names would take for the report's — a link, a folder, or an edit of a file the
  // build wrote makes the folder the user's, and a build refuses to replace it; with it gone (or a
  // temporary a killed writer left), the folder is replaced and its manifest written again.
  Scratch s;
  const fs::path out = s.dir / "rep";
  auto build = [&] {
    ReportBuild b(options(out));
    b.store("first", section(1.5));
    b.assemble(Record{});
    b.commit();
  };
  build();
  BOOST_TEST(fs::is_regular_file(out / kFolderManifest));
  BOOST_TEST(is_report_folder(out));
  std::ofstream(out / "data.h5.tmp-123") << "left by a killed writer";
  BOOST_TEST(is_report_folder(out));
  fs::create_directories(out / "figures");
  std::ofstream(out / "figures" / "mine.png") << "the user's plot";
  std::string why;
  BOOST_TEST(!holds_only_its_manifest(out, &why));
  BOOST_TEST(why.find("figures") != std::string::npos, why);
  BOOST_TEST(!is_report_folder(out));
  BOOST_CHECK_THROW(ReportBuild b(options(out)), InputError);
  BOOST_TEST(fs::exists(out / "figures" / "mine.png"));
  fs::remove_all(out / "figures");
  fs::create_symlink(s.dir / "elsewhere.png", out / "b.png");
  BOOST_TEST(!is_report_folder(out));
  fs::remove(out / "b.png");
  BOOST_TEST(is_report_folder(out));
  build();  // replaced: the temporary went with the old folder
  BOOST_TEST(!fs::exists(out / "data.h5.tmp-123"));
  BOOST_TEST(is_report_folder(out));
  // An edit of a file the build wrote (same size: the hash tells it) is the user's too.
  std::string data;
  {
    std::ifstream f(out / "data.h5", std::ios::binary);
    data.assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
  }
  data[data.size() / 2] ^= 0x01;
  std::ofstream(out / "data.h5", std::ios::binary | std::ios::trunc) << data;
  BOOST_TEST(!holds_only_its_manifest(out, &why));
  BOOST_TEST(why.find("changed") != std::string::npos, why);
  // A folder without a manifest (made by hand) is never stoneskip's.
  fs::remove(out / kFolderManifest);
  BOOST_TEST(!holds_only_its_manifest(out, &why));
  BOOST_TEST(why.find("no stoneskip manifest") != std::string::npos, why);
}

BOOST_AUTO_TEST_CASE(a_report_replaced_leaves_nothing_beside_it_and_a_folder_put_there_meanwhile_is_kept) {
  // Oracle: the listing of the parent folder. Replacing a report swaps the two folders and removes
  // the old one: only the report is left, no work or old folder beside it. A folder of someone
  // else's put at the name while the build runs is refused at commit() and left as it was.
  Scratch s;
  const fs::path out = s.dir / "rep";
  for (double v : {1.0, 2.0}) {
    ReportBuild b(options(out));
    b.store("first", section(v));
    b.assemble(Record{});
    b.commit();
  }
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(s.dir)) names.push_back(e.path().filename().string());
  BOOST_TEST(names == std::vector<std::string>{"rep"}, names.size());
  BOOST_TEST(is_report_folder(out));
  {
    ReportBuild b(options(out));
    b.store("first", section(3.0));
    b.assemble(Record{});
    fs::remove_all(out);
    fs::create_directories(out);
    std::ofstream(out / "notes.txt") << "someone's";
    BOOST_CHECK_THROW(b.commit(), InputError);
  }
  std::ifstream in(out / "notes.txt");
  std::string text;
  std::getline(in, text);
  BOOST_TEST(text == "someone's");
  BOOST_TEST(!fs::exists(out / "data.h5"));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
