// stoneskip report front OUT     OUT/index.md and OUT/index.html: the front page of a main job's output
//
// Links every report in OUT (each sub-folder holding a report's data.h5), the movies in
// OUT/movies and the throws in OUT/throws, with each report's verdicts in one line, a picture, and
// its findings under "What we found" (reports/front/front_page.hpp). It reads and renders the
// reports' data.h5 in memory and draws nothing; the main job runs it last.
#include <cstdio>
#include <memory>

#include "reports/front/front_page.hpp"
#include "tools/cli/command_registry.hpp"
#include "tools/cli/report_render.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/printable_text.hpp"

namespace stoneskip::cli {
namespace {

void front(const std::string& dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec)) throw_input_error(dir, 0, "", "not a folder (the main job's output folder was expected)");
  // As report render: the pages are written into DIR itself, never through a link to elsewhere.
  std::string bare = dir;
  while (bare.size() > 1 && bare.back() == '/') bare.pop_back();
  if (std::filesystem::is_symlink(std::filesystem::symlink_status(bare, ec)))
    throw_input_error(dir, 0, "", "is a link: stoneskip does not write through links (give the folder itself)");
  const FrontPageInput in = read_front_page_input(dir, render_stored_report);
  write_front_page(dir, front_page_markdown(in));
  for (const FrontSkipped& s : in.skipped)
    std::fprintf(stderr, "stoneskip: report front: not shown: %s: %s\n", printable_text(s.path).c_str(), printable_text(s.reason).c_str());
  std::printf("front page: %s/index.html (and index.md): %zu reports, %zu movies, %zu throws\n", dir.c_str(), in.reports.size(),
              in.movies.size(), in.throws.size());
}

void add_report_front(CLI::App& report) {
  auto dir = std::make_shared<std::string>();
  auto* cmd = report.add_subcommand("front", "Write OUT/index.html and OUT/index.md: every report, movie and throw in OUT, with what was found");
  cmd->add_option("OUT", *dir, "The main job's output folder (holds the report folders)")->required();
  cmd->callback([dir] { front(*dir); });
}

const bool kFrontRegistered = register_report_kind(add_report_front);

}  // namespace
}  // namespace stoneskip::cli
