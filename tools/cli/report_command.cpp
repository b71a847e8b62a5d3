// stoneskip report KIND --out DIR: runs a report's studies and writes DIR/index.md, DIR/data.h5
// and DIR/figures/. The kinds register themselves (register_report_kind).
#include "tools/cli/command_registry.hpp"

namespace stoneskip::cli {
namespace {

void add_report(CLI::App& app) {
  auto* cmd = app.add_subcommand("report", "Run a verification/validation study and write its report (Markdown, figures, HDF5 data)");
  cmd->require_subcommand(1);
  for (const auto& add : registered_report_kinds()) add(*cmd);
}

const bool kRegistered = register_command(add_report);

}  // namespace
}  // namespace stoneskip::cli
