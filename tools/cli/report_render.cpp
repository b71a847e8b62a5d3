#include "tools/cli/report_render.hpp"

#include <sys/stat.h>

#include <cstdio>

#include "reports/capture/capture_report.hpp"
#include "reports/scene/scene_report.hpp"
#include "reports/stones/stones_report.hpp"
#include "reports/waves/waves_report.hpp"
#include "tools/cli/command_registry.hpp"
#include "tools/io/atomic_file.hpp"
#include "tools/io/folder_manifest.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/progress.hpp"
#include "verification/study/verdict_rules.hpp"

namespace stoneskip::cli {

RenderedReport render_stored_report(const StoredReport& s) {
  if (s.kind == "waves") return render_waves_report(s);
  if (s.kind == "stones") return render_stones_report(s);
  if (s.kind == "captures") return render_captures_report(s);
  if (s.kind == "scene") return render_scene_report(s);
  throw_input_error(s.file.string(), 0, "report", "unknown report kind '" + s.kind + "'");
}

std::pair<int, std::size_t> render_folder(const std::filesystem::path& dir, bool in_place) {
  const StoredReport stored = load_stored_report(dir / "data.h5");
  // A stored verdict is printed only if its rule, applied to its stored inputs, still says it.
  std::vector<std::string> contradicted;
  try {
    contradicted = contradicted_verdicts(stored.report);
    for (auto& c : contradicted_verdicts(stored.sections)) contradicted.push_back(std::move(c));
  } catch (const RecordError& e) {
    throw_input_error((dir / "data.h5").string(), 0, "", std::string("a stored verdict cannot be re-checked: ") + e.what());
  }
  if (!contradicted.empty())
    throw_input_error((dir / "data.h5").string(), 0, "",
                      "a stored verdict contradicts its rule: " + contradicted.front() +
                          (contradicted.size() > 1 ? " (and " + std::to_string(contradicted.size() - 1) + " more)" : ""));
  // The figures go to DIR/figures: it must be a folder, or absent (then it is made).
  struct stat st {};
  const std::filesystem::path figures = dir / "figures";
  if (::lstat(figures.c_str(), &st) == 0 && !S_ISDIR(st.st_mode))
    throw_input_error(figures.string(), 0, "", "exists and is " + file_type_words(st.st_mode) + ", not a folder: cannot draw the figures into it");
  RenderedReport r;
  try {
    r = render_stored_report(stored);
  } catch (const RecordError& e) {
    throw_input_error((dir / "data.h5").string(), 0, "", std::string("the report data is incomplete or inconsistent: ") + e.what());
  }
  const std::vector<std::filesystem::path> written = rendered_files(r);
  if (in_place) {
    // A folder the user names: only what stoneskip wrote there may be replaced (its manifest).
    std::string why;
    if (!may_overwrite(dir, written, &why))
      throw_input_error(dir.string(), 0, "",
                        "rendering would replace " + why + ": stoneskip replaces only files it wrote (render a copy "
                        "of the folder, or move the file away)");
  }
  const Heartbeat alive("drawing " + std::to_string(r.figures.size()) + " figures");  // a line after 2 s
  const RenderSummary s = write_rendered_report(dir, r);
  // Figures an earlier rendering drew and this one does not (another study's data.h5 put here) are
  // removed; the manifest then lists what was just written (and what it listed before, unchanged):
  // a file of the user's beside them stays unlisted, so no build replaces the folder over it.
  remove_listed_except(dir, "figures", written);
  update_folder_manifest(dir, written);
  for (const auto& f : s.failures) std::fprintf(stderr, "figure failed: %s\n", f.c_str());
  if (!s.failures.empty()) set_exit_code(1);
  return {s.rendered, r.figures.size()};
}

void finish_report(ReportBuild& build, const Record& root, const std::filesystem::path& out_dir) {
  const std::filesystem::path work = build.assemble(root);
  const auto [drawn, figures] = render_folder(work);
  build.commit();
  std::printf("report: %s, %d of %zu figures drawn%s\n", (out_dir / "index.md").c_str(), drawn, figures,
              build.resumed_sections() > 0
                  ? (" (" + std::to_string(build.resumed_sections()) + " sections resumed from an earlier run)").c_str()
                  : "");
}

}  // namespace stoneskip::cli
