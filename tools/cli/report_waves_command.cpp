// stoneskip report waves --out DIR [--quick | --study FILE] [--cases DIR]
//
// Runs the wave studies (consistency, convergence, isotropy, stability, speed against error of
// the stencils of model/README.md §2.2) with the settings of a study file, stores each section in
// DIR/data.h5 as it finishes, and renders DIR/index.md and DIR/figures/ from that file alone.
//   stoneskip report waves --out out/waves          # cases/studies/waves.toml: a few minutes on 2 cores
//   stoneskip report waves --out /tmp/w --quick     # cases/studies/waves_quick.toml: seconds
//   stoneskip report render out/waves               # rebuild index.md and the figures from data.h5
// A run killed late resumes its finished sections when started again with the same settings.
#include <memory>

#include "tools/cli/command_registry.hpp"
#include "tools/cli/report_render.hpp"
#include "tools/io/input_error.hpp"
#include "tools/scene/wave_study_file.hpp"

namespace stoneskip::cli {
namespace {

struct ReportWavesArgs {
  std::string out;
  std::string cases = "cases";
  std::string study;
  bool quick = false;
};

void report_waves(const ReportWavesArgs& a) {
  const std::string study =
      !a.study.empty() ? a.study : a.cases + (a.quick ? "/studies/waves_quick.toml" : "/studies/waves.toml");
  const WaveStudyFile f = load_wave_study_file(study);
  // Settings the study itself would refuse are bad input: refused before the folder is made.
  if (std::string why; !f.options.valid(&why)) throw_input_error(study, 0, "", why);
  ReportBuild build({a.out, "waves", "# " + study + "\n" + f.text,
                     "stoneskip report waves --out " + a.out + (a.study.empty() ? (a.quick ? " --quick" : "") : " --study " + a.study),
                     terminal_progress()});
  const Record root = run_wave_studies(f.options, build);
  finish_report(build, root, a.out);
}

void add_report_waves(CLI::App& report) {
  auto a = std::make_shared<ReportWavesArgs>();
  auto* cmd = report.add_subcommand("waves", "Water-surface verification: consistency, convergence, isotropy, stability, speed vs error of the stencils");
  cmd->add_option("--out", a->out, "Report folder (made whole at the end; an existing report folder is replaced)")->required();
  cmd->add_option("--cases", a->cases, "Folder of the shipped cases (holds studies/)")->capture_default_str();
  auto* q = cmd->add_flag("--quick", a->quick, "The quick preset (cases/studies/waves_quick.toml): seconds, for smoke tests");
  cmd->add_option("--study", a->study, "A waves study file instead of the shipped presets")->excludes(q);
  cmd->callback([a] { report_waves(*a); });
}

const bool kRegistered = register_report_kind(add_report_waves);

}  // namespace
}  // namespace stoneskip::cli
