// stoneskip report stones --out DIR [--cases DIR] [--quick] [--workers N]
//
// The stone studies: convergence of the real-time model against the CVODE reference, speed
// against error, bounce-count curves with bisected thresholds, hard cases, validation against
// Clanet et al. 2004 / Bocquet 2003 / the seed's claims. Writes DIR/index.md, DIR/data.h5 and
// DIR/figures/. About 5–8 minutes on two cores; --quick is a smoke run of a few seconds.
#include <cstdio>
#include <memory>

#include "reports/stones/stones_report.hpp"
#include "tools/cli/command_registry.hpp"

namespace stoneskip::cli {
namespace {

void add_report_stones(CLI::App& report) {
  auto* cmd = report.add_subcommand("stones", "Stone studies: convergence, speed against error, bounce-count curves, hard cases, validation");
  auto o = std::make_shared<StonesReportOptions>();
  auto out = std::make_shared<std::string>();
  auto cases = std::make_shared<std::string>("cases");
  cmd->add_option("--out", *out, "Report folder (created if missing)")->required();
  cmd->add_option("--cases", *cases, "Folder of the shipped cases (with studies/ and hard/)")->capture_default_str();
  cmd->add_option("--workers", o->workers, "Worker threads")->capture_default_str()->check(CLI::Range(1, 64));
  cmd->add_flag("--quick", o->quick, "Coarse grids, single timings: a smoke run, not the report's numbers");
  cmd->callback([o, out, cases] {
    o->out_dir = *out;
    o->cases_dir = *cases;
    const StonesReportSummary s = write_stones_report(*o);
    std::printf("stones report: %s/index.md, %d figures, %.1f s\n", out->c_str(), s.figures, s.wall_s);
    for (const auto& f : s.figure_failures) std::fprintf(stderr, "figure failed: %s\n", f.c_str());
    if (!s.figure_failures.empty()) set_exit_code(1);
  });
}

const bool kRegistered = register_report_kind(add_report_stones);

}  // namespace
}  // namespace stoneskip::cli
