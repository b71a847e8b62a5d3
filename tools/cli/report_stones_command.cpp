// stoneskip report stones --out DIR [--quick | --study FILE] [--cases DIR] [--workers N]
//
// The stone studies: convergence of the real-time model against the CVODE reference, speed
// against error, bounce-count curves with bisected thresholds, hard cases, validation against
// Clanet et al. 2004 / Bocquet 2003 / the seed's claims — with the settings of a study file
// (cases/studies/stones.toml; --quick: stones_quick.toml). Each section is stored in DIR/data.h5
// as it finishes; DIR/index.md and DIR/figures/ are rendered from that file alone. A run killed
// late resumes its finished sections when started again with the same settings.
//   stoneskip report stones --out out/stones          # the full report (minutes on 2 cores)
//   stoneskip report stones --out /tmp/s --quick      # a smoke run of seconds
#include <memory>

#include "tools/cli/command_registry.hpp"
#include "tools/cli/report_render.hpp"
#include "tools/io/input_error.hpp"
#include "tools/cli/terminal_progress.hpp"
#include "tools/scene/stone_study_file.hpp"

namespace stoneskip::cli {
namespace {

struct ReportStonesArgs {
  std::string out;
  std::string cases = "cases";
  std::string study;
  bool quick = false;
  int workers = 2;
};

void report_stones(const ReportStonesArgs& a) {
  const std::string study =
      !a.study.empty() ? a.study : a.cases + (a.quick ? "/studies/stones_quick.toml" : "/studies/stones.toml");
  StoneStudyFile f = load_stone_study_file(study);
  f.options.workers = a.workers;
  // Settings the study itself would refuse are bad input: refused before the folder is made.
  if (std::string why; !f.options.valid(&why)) throw_input_error(study, 0, "", why);
  ReportBuild build({a.out, "stones", f.settings_text,
                     "stoneskip report stones --out " + a.out +
                         (a.study.empty() ? (a.quick ? " --quick" : "") : " --study " + a.study) +
                         " --workers " + std::to_string(a.workers),
                     terminal_progress()});
  const Record root = run_stone_studies(f.options, build);
  finish_report(build, root, a.out);
}

void add_report_stones(CLI::App& report) {
  auto a = std::make_shared<ReportStonesArgs>();
  auto* cmd = report.add_subcommand("stones", "Stone studies: convergence, speed against error, bounce-count curves, hard cases, validation");
  cmd->add_option("--out", a->out, "Report folder (made whole at the end; an existing report folder is replaced)")->required();
  cmd->add_option("--cases", a->cases, "Folder of the shipped cases (holds studies/)")->capture_default_str();
  auto* q = cmd->add_flag("--quick", a->quick, "The quick preset (cases/studies/stones_quick.toml): a smoke run, not the report's numbers");
  cmd->add_option("--study", a->study, "A stones study file instead of the shipped presets")->excludes(q);
  cmd->add_option("--workers", a->workers, "Worker threads")->capture_default_str()->check(CLI::Range(1, 64));
  cmd->callback([a] { report_stones(*a); });
}

const bool kRegistered = register_report_kind(add_report_stones);

}  // namespace
}  // namespace stoneskip::cli
