// Every command in the documents runs as written on the shipped cases. Oracle: the documents
// themselves — each `stoneskip` command in a ```sh or ```bash block of README.md or of a folder's
// README.md exits with status 0, or N where its comment says `exit N`. A command whose comment
// says `long` is skipped (the main job and the reports' own tests run that work), and so is
// anything that is not `stoneskip` (cmake, mpirun, srun, the quick start), each with its reason.
// Arguments are split on whitespace, no shell; a `*` in a file name is expanded as a shell would.
// The commands run in document order in one scratch folder holding links to `cases/` and `tools/`,
// so a command may read what an earlier one wrote and nothing lands in the checkout.
#include <boost/test/unit_test.hpp>

#include <fnmatch.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tools/cli/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using stoneskip::test::TempDir;

// A command may run this long; the cheap ones take under 15 s on a loaded 2-core machine.
constexpr int kCommandTimeout_s = 120;

struct DocCommand {
  std::string doc;    // e.g. "tools/README.md"
  int line = 0;       // where the command starts
  std::string text;   // as written, continuation lines joined, comment removed
  std::string comment;
  std::vector<std::string> words;
};

// The documents: README.md at the top and in every folder (not build trees, not out/).
std::vector<fs::path> documents() {
  std::vector<fs::path> docs;
  for (auto it = fs::recursive_directory_iterator("."); it != fs::recursive_directory_iterator(); ++it) {
    const std::string name = it->path().filename().string();
    if (it->is_directory() && (name.rfind("build", 0) == 0 || name.rfind(".", 0) == 0 || name == "out")) {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file() && name == "README.md") docs.push_back(it->path().lexically_normal());
  }
  std::sort(docs.begin(), docs.end());
  return docs;
}

std::vector<std::string> split_words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> w;
  for (std::string x; in >> x;) w.push_back(x);
  return w;
}

// The command lines of the ```sh / ```bash blocks of one document.
std::vector<DocCommand> commands_in(const fs::path& doc) {
  std::ifstream in(doc);
  std::vector<DocCommand> out;
  bool in_block = false, shell_block = false;
  std::string pending;
  int pending_line = 0, n = 0;
  for (std::string line; std::getline(in, line);) {
    ++n;
    const auto first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line.compare(first, 3, "```") == 0) {
      const std::string info = line.substr(first + 3);
      shell_block = !in_block && (info == "sh" || info == "bash" || info == "shell");
      in_block = !in_block;
      continue;
    }
    if (!in_block || !shell_block) continue;
    if (pending.empty()) pending_line = n;
    if (!line.empty() && line.back() == '\\') {
      pending += line.substr(0, line.size() - 1) + " ";
      continue;
    }
    std::string text = pending + line;
    pending.clear();
    DocCommand c;
    c.doc = doc.string();
    c.line = pending_line;
    // A comment starts at a '#' that begins a word (a shell comment).
    static const std::regex comment_start(R"((^|\s)#)");
    std::smatch m;
    if (std::regex_search(text, m, comment_start)) {
      c.comment = text.substr(m.position(0) + m.length(0));
      text = text.substr(0, m.position(0));
    }
    c.text = text;
    c.words = split_words(text);
    if (!c.words.empty()) out.push_back(c);
  }
  return out;
}

bool is_stoneskip(const std::string& w) { return w == "stoneskip" || w == "build/tools/stoneskip"; }

// "long" at the start of any '#' part of the comment.
bool marked_long(const std::string& comment) {
  std::istringstream parts(comment);
  for (std::string part; std::getline(parts, part, '#');) {
    const auto f = part.find_first_not_of(" \t");
    if (f != std::string::npos && part.compare(f, 4, "long") == 0) return true;
  }
  return false;
}

int expected_status(const std::string& comment) {
  static const std::regex exit_n(R"(\bexit (\d+)\b)");
  std::smatch m;
  return std::regex_search(comment, m, exit_n) ? std::stoi(m[1]) : 0;
}

// A word with '*' in its file name becomes the sorted matching files, as a shell expands it.
std::vector<std::string> expand(const std::string& word) {
  if (word.find('*') == std::string::npos) return {word};
  const fs::path p(word);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  std::vector<std::string> found;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (::fnmatch(p.filename().c_str(), e.path().filename().c_str(), 0) == 0)
      found.push_back((p.has_parent_path() ? dir / e.path().filename() : e.path().filename()).string());
  std::sort(found.begin(), found.end());
  return found.empty() ? std::vector<std::string>{word} : found;
}

// One argument vector through the helper of test_support.hpp: each word reaches stoneskip exactly
// as written (no shell, no expansion, no splitting).
stoneskip::test::RanApart run_words(const std::vector<std::string>& args) {
  return stoneskip::test::run_apart(args, kCommandTimeout_s);
}

// Runs in `dir` for the object's life.
class WorkingDirectory {
 public:
  explicit WorkingDirectory(const fs::path& dir) : old_(fs::current_path()) { fs::current_path(dir); }
  ~WorkingDirectory() { fs::current_path(old_); }

 private:
  fs::path old_;
};

}  // namespace

BOOST_AUTO_TEST_SUITE(docs_examples)

BOOST_AUTO_TEST_CASE(the_documents_hold_the_quick_start_and_stoneskip_commands) {
  // Oracle: README.md's quick start as written, and the commands the documents show; a parser that
  // found none would make the test below pass vacuously.
  std::vector<DocCommand> all;
  for (const auto& d : documents())
    for (auto& c : commands_in(d)) all.push_back(c);
  const auto has = [&](const std::string& text) {
    return std::any_of(all.begin(), all.end(), [&](const DocCommand& c) { return split_words(c.text) == split_words(text); });
  };
  BOOST_TEST(has("bash tools/quickstart main"));
  BOOST_TEST(has("bash tools/quickstart test"));
  const auto n = std::count_if(all.begin(), all.end(), [](const DocCommand& c) { return is_stoneskip(c.words[0]); });
  BOOST_TEST(n >= 20);
  // The README is a map: at most 200 lines.
  std::ifstream readme("README.md");
  int lines = 0;
  for (std::string l; std::getline(readme, l);) ++lines;
  BOOST_TEST(lines <= 200);
}

BOOST_AUTO_TEST_CASE(the_documents_refer_to_nothing_outside_the_repository) {
  // Oracle: a reader has only the repository — no path above it, no issue tracker, and every
  // relative link of a document names a file or folder that exists.
  static const std::regex issue_number(R"(\bissues? #?\d)", std::regex::icase);
  static const std::regex link(R"(\]\(([^)#\s]*)(#[^)]*)?\))");
  // The folder beside the repository that its users do not have (spelt apart so that this file
  // does not mention it itself).
  static const std::string kOutsideFolder = std::string("..") + "/shared";
  const fs::path root = fs::weakly_canonical(".");
  for (const auto& d : documents()) {
    std::ifstream in(d);
    int n = 0;
    for (std::string line; std::getline(in, line);) {
      ++n;
      BOOST_TEST_CONTEXT(d.string() << ":" << n << ": " << line) {
        BOOST_TEST(line.find(kOutsideFolder) == std::string::npos);
        BOOST_TEST(!std::regex_search(line, issue_number));
        for (std::sregex_iterator it(line.begin(), line.end(), link), end; it != end; ++it) {
          const std::string target = (*it)[1];
          if (target.empty() || target.find("://") != std::string::npos) continue;
          const fs::path p = fs::weakly_canonical(d.parent_path() / target);
          BOOST_TEST(fs::exists(p), target << " does not exist");
          const std::string rel = p.lexically_relative(root).string();
          BOOST_TEST(rel.rfind("..", 0) != 0, target << " lies outside the repository");
        }
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(every_stoneskip_command_of_the_documents_runs_as_written) {
  const fs::path root = fs::current_path();
  std::vector<DocCommand> all;
  for (const auto& d : documents())
    for (auto& c : commands_in(d)) all.push_back(c);

  TempDir scratch("stoneskip-docs-examples");
  for (const char* linked : {"cases", "tools"}) fs::create_directory_symlink(root / linked, scratch.path() / linked);
  WorkingDirectory here(scratch.path());

  std::set<std::vector<std::string>> done;
  int ran = 0, skipped = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (const auto& c : all) {
    const std::string where = c.doc + ":" + std::to_string(c.line) + ": " + c.text;
    if (!is_stoneskip(c.words[0])) {
      if (c.words[0].rfind("#", 0) != 0) BOOST_TEST_MESSAGE("skipped (not a stoneskip command): " << where);
      ++skipped;
      continue;
    }
    if (marked_long(c.comment)) {
      BOOST_TEST_MESSAGE("skipped (marked long in the document: #" << c.comment << "): " << where);
      ++skipped;
      continue;
    }
    if (!done.insert(c.words).second) continue;  // the same command shown in two documents runs once
    std::vector<std::string> args;
    for (std::size_t i = 1; i < c.words.size(); ++i)
      for (auto& w : expand(c.words[i])) args.push_back(w);
    const int want = expected_status(c.comment);
    const auto r = run_words(args);
    ++ran;
    BOOST_TEST_MESSAGE("ran in " << r.wall_s << " s, exit " << r.status << ": " << where);
    BOOST_TEST(r.status == want, where << "\nexit " << r.status << ", expected " << want << "\nstderr: " << r.err
                                       << "\nstdout (start): " << r.out.substr(0, 2000));
  }
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  BOOST_TEST_MESSAGE(ran << " commands run in " << wall_s << " s, " << skipped << " skipped");
  BOOST_TEST(ran >= 15);
}

BOOST_AUTO_TEST_SUITE_END()
