// stoneskip report scene --out DIR [--quick | --study FILE] [--cases DIR]
//
// Runs the scene studies (two-way against one-way against still water, the coupled stability
// limit, the forced leapfrog's convergence, the rings' speed, each shortcut's error and saving,
// the speed figures, the still frames) with the settings of a study file, stores each section in
// DIR/data.h5 as it finishes, and renders DIR/index.md and DIR/figures/ from that file alone.
//   stoneskip report scene --out out/scene          # cases/studies/scene.toml: a few minutes on 2 cores
//   stoneskip report scene --out /tmp/s --quick     # cases/studies/scene_quick.toml: seconds
//   stoneskip report render out/scene               # rebuild index.md and the figures from data.h5
#include <memory>

#include "tools/cli/command_registry.hpp"
#include "tools/cli/report_render.hpp"
#include "tools/scene/scene_study_file.hpp"

namespace stoneskip::cli {
namespace {

struct ReportSceneArgs {
  std::string out;
  std::string cases = "cases";
  std::string study;
  bool quick = false;
};

void report_scene(const ReportSceneArgs& a) {
  const std::string study =
      !a.study.empty() ? a.study : a.cases + (a.quick ? "/studies/scene_quick.toml" : "/studies/scene.toml");
  const SceneStudyFile f = load_scene_study_file(study);
  ReportBuild build({a.out, "scene", f.settings_text,
                     "stoneskip report scene --out " + a.out + (a.study.empty() ? (a.quick ? " --quick" : "") : " --study " + a.study),
                     terminal_progress()});
  const Record root = run_scene_studies(f.options, build);
  finish_report(build, root, a.out);
}

void add_report_scene(CLI::App& report) {
  auto a = std::make_shared<ReportSceneArgs>();
  auto* cmd = report.add_subcommand("scene", "The seed's scene whole: two-way coupling, its stability and convergence, rings, shortcuts, speed, stills");
  cmd->add_option("--out", a->out, "Report folder (made whole at the end; an existing report folder is replaced)")->required();
  cmd->add_option("--cases", a->cases, "Folder of the shipped cases (holds studies/)")->capture_default_str();
  auto* q = cmd->add_flag("--quick", a->quick, "The quick preset (cases/studies/scene_quick.toml): seconds, for smoke tests");
  cmd->add_option("--study", a->study, "A scene study file instead of the shipped presets")->excludes(q);
  cmd->callback([a] { report_scene(*a); });
}

const bool kRegistered = register_report_kind(add_report_scene);

}  // namespace
}  // namespace stoneskip::cli
