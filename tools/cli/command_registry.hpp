#pragma once
// Each sub-command of `stoneskip` lives in its own file in tools/cli/ and registers itself here at
// static-initialisation time (the files are compiled into the executable, not a library, so the
// registrations are never dropped by the linker):
//
//   namespace { void add_run(CLI::App& app) { ... } const bool kRegistered = register_command(add_run); }
//
// A command reports bad input by throwing InputError (exit 2); a command that completes but must
// fail (a regression found) calls set_exit_code(1).
#include <CLI/CLI.hpp>

#include <functional>

namespace stoneskip::cli {

using CommandAdder = std::function<void(CLI::App& root)>;

bool register_command(CommandAdder adder);
const std::vector<CommandAdder>& registered_commands();

// `stoneskip report KIND --out DIR`: each report kind (waves, stones, ...) registers a function
// that adds its own sub-command to the `report` command (tools/cli/report_command.cpp).
bool register_report_kind(CommandAdder adder);
const std::vector<CommandAdder>& registered_report_kinds();

void set_exit_code(int code);
int exit_code();

// Bad input reported now, on stderr, as main() reports an InputError ("stoneskip: " and the
// message on one line), for a command that must print before it returns (a rank of an MPI job
// that mpirun may stop as soon as another rank exits).
void print_input_error(const std::string& message);

}  // namespace stoneskip::cli
