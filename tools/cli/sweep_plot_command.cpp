// stoneskip sweep-plot FILE.h5 [--out DIR] [--map COLUMN ...] [--no-render]
//
// Draws a finished sweep (`stoneskip sweep`): bounce-count maps over every pair of varied keys
// with the count's thresholds as contours, the real-time/reference disagreement map, histograms
// for random designs, and a page DIR/index.md with the outcomes, the agreement of the solvers and
// what the throws cost (reports/sweep/). DIR defaults to FILE's name without .h5, plus "_plots".
//   stoneskip sweep-plot speed_spin.h5 --out out/speed_spin --map realtime_distance_m --map cost_realtime_wall_s
#include <cstdio>
#include <filesystem>
#include <optional>

#include "reports/common/report_build.hpp"
#include "reports/sweep/sweep_page.hpp"
#include "tools/cli/command_registry.hpp"
#include "tools/io/atomic_file.hpp"
#include "tools/io/folder_manifest.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/output_over_input.hpp"
#include "tools/io/progress.hpp"

namespace stoneskip::cli {
namespace {

struct PlotArgs {
  std::string file;
  std::optional<std::string> out;
  bool no_render = false;
  std::vector<std::string> columns;
};

void run(const PlotArgs& a) {
  const SweepData data = read_sweep_file(a.file);
  if (a.out && a.out->empty()) throw_input_error("--out", 0, "", "needs a folder name (got an empty one)");
  const std::filesystem::path dir =
      a.out ? std::filesystem::path(*a.out) : std::filesystem::path(std::filesystem::path(a.file).replace_extension("").string() + "_plots");
  refuse_output_over_inputs(dir, OutputKind::folder, {a.file});
  if (!a.no_render && !gnuplot_available())
    throw_input_error("gnuplot", 0, "", "not found on PATH (apt-get install gnuplot-nox), or use --no-render");
  SweepMapOptions maps;
  maps.columns = a.columns;
  // Built whole in a work folder, then moved into place; a page made before may be replaced.
  // A page holds nothing but what its manifest lists (tools/io/folder_manifest.hpp) and a data.h5
  // holding /figures: a folder with the user's files in it, or one of them edited, is never replaced.
  AtomicFolder out(dir, [](const std::filesystem::path& d) {
    if (!holds_only_its_manifest(d)) return false;
    try {
      return Hdf5Reader(d / "data.h5").root().has("figures");
    } catch (const std::exception&) {
      return false;
    }
  });
  std::optional<SweepPageSummary> page;
  {
    const Heartbeat alive("sweep-plot");  // a line on stderr once drawing takes more than 2 s
    page = write_sweep_page(out.work_dir(), data, a.file, maps, !a.no_render);
  }
  const SweepPageSummary& s = *page;
  out.commit();
  std::printf("wrote %s/index.md and %zu figures (%d drawn) from %zu throws\n", dir.c_str(), s.figures, s.render.rendered,
              data.throws.rows());
  for (const auto& f : s.render.failures) std::fprintf(stderr, "figure failed: %s\n", f.c_str());
  if (!s.render.failures.empty()) set_exit_code(1);
}

void add_sweep_plot(CLI::App& app) {
  auto a = std::make_shared<PlotArgs>();
  auto* cmd = app.add_subcommand("sweep-plot", "Draw a finished sweep: bounce-count maps, disagreement, histograms");
  cmd->add_option("FILE", a->file, "Sweep result file (from stoneskip sweep)")->required();
  cmd->add_option("--out", a->out, "Folder for index.md, data.h5 and figures/ (default: FILE without .h5 + _plots)");
  cmd->add_flag("--no-render", a->no_render, "Store the figures' data in data.h5 and write the page without running gnuplot (no figures/ folder: the page's images are missing)");
  cmd->add_option("--map", a->columns,
                  "Also map this column of the table, e.g. realtime_distance_m or cost_realtime_wall_s (repeatable)");
  cmd->callback([a] { run(*a); });
}

const bool kRegistered = register_command(add_sweep_plot);

}  // namespace
}  // namespace stoneskip::cli
