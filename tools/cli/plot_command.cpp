// stoneskip plot DIR: redraw every figure of a report from DIR/data.h5 (no re-running).
#include <cstdio>
#include <filesystem>

#include "reports/common/figure.hpp"
#include "tools/cli/command_registry.hpp"
#include "tools/io/hdf5_file.hpp"
#include "tools/io/input_error.hpp"

namespace stoneskip::cli {
namespace {

void add_plot(CLI::App& app) {
  auto* cmd = app.add_subcommand("plot", "Redraw a report's figures from its data file DIR/data.h5, without re-running");
  auto dir = std::make_shared<std::string>();
  cmd->add_option("DIR", *dir, "Report folder (holds data.h5)")->required();
  cmd->callback([dir] {
    std::filesystem::path data = std::filesystem::path(*dir) / "data.h5";
    Hdf5Reader file(data);
    if (!file.root().has("figures")) throw_input_error(data.string(), 0, "/figures", "no figures stored in this file");
    auto figs = load_figures(file.root().open_group("figures"));
    if (!gnuplot_available()) throw_input_error("gnuplot", 0, "", "not found on PATH (apt-get install gnuplot-nox)");
    RenderSummary s = render_figures(*dir, figs);
    std::printf("redrew %d of %zu figures into %s/figures\n", s.rendered, figs.size(), dir->c_str());
    for (const auto& f : s.failures) std::fprintf(stderr, "figure failed: %s\n", f.c_str());
    if (!s.failures.empty()) set_exit_code(1);
  });
}

const bool kRegistered = register_command(add_plot);

}  // namespace
}  // namespace stoneskip::cli
