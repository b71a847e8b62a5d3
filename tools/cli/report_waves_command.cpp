// stoneskip report waves --out DIR [--quick]
//
// Runs the wave studies (consistency, convergence, isotropy, stability, speed against error of
// the four stencils of spec §2.2) and writes DIR/index.md, DIR/data.h5 and DIR/figures/.
//   stoneskip report waves --out out/waves          # the full report, a few minutes on 2 cores
//   stoneskip report waves --out /tmp/w --quick     # reduced grids, seconds (a smoke run)
//   stoneskip plot out/waves                        # redraw the figures from data.h5
// Progress goes to stderr. Exit 1 if a figure could not be drawn.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "reports/waves/waves_report.hpp"
#include "tools/cli/command_registry.hpp"
#include "tools/io/atomic_file.hpp"
#include "tools/io/input_error.hpp"

namespace stoneskip::cli {
namespace {

struct ReportWavesArgs {
  std::string out;
  bool quick = false;
};

void report_waves(const ReportWavesArgs& a) {
  std::filesystem::create_directories(a.out);
  { AtomicOutput check(std::filesystem::path(a.out) / "index.md"); }  // an unwritable folder fails now, not later
  const auto start = std::chrono::steady_clock::now();
  WaveStudiesOptions options;
  options.quick = a.quick;
  WaveStudies studies = run_wave_studies(options);
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string command = "stoneskip report waves --out " + a.out + (a.quick ? " --quick" : "");
  WavesReportSummary s = write_waves_report(studies, a.out, command, wall_s);
  std::printf("wrote %s (%d figures, studies took %.1f s)\n", s.index.c_str(), s.figures_rendered, wall_s);
  for (const auto& f : s.figure_failures) std::fprintf(stderr, "figure failed: %s\n", f.c_str());
  if (!s.figure_failures.empty()) set_exit_code(1);
}

void add_report_waves(CLI::App& report) {
  auto a = std::make_shared<ReportWavesArgs>();
  auto* cmd = report.add_subcommand("waves", "Water-surface verification: consistency, convergence, isotropy, stability, speed vs error of the four stencils");
  cmd->add_option("--out", a->out, "Report folder (created)")->required();
  cmd->add_flag("--quick", a->quick, "Reduced grids and sequences (seconds; for smoke tests)");
  cmd->callback([a] { report_waves(*a); });
}

const bool kRegistered = register_report_kind(add_report_waves);

}  // namespace
}  // namespace stoneskip::cli
