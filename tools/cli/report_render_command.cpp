// stoneskip report render DIR     rebuild DIR/index.md and DIR/figures/ from DIR/data.h5 alone
// stoneskip plot DIR              an alias of `report render DIR` (its older name), nothing more
//
// A report is a function of its data: this is the same rendering the report commands run after
// their studies, so the same build reproduces index.md byte for byte (the page names the code that
// rendered it beside the code that made the data).
#include <sys/stat.h>

#include <cstdio>
#include <memory>

#include "tools/cli/command_registry.hpp"
#include "tools/cli/report_render.hpp"
#include "tools/io/input_error.hpp"

namespace stoneskip::cli {
namespace {

void render(std::string dir) {
  // Never written through: a link named as the folder is refused (its target is not this name's);
  // "link/" names what the link points to, so the trailing slashes go first.
  while (dir.size() > 1 && dir.back() == '/') dir.pop_back();
  struct stat st {};
  if (::lstat(dir.c_str(), &st) == 0 && S_ISLNK(st.st_mode))
    throw_input_error(dir, 0, "", "is a link: stoneskip does not write through links (render the folder it points to)");
  const auto [drawn, figures] = render_folder(dir, true);
  std::printf("rendered %s, %d of %zu figures drawn\n", (std::filesystem::path(dir) / "index.md").c_str(), drawn, figures);
}

void add_report_render(CLI::App& report) {
  auto dir = std::make_shared<std::string>();
  auto* cmd = report.add_subcommand("render", "Rebuild a report's index.md and figures from its data.h5 alone");
  cmd->add_option("DIR", *dir, "Report folder (holds data.h5)")->required();
  cmd->callback([dir] { render(*dir); });
}

void add_plot(CLI::App& app) {
  auto dir = std::make_shared<std::string>();
  auto* cmd = app.add_subcommand("plot", "Alias of `report render DIR` (its older name): rebuild index.md and figures from DIR/data.h5");
  cmd->add_option("DIR", *dir, "Report folder (holds data.h5)")->required();
  cmd->callback([dir] { render(*dir); });
}

const bool kRenderRegistered = register_report_kind(add_report_render);
const bool kPlotRegistered = register_command(add_plot);

}  // namespace
}  // namespace stoneskip::cli
