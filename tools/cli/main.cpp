// stoneskip: verification and validation of real-time stone-skipping simulation.
//
//   stoneskip run cases/paper_8ms_spin.toml            # one throw, readable summary
//   stoneskip run cases/paper_8ms_spin.toml --json     # the same as one JSON object
//   stoneskip mesh cases/paper_8ms_spin.toml           # the stone's mesh and mass properties
//   stoneskip --help                                   # every command
//
// Exit status: 0 success, 1 a check failed (e.g. a regression), 2 bad input (one-line message
// naming the file and the line or key; an output place that cannot be written is bad input too),
// 3 an internal error, 128 + N stopped by signal N (SIGINT 130, SIGTERM 143: temporaries removed,
// tools/io/signal_cleanup.hpp).
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <iostream>
#include <new>
#include <string>
#include <system_error>
#include <vector>

#include "model/water/leapfrog_kernel.hpp"
#include "tools/io/hdf5_file.hpp"
#include "tools/cli/command_registry.hpp"
#include "stoneskip_version.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/printable_text.hpp"
#include "tools/io/shipped_files.hpp"
#include "tools/io/signal_cleanup.hpp"

namespace {

// A message on one line whatever names it quotes, with no byte a terminal would act on: a newline
// in a file name is written as \n, a Latin-1 byte of a capture's field as \xE9
// (tools/io/printable_text.hpp; the bad-input rule is one line on stderr).
std::string one_line(const std::string& what) { return stoneskip::printable_text(what); }

}  // namespace

namespace stoneskip::cli {

namespace {
std::vector<CommandAdder>& registry() {
  static std::vector<CommandAdder> r;
  return r;
}
std::vector<CommandAdder>& report_registry() {
  static std::vector<CommandAdder> r;
  return r;
}
int g_exit_code = 0;
}  // namespace

bool register_command(CommandAdder adder) {
  registry().push_back(std::move(adder));
  return true;
}
const std::vector<CommandAdder>& registered_commands() { return registry(); }
bool register_report_kind(CommandAdder adder) {
  report_registry().push_back(std::move(adder));
  return true;
}
const std::vector<CommandAdder>& registered_report_kinds() { return report_registry(); }
void set_exit_code(int code) { g_exit_code = code; }
int exit_code() { return g_exit_code; }
void print_input_error(const std::string& message) {
  std::fprintf(stderr, "stoneskip: %s\n", one_line(message).c_str());
  std::fflush(stderr);
}

}  // namespace stoneskip::cli

namespace {

int run_main(int argc, char** argv) {
  // First, before any thread exists: SIGINT, SIGTERM and SIGHUP remove the temporaries.
  stoneskip::install_signal_cleanup();
  // STONESKIP_ISA forces the stencil kernel's instruction-set path: a value that names none, or one
  // this CPU lacks, is bad input (model/water/leapfrog_kernel.hpp).
  {
    stoneskip::SimdPath path;
    std::string why;
    if (!stoneskip::simd_path_from_environment(path, &why)) {
      std::fprintf(stderr, "stoneskip: %s\n", one_line(why).c_str());
      return 2;
    }
  }
  CLI::App app{"stoneskip: verification and validation of real-time stone-skipping simulation"};
  app.require_subcommand(1);
  // The version, and where the shipped cases are found (tools/io/shipped_files.hpp).
  const std::filesystem::path shipped = stoneskip::shipped_cases_dir();
  app.set_version_flag("--version", std::string("stoneskip ") + stoneskip::kVersion + " (git " + stoneskip::kGitDescribe + ")\nshipped cases: " +
                                        (shipped.empty() ? std::string("none found") : shipped.string()) + "\n");
  for (const auto& add : stoneskip::cli::registered_commands()) add(app);
  // A first word that is no option and no command is named (CLI11 would only say that a
  // subcommand is required).
  bool known = argc < 2 || argv[1][0] == '-';
  for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    known = known || sub->check_name(argv[1]);
  if (!known) {
    std::fprintf(stderr, "stoneskip: unknown command '%s' (see --help)\n", one_line(argv[1]).c_str());
    return 2;
  }
  // The same one level down, for a command made of subcommands (`report sweep` said only that a
  // subcommand is required): the word is named, with the ones there are.
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    if (argc < 3 || !sub->check_name(argv[1]) || sub->get_require_subcommand_min() == 0 || argv[2][0] == '-') continue;
    std::string names;
    bool found = false;
    for (const CLI::App* leaf : sub->get_subcommands([](CLI::App*) { return true; })) {
      found = found || leaf->check_name(argv[2]);
      names += (names.empty() ? "" : ", ") + leaf->get_name();
    }
    if (found) break;
    const std::string word = argv[2];
    std::fprintf(stderr, "stoneskip: %s: unknown subcommand '%s' (one of %s%s; see stoneskip %s --help)\n", sub->get_name().c_str(),
                 one_line(word).c_str(), names.c_str(),
                 sub->get_name() == "report" && word == "sweep" ? "; a sweep's maps come from `stoneskip sweep-plot FILE`" : "",
                 sub->get_name().c_str());
    return 2;
  }
  int code = 0;
  try {
    app.parse(argc, argv);
    code = stoneskip::cli::exit_code();
  } catch (const CLI::CallForHelp& e) {
    code = app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    code = app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    code = app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Usage errors are bad input: one line, exit 2.
    std::fprintf(stderr, "stoneskip: %s (see --help)\n", one_line(e.what()).c_str());
    return 2;
  } catch (const stoneskip::InputError& e) {
    stoneskip::cli::print_input_error(e.what());
    return 2;
  } catch (const std::filesystem::filesystem_error& e) {
    // A path the user named that cannot be read or written (the commands check the ones they
    // know; this catches the rest): bad input, not a bug.
    std::fprintf(stderr, "stoneskip: %s\n", one_line(e.what()).c_str());
    return 2;
  } catch (const std::system_error& e) {
    // An output that could not be written for want of room or a working disk (a sweep's journal
    // on a full disk): the place's fault, not a bug; what was finished stays (sweep --resume).
    const int c = e.code().value();
    const bool place = (e.code().category() == std::generic_category() || e.code().category() == std::system_category()) &&
                       (c == ENOSPC || c == EDQUOT || c == EIO || c == EROFS || c == EFBIG);
    std::fprintf(stderr, "stoneskip: %s%s\n", place ? "" : "internal error: ", one_line(e.what()).c_str());
    return place ? 2 : 3;
  } catch (const std::bad_alloc&) {
    // A run larger than the machine's memory (past the documented limits, lifted) said
    // "internal error: std::bad_alloc", exit 3. It is the run's size, not a bug: exit 2, saying so.
    std::fprintf(stderr,
                 "stoneskip: out of memory: the run needs more memory than this machine gave it (the limits of "
                 "cases/README.md, which --allow-large and --max-memory-gb lift, refuse such runs before they start)\n");
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "stoneskip: internal error: %s\n", one_line(e.what()).c_str());
    return 3;
  }
  // What went to stdout must have arrived: a full disk behind a redirection would otherwise leave
  // an empty or cut result beside exit 0 (a closed pipe ends the process with SIGPIPE first). Exit
  // 2 then, also over a check's exit 1: its result was not delivered.
  std::cout.flush();
  if (!std::cout.good() || std::fflush(stdout) != 0 || std::ferror(stdout)) {
    std::fprintf(stderr, "stoneskip: could not write the output to standard output (a full disk?)\n");
    return 2;
  }
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  const int code = run_main(argc, argv);
  // After an HDF5 write that failed (a full disk) the library holds a file it could not close,
  // and its own clean-up at exit crashed on it (a segfault after the one-line error): the streams
  // are flushed and the process ends without the library's clean-up. Every file that was written
  // has been closed and checked by its writer (tools/io/hdf5_file.hpp).
  if (stoneskip::hdf5_write_failed()) {
    std::fflush(nullptr);
    std::_Exit(code);
  }
  return code;
}
