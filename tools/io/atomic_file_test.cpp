// Atomic outputs replace nothing but a regular file, and inputs that are not regular files are
// named for what they are. Oracles: the file types
// made here with mkfifo, mknod and symlink (lstat says what they are), and the POSIX rename rule
// that a rename replaces whatever the destination name is — so a refusal must come first.
#include <boost/test/unit_test.hpp>

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tools/io/scratch_dir.hpp"
#include "tools/io/atomic_file.hpp"
#include "tools/io/hdf5_file.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/signal_cleanup.hpp"

using namespace stoneskip;
namespace fs = std::filesystem;

namespace {

struct Scratch : ScratchDir {
  Scratch() : ScratchDir("stoneskip_atomic") {}
};

std::string refusal(const fs::path& p) {
  try {
    write_text_file(p, "text");
    return "";
  } catch (const InputError& e) {
    return e.what();
  }
}

unsigned type_of(const fs::path& p) {
  struct stat st {};
  ::lstat(p.c_str(), &st);
  return st.st_mode & S_IFMT;
}

bool no_temporaries(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().find(".tmp-") != std::string::npos) return false;
  return true;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(atomic_outputs)

BOOST_AUTO_TEST_CASE(only_a_regular_file_is_ever_replaced) {
  // Oracle: lstat before and after. A FIFO, a character device (a copy of /dev/null's numbers,
  // made with mknod when we are root: the machine's own /dev/null is never touched), a symbolic
  // link to either and a folder keep their type; a regular file is replaced by the new text.
  Scratch s;
  const fs::path fifo = s.dir / "fifo", dev = s.dir / "null", link = s.dir / "link", folder = s.dir / "folder";
  BOOST_REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
  const bool root = ::geteuid() == 0;
  if (root) BOOST_REQUIRE(::mknod(dev.c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0);
  fs::create_symlink(root ? dev : fifo, link);
  fs::create_directories(folder);
  struct Case {
    fs::path path;
    unsigned type;
    std::string words;
  };
  std::vector<Case> cases = {{fifo, S_IFIFO, "a FIFO"}, {link, S_IFLNK, "a symbolic link"}, {folder, S_IFDIR, "a folder"}};
  if (root) cases.push_back({dev, S_IFCHR, "a character device"});
  for (const auto& c : cases) {
    BOOST_TEST_CONTEXT(c.path) {
      const std::string e = refusal(c.path);
      BOOST_TEST(e.find(c.path.string()) == 0u, e);
      BOOST_TEST(e.find(c.words) != std::string::npos, e);
      BOOST_TEST(type_of(c.path) == c.type);
      BOOST_TEST(e.find('\n') == std::string::npos);
    }
  }
  BOOST_TEST(no_temporaries(s.dir));
  const fs::path regular = s.dir / "plain.txt";
  { std::ofstream(regular) << "old"; }
  BOOST_TEST(refusal(regular) == "");
  std::ifstream in(regular);
  std::string got;
  std::getline(in, got);
  BOOST_TEST(got == "text");
}

BOOST_AUTO_TEST_CASE(a_replaced_file_keeps_its_permissions_and_a_read_only_one_is_kept) {
  // Oracle: stat before and after. The new text goes in with the old mode bits (0600 stays 0600).
  // A file nobody may write is refused and left as it was: `regress --update` replaced a 0444
  // baseline until December 5 (the move into place needs only the folder's permission).
  Scratch s;
  const fs::path f = s.dir / "baseline.toml";
  write_text_file(f, "old\n");
  BOOST_REQUIRE(::chmod(f.c_str(), 0600) == 0);
  write_text_file(f, "new\n");
  struct stat st {};
  BOOST_REQUIRE(::stat(f.c_str(), &st) == 0);
  BOOST_TEST((st.st_mode & 07777) == 0600u);
  BOOST_TEST(read_text_file(f) == "new\n");
  BOOST_REQUIRE(::chmod(f.c_str(), 0444) == 0);
  BOOST_TEST(refusal(f).find("is read-only (mode 0444): refusing to replace it") != std::string::npos, refusal(f));
  BOOST_TEST(read_text_file(f) == "new\n");
}

BOOST_AUTO_TEST_CASE(an_unwritable_place_is_refused_before_any_work) {
  // Oracle: what the kernel says when a file is created there. The output is opened (its
  // temporary created) in the constructor, so the error comes before the caller computes
  // anything; an empty name and a missing folder are named as such.
  Scratch s;
  auto error_of = [](const fs::path& p) {
    try {
      AtomicOutput o(p);
      return std::string();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
  };
  BOOST_TEST(error_of("").find("an output file name is required") != std::string::npos);
  BOOST_TEST(error_of(s.dir / "none" / "x.h5").find("does not exist") != std::string::npos);
  BOOST_TEST(error_of("/proc/stoneskip_cannot_exist.h5").find("cannot write in folder '/proc'") != std::string::npos);
  const fs::path file = s.dir / "afile";
  { std::ofstream(file) << "x"; }
  BOOST_TEST(error_of(file / "x.h5").find("not a folder") != std::string::npos);
  // The temporary exists while the output is open, is registered for the signal cleanup, and is
  // gone (unregistered) when the output is dropped uncommitted.
  const int registered = registered_temporary_count();
  {
    AtomicOutput o(s.dir / "out.h5");
    BOOST_TEST(fs::is_regular_file(o.temporary_path()));
    BOOST_TEST(registered_temporary_count() == registered + 1);
  }
  BOOST_TEST(registered_temporary_count() == registered);
  BOOST_TEST(no_temporaries(s.dir));
  BOOST_TEST(!fs::exists(s.dir / "out.h5"));
}

BOOST_AUTO_TEST_CASE(a_destination_turned_into_a_fifo_before_commit_is_not_replaced) {
  // Oracle: the type checked again at commit: a FIFO made after the output was opened survives,
  // and the temporary is removed.
  Scratch s;
  const fs::path p = s.dir / "late";
  {
    Hdf5Writer w(p);
    w.root().set_attr("x", 1.0);
    BOOST_REQUIRE(::mkfifo(p.c_str(), 0644) == 0);
    BOOST_CHECK_THROW(w.commit(), InputError);
  }
  BOOST_TEST(type_of(p) == static_cast<unsigned>(S_IFIFO));
  BOOST_TEST(no_temporaries(s.dir));
}

BOOST_AUTO_TEST_CASE(the_move_into_place_is_atomic_against_a_destination_changed_after_its_check) {
  // Oracle: what is at the name afterwards (lstat, the link's target, the files' texts). The check
  // and the move are apart in time; move_into_place is handed the check's answer (`replacing`) and
  // the name is changed here in between, as another program could: a link, a folder or a file
  // that appeared is left as it is, with the output kept under its temporary name; a regular file
  // is replaced, and a name emptied meanwhile is taken.
  Scratch s;
  auto text = [](const fs::path& p) {
    std::ifstream in(p);
    std::string t;
    std::getline(in, t);
    return t;
  };
  const fs::path tmp = s.dir / "out.tmp-1", out = s.dir / "out", someones = s.dir / "someones";
  auto ours = [&] { std::ofstream(tmp) << "ours"; };
  auto refused = [&](bool replacing, const std::string& words) {
    try {
      move_into_place(tmp, out, replacing);
    } catch (const InputError& e) {
      return std::string(e.what()).find(words) != std::string::npos;
    }
    return false;
  };
  { std::ofstream(someones) << "someone's"; }
  // Checked as a regular file, now a link to someone's file: not written through, not replaced.
  ours();
  fs::create_symlink(someones, out);
  BOOST_TEST(refused(true, "it became a symbolic link while the output was written"));
  BOOST_TEST(fs::is_symlink(fs::symlink_status(out)));
  BOOST_TEST(fs::read_symlink(out) == someones);
  BOOST_TEST(text(someones) == "someone's");
  BOOST_TEST(text(tmp) == "ours");
  fs::remove(out);
  // Checked as a regular file, now a folder.
  fs::create_directory(out);
  BOOST_TEST(refused(true, "it became a folder"));
  BOOST_TEST(fs::is_directory(fs::symlink_status(out)));
  BOOST_TEST(text(tmp) == "ours");
  fs::remove(out);
  // Checked as free, now a file: kept.
  { std::ofstream(out) << "appeared"; }
  BOOST_TEST(refused(false, "a regular file appeared at this name"));
  BOOST_TEST(text(out) == "appeared");
  BOOST_TEST(text(tmp) == "ours");
  // Checked as a regular file, still one: replaced, and nothing left under the temporary name.
  move_into_place(tmp, out, true);
  BOOST_TEST(text(out) == "ours");
  BOOST_TEST(!fs::exists(fs::symlink_status(tmp)));
  // Checked as a regular file, removed meanwhile: the free name is taken.
  fs::remove(out);
  ours();
  move_into_place(tmp, out, true);
  BOOST_TEST(text(out) == "ours");
  BOOST_TEST(!fs::exists(fs::symlink_status(tmp)));
}

BOOST_AUTO_TEST_CASE(inputs_that_are_not_regular_files_are_named_for_what_they_are) {
  // Oracle: lstat's type. A folder, a FIFO (never opened: reading it would wait forever) and a
  // character device are "not a regular file", a missing name is "no such file", and a file
  // above the caller's limit is refused by its size.
  Scratch s;
  const fs::path fifo = s.dir / "fifo";
  BOOST_REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
  auto error_of = [](const fs::path& p, std::size_t limit) {
    try {
      read_text_file(p, limit);
      return std::string();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
  };
  const std::size_t any = static_cast<std::size_t>(-1);
  BOOST_TEST(error_of(s.dir, any).find("it is a folder, not a regular file") != std::string::npos);
  BOOST_TEST(error_of(fifo, any).find("it is a FIFO, not a regular file") != std::string::npos);
  BOOST_TEST(error_of("/dev/zero", any).find("it is a character device, not a regular file") != std::string::npos);
  BOOST_TEST(error_of(s.dir / "missing.toml", any).find("no such file") != std::string::npos);
  const fs::path big = s.dir / "big.txt";
  { std::ofstream(big) << std::string(1000, 'x'); }
  BOOST_TEST(error_of(big, 999).find("larger than the limit of 999 bytes") != std::string::npos);
  BOOST_TEST(error_of(big, 1000) == "");
}

BOOST_AUTO_TEST_CASE(the_signal_cleanup_removes_registered_files_and_folders) {
  // Oracle: the file system afterwards. What the cleanup thread does on SIGINT before _exit
  // (remove every registered path, folders with all they hold, with system calls only) leaves
  // nothing of them; an unregistered file beside them stays. (The signal itself is sent to the
  // command in tools/cli/signal_test.cpp.)
  Scratch s;
  const fs::path folder = s.dir / "report.partial", file = s.dir / "x.h5.tmp-1", keep = s.dir / "keep";
  fs::create_directories(folder / "sections" / "deeper");
  for (int i = 0; i < 300; ++i) std::ofstream(folder / "sections" / ("s" + std::to_string(i) + ".h5")) << i;
  std::ofstream(folder / "sections" / "deeper" / "f") << 1;
  const fs::path outside = s.dir / "outside";
  fs::create_directories(outside);
  std::ofstream(outside / "canary") << 1;
  fs::create_symlink(outside, folder / "a_link_outside");  // removed as a link, never followed
  std::ofstream(file) << 1;
  std::ofstream(keep) << 1;
  {
    RegisteredTemporary a(folder, TemporaryKind::folder), b(file, TemporaryKind::file);
    BOOST_TEST(remove_registered_temporaries() == 2);
  }
  BOOST_TEST(!fs::exists(fs::symlink_status(folder)));
  BOOST_TEST(!fs::exists(file));
  BOOST_TEST(fs::exists(keep));
  BOOST_TEST(fs::exists(outside / "canary"));  // the link was not followed
}

BOOST_AUTO_TEST_CASE(an_atomic_folder_appears_whole_and_replaces_only_what_it_may) {
  // Oracle: the folder listing. Before commit only the registered work folder exists (and the
  // signal cleanup would remove it); an error removes it; commit puts it in place; an existing
  // folder is replaced only when empty or when the predicate says stoneskip made it.
  Scratch s;
  const auto ours = [](const fs::path& d) { return fs::is_regular_file(d / "index.md"); };
  const int registered = registered_temporary_count();
  {
    AtomicFolder f(s.dir / "page", ours);
    std::ofstream(f.work_dir() / "index.md") << "half";
    BOOST_TEST(registered_temporary_count() == registered + 1);
    BOOST_TEST(!fs::exists(s.dir / "page"));
  }  // destroyed before commit: an error
  BOOST_TEST(fs::is_empty(s.dir));
  BOOST_TEST(registered_temporary_count() == registered);
  for (const char* text : {"first", "second"}) {
    AtomicFolder f(s.dir / "page", ours);
    std::ofstream(f.work_dir() / "index.md") << text;
    f.commit();
  }
  std::ifstream in(s.dir / "page" / "index.md");
  std::string text;
  in >> text;
  BOOST_TEST(text == "second");
  fs::create_directories(s.dir / "theirs");
  std::ofstream(s.dir / "theirs" / "notes.txt") << "x";
  std::ofstream(s.dir / "afile") << "x";
  BOOST_CHECK_THROW(AtomicFolder(s.dir / "theirs", ours), InputError);
  BOOST_CHECK_THROW(AtomicFolder(s.dir / "afile", ours), InputError);
  BOOST_CHECK_THROW(AtomicFolder(s.dir / "nowhere" / "x", ours), InputError);
  BOOST_CHECK_THROW(AtomicFolder("", ours), InputError);
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(s.dir)) n += e.path().filename().string().find(".partial") == std::string::npos;
  BOOST_TEST(n == 3u);  // page, theirs, afile: no work folder left
  BOOST_TEST(std::distance(fs::directory_iterator(s.dir), fs::directory_iterator()) == 3);
  BOOST_TEST(registered_temporary_count() == registered);
}

BOOST_AUTO_TEST_CASE(a_name_near_the_file_systems_limit_is_written_through_a_shortened_temporary) {
  // A 250-byte name is a name the file system accepts (NAME_MAX 255), but "<name>.tmp-PID" is not:
  // such a file or folder was refused, "File name too long". Oracle: the folder listing, the file's
  // own text read back, and a multi-byte name (3-byte characters) cut at a character's start.
  Scratch s;
  const std::string ascii(250, 'a');
  std::string wide;
  while (wide.size() + 3 <= 252) wide += "\xe2\x82\xac";  // 84 euro signs, 252 bytes
  for (const std::string& name : {ascii, wide}) {
    write_text_file(s.dir / name, "text of " + std::to_string(name.size()));
    std::ifstream in(s.dir / name);
    std::string line;
    std::getline(in, line);
    BOOST_TEST(line == "text of " + std::to_string(name.size()));
    AtomicOutput o(s.dir / (name + "x").substr(0, 255));
    const std::string t = o.temporary_path().filename().string();
    BOOST_TEST(t.size() <= 255u, t.size());
    BOOST_TEST(t.find(".tmp-") != std::string::npos);
    // The cut leaves no partial character: every byte before ".tmp-" that starts a character does.
    const std::string kept = t.substr(0, t.find(".tmp-"));
    BOOST_TEST(name.compare(0, kept.size(), kept) == 0);
    BOOST_TEST((kept.size() == name.size() || (static_cast<unsigned char>(name[kept.size()]) & 0xC0) != 0x80));
  }
  const auto ours = [](const fs::path& d) { return fs::is_regular_file(d / "index.md"); };
  {
    AtomicFolder f(s.dir / ("d" + ascii.substr(1)), ours);
    std::ofstream(f.work_dir() / "index.md") << "page";
    f.commit();
  }
  BOOST_TEST(fs::is_regular_file(s.dir / ("d" + ascii.substr(1)) / "index.md"));
  BOOST_TEST(no_temporaries(s.dir));
  BOOST_TEST(std::distance(fs::directory_iterator(s.dir), fs::directory_iterator()) == 3);  // two files, one folder
  // A name past the limit is refused before any work, file or folder (a folder's shortened work
  // folder was filled, and only the final rename failed), and nothing is left behind.
  const std::string too_long(256, 'b');
  BOOST_CHECK_THROW(AtomicOutput(s.dir / too_long), InputError);
  BOOST_CHECK_THROW(AtomicFolder(s.dir / too_long, ours), InputError);
  BOOST_TEST(std::distance(fs::directory_iterator(s.dir), fs::directory_iterator()) == 3);
  // A companion's name (a sweep's journal) is shortened the same way, and the same every time.
  const fs::path journal = name_beside(s.dir / ascii, ".journal");
  BOOST_TEST(journal.filename().string().size() <= 255u);
  BOOST_TEST(journal == name_beside(s.dir / ascii, ".journal"));
  BOOST_TEST(name_beside(s.dir / "r.h5", ".journal") == s.dir / "r.h5.journal");  // short names unchanged
}

BOOST_AUTO_TEST_CASE(an_atomic_folder_moves_into_place_atomically_against_a_destination_changed_after_its_check) {
  // Oracle: what is at the name afterwards (lstat, the link's target, the files' texts). The check
  // (AtomicFolder's, at construction and at commit) and the move are apart in time; the name is
  // changed here in between, as another program could. A folder made by someone else, a link to
  // a folder and a file that appeared are left as they are, with the output still in its work
  // folder; an empty folder or one the predicate says stoneskip made is replaced; a free name is
  // taken. With the code before (the old folder renamed aside, the new one renamed in) 7 of these
  // checks fail: someone's folder, the link and the file are replaced.
  Scratch s;
  auto text = [](const fs::path& p) {
    std::ifstream in(p);
    std::string t;
    std::getline(in, t);
    return t;
  };
  const fs::path work = s.dir / "page.partial-1", out = s.dir / "page", theirs = s.dir / "theirs";
  const auto ours = [](const fs::path& d) { return fs::is_regular_file(d / "made-by-stoneskip"); };
  auto fill_work = [&] {
    fs::create_directories(work);
    std::ofstream(work / "index.md") << "ours";
  };
  auto refused = [&](const std::string& words) {
    try {
      move_folder_into_place(work, out, ours);
    } catch (const InputError& e) {
      return std::string(e.what()).find(words) != std::string::npos;
    }
    return false;
  };
  fs::create_directories(theirs);
  std::ofstream(theirs / "notes.txt") << "someone's";
  fill_work();
  // A free name is taken.
  BOOST_TEST((move_folder_into_place(work, out, ours) == FolderMove::placed));
  BOOST_TEST(text(out / "index.md") == "ours");
  BOOST_TEST(!fs::exists(fs::symlink_status(work)));
  fs::remove_all(out);
  // Someone's folder appeared: swapped, looked at, swapped back, refused.
  fill_work();
  fs::create_directories(out);
  std::ofstream(out / "notes.txt") << "someone's";
  BOOST_TEST(refused("is not one stoneskip made"));
  BOOST_TEST(text(out / "notes.txt") == "someone's");
  BOOST_TEST(!fs::exists(out / "index.md"));
  BOOST_TEST(text(work / "index.md") == "ours");
  fs::remove_all(out);
  // A link to someone's folder appeared: not followed, not replaced.
  fs::create_directory_symlink(theirs, out);
  BOOST_TEST(refused("a symbolic link appeared at this name"));
  BOOST_TEST(fs::is_symlink(fs::symlink_status(out)));
  BOOST_TEST(fs::read_symlink(out) == theirs);
  BOOST_TEST(text(theirs / "notes.txt") == "someone's");
  BOOST_TEST(text(work / "index.md") == "ours");
  fs::remove(out);
  // A file appeared.
  std::ofstream(out) << "appeared";
  BOOST_TEST(refused("a regular file appeared at this name"));
  BOOST_TEST(text(out) == "appeared");
  BOOST_TEST(text(work / "index.md") == "ours");
  fs::remove(out);
  // An empty folder, and then a folder stoneskip made, are replaced: the old one comes back at
  // the work folder's name for the caller to remove.
  fs::create_directories(out);
  BOOST_TEST((move_folder_into_place(work, out, ours) == FolderMove::swapped));
  BOOST_TEST(text(out / "index.md") == "ours");
  BOOST_TEST(fs::is_empty(work));
  fs::remove_all(work);
  std::ofstream(out / "made-by-stoneskip") << "";
  fill_work();
  std::ofstream(work / "index.md") << "newer";
  BOOST_TEST((move_folder_into_place(work, out, ours) == FolderMove::swapped));
  BOOST_TEST(text(out / "index.md") == "newer");
  BOOST_TEST(text(work / "index.md") == "ours");
}

BOOST_AUTO_TEST_SUITE_END()
