#pragma once
// What every `stoneskip report KIND` command shares: progress bars for the studies, and the
// last steps of a build — assemble data.h5, render index.md and the figures from it alone (the
// same code `stoneskip report render DIR` runs), move the folder into place.
#include <filesystem>
#include <string>

#include "reports/common/report_build.hpp"
#include "reports/common/stored_report.hpp"
#include "tools/cli/terminal_progress.hpp"

namespace stoneskip::cli {

// Renders a stored report by its kind ("waves", "stones", …); InputError for an unknown kind.
RenderedReport render_stored_report(const StoredReport& stored);

// Renders DIR/data.h5 into DIR/index.md and DIR/figures/; prints each figure that could not be
// drawn and sets exit code 1 then. Returns the number of figures drawn and of figures in all.
// in_place (a folder the user names, `report render DIR`): InputError, before anything is written,
// if a file to be written exists and is not one stoneskip wrote there (tools/io/folder_manifest.hpp).
std::pair<int, std::size_t> render_folder(const std::filesystem::path& dir, bool in_place = false);

// assemble(root) → render into the work folder → commit. Prints where the report is.
void finish_report(ReportBuild& build, const Record& root, const std::filesystem::path& out_dir);

}  // namespace stoneskip::cli
