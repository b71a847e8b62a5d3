// stoneskip regress [--baseline FILE...] [--update] [--workers N]
//
// Recomputes the golden bounce-count curves stored in cases/baselines/*.toml (or the files given)
// and prints a difference report by the rules of verification/stones/bounce_baseline.hpp: robust
// counts must match away from thresholds, sensitive ones are compared on ensembles, thresholds
// (bisected) must match within each baseline's compare_tolerance. Exit status 1 on a regression,
// 2 on bad input. --update rewrites each baseline's [result] from the recomputed curve (the text
// before [result], settings and comments, is kept as written), for when a change of the model is
// intended; it says how many throws failed (stored as −1) and refuses a curve of which every grid
// value failed (nothing to compare later runs with).
//
//   stoneskip regress                                     # all stored baselines (< 1 min)
//   stoneskip regress --baseline cases/baselines/spin_paper_realtime.toml
// Every baseline and its case are read and checked, and the work of all the throws (grids and
// bisections) estimated and held to the limits of cases/README.md, before any throw is run.
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "stoneskip_version.hpp"
#include "tools/cli/command_registry.hpp"
#include "tools/cli/limit_options.hpp"
#include "tools/cli/terminal_progress.hpp"
#include "tools/io/atomic_file.hpp"
#include "tools/io/input_error.hpp"
#include "tools/io/shipped_files.hpp"
#include "tools/scene/baseline_file.hpp"
#include "tools/scene/resource_estimate.hpp"

namespace stoneskip::cli {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> default_baselines() {
  std::vector<std::string> files;
  const fs::path dir = locate_input("cases/baselines");  // here, else the shipped ones (tools/io/shipped_files.hpp)
  if (!fs::is_directory(dir))
    throw_input_error(dir.string(), 0, "", "no baseline folder here or shipped (give --baseline FILE)");
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".toml") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  if (files.empty()) throw_input_error(dir.string(), 0, "", "no *.toml baselines in this folder");
  return files;
}

std::string today_utc() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d", std::gmtime(&t));
  return buf;
}

void add_regress(CLI::App& app) {
  auto* cmd = app.add_subcommand("regress", "Recompute the stored bounce-count baselines and report differences (exit 1 on a regression)");
  auto files = std::make_shared<std::vector<std::string>>();
  auto update = std::make_shared<bool>(false);
  auto workers = std::make_shared<int>(2);
  cmd->add_option("--baseline", *files, "Baseline files (default: cases/baselines/*.toml)");
  cmd->add_flag("--update", *update, "Rewrite each baseline's [result] from the recomputed curve");
  cmd->add_option("--workers", *workers, "Worker threads")->capture_default_str()->check(CLI::Range(1, 64));
  auto limits = std::make_shared<ResourceLimits>();
  add_limit_options(cmd, *limits);
  cmd->callback([files, update, workers, limits] {
    const auto t0 = std::chrono::steady_clock::now();
    // --update rewrites only baselines here or named where they are: the shipped copies, found from
    // any folder (tools/io/shipped_files.hpp), are read, never rewritten (an installed binary run
    // from an empty folder rewrote its installed baselines until December 5).
    if (*update && files->empty() && !fs::is_directory("cases/baselines"))
      throw_input_error("cases/baselines", 0, "",
                        "no baseline folder here: --update rewrites the baselines in ./cases/baselines or those named "
                        "with --baseline, never the shipped copies");
    if (*update)
      for (const auto& p : *files)
        if (!fs::exists(fs::symlink_status(p)))
          throw_input_error(p, 0, "", "not found here: --update rewrites a baseline where it is named, never the shipped "
                                      "copy (copy it here first)");
    const std::vector<std::string> paths = files->empty() ? default_baselines() : *files;
    // Read everything first: bad input is reported before any work.
    std::vector<BounceBaseline> stored;
    std::vector<BounceSweepSpec> specs;
    for (const auto& p : paths) {
      stored.push_back(read_baseline(p));
      // Nothing to compare with is bad input (exit 2, before any sweep), not a regression.
      if (!*update && !stored.back().has_result)
        throw_input_error(p, 0, "result", "the baseline has no [result]: write one with `stoneskip regress --update --baseline " + p + "`");
      if (!*update && stored.back().ensemble_members > 0 && stored.back().ensembles.empty())
        throw_input_error(p, 0, "result.ensemble_counts",
                          "missing: the baseline compares ensembles of " + std::to_string(stored.back().ensemble_members) +
                              " nudged throws (baseline.ensemble_members); write them with `stoneskip regress --update --baseline " +
                              p + "`, or set ensemble_members = 0 for single runs");
      // --update rewrites the file: one that may not be written (a link, say) is refused now, not
      // after the sweep.
      if (*update) check_output_destination(p);
      specs.push_back(sweep_of(stored.back()));
      enforce_limits(estimate_regress({specs.back()}), *limits, p);
    }
    enforce_limits(estimate_regress(specs), *limits, "regress");
    std::printf("regress: %zu baseline%s\n", paths.size(), paths.size() == 1 ? "" : "s");
    // Out before the sweeps: a signal ends the process without flushing stdio's buffer (a file's
    // is not flushed line by line), and the line would be lost.
    std::fflush(stdout);
    const auto results = run_bounce_sweeps(specs, ParallelOptions{*workers, "regress", terminal_progress()});
    int failed = 0;
    for (std::size_t i = 0; i < stored.size(); ++i) {
      const BounceBaseline& b = stored[i];
      if (*update) {
        const BounceSweepResult& r = results[i];
        const long grid_failed = std::count_if(r.counts.begin(), r.counts.end(), [](int n) { return n < 0; });
        long members_failed = 0;
        for (const auto& e : r.ensembles) members_failed += std::count_if(e.begin(), e.end(), [](int n) { return n < 0; });
        // A curve of failures only would be golden: every later run that failed alike would pass.
        if (!r.counts.empty() && grid_failed == static_cast<long>(r.counts.size())) {
          std::printf("  %-34s NOT UPDATED  every grid value's throw failed (%s): %s\n", b.name.c_str(),
                      r.failures.empty() ? "" : r.failures.front().c_str(), b.file.c_str());
          ++failed;
          continue;
        }
        // The file as the user wrote it, its [result] replaced (comments and layout kept).
        write_text_file(b.file, updated_baseline_text(read_text_file(b.file), r,
                                                      std::string("stoneskip ") + kVersion + " (git " + kGitDescribe + "), " + today_utc()));
        std::printf("  %-34s UPDATED  %zu grid values, %zu thresholds", b.name.c_str(), r.counts.size(), r.thresholds.size());
        if (grid_failed + members_failed > 0)
          std::printf("; failed and stored as -1: %ld grid throw%s, %ld nudged member%s", grid_failed, grid_failed == 1 ? "" : "s",
                      members_failed, members_failed == 1 ? "" : "s");
        std::printf(" (%s)\n", b.file.c_str());
        continue;
      }
      const BaselineComparison c = compare_with_baseline(b, results[i]);
      std::printf("  %-34s %s  %d grid values, %d thresholds; %s, %s  (%s)\n", b.name.c_str(), c.passed ? "PASS" : "FAIL",
                  c.grid_points, c.thresholds, to_string(b.parameter), specs[i].solver.label().c_str(), b.file.c_str());
      std::printf("      case: %s\n", resolve_case_file(b).string().c_str());  // the one that ran
      if (b.ensemble_members > 0)
        std::printf("      ensembles of %d nudged throws per value; %d of %d values sensitive (the ensembles decide there)\n",
                    b.ensemble_members, c.sensitive_points, c.grid_points);
      else
        std::printf("      single runs only (ensemble_members = 0): a count a nudge changes is not told from a regression\n");
      for (const auto& r : c.regressions) std::printf("      REGRESSION: %s\n", r.c_str());
      for (const auto& r : c.tolerated) std::printf("      tolerated:  %s\n", r.c_str());
      for (const auto& r : c.resolution) std::printf("      resolution: %s\n", r.c_str());
      if (!c.passed) ++failed;
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (*update) {
      std::printf("regress: %zu baselines rewritten, %d refused (%.1f s)\n", stored.size() - failed, failed, wall);
      if (failed) set_exit_code(1);
      return;
    }
    std::printf("regress: %zu passed, %d failed (%.1f s)\n", stored.size() - failed, failed, wall);
    if (failed) set_exit_code(1);
  });
}

const bool kRegistered = register_command(add_regress);

}  // namespace
}  // namespace stoneskip::cli
