#pragma once
// `stoneskip report stones --out DIR`: the stone studies (convergence of the real-time model,
// speed against error, bounce-count curves, hard cases, validation) written as DIR/index.md,
// DIR/data.h5 (results, settings, provenance, /figures) and DIR/figures/*.png|svg.
#include <filesystem>
#include <string>
#include <vector>

namespace stoneskip {

struct StonesReportOptions {
  std::filesystem::path out_dir;
  std::filesystem::path cases_dir = "cases";  // holds the shipped cases, studies/ and hard/
  int workers = 2;
  bool quick = false;   // coarser grids and fewer repeats (a smoke run, minutes → seconds)
};

struct StonesReportSummary {
  double wall_s = 0;
  int figures = 0;
  std::vector<std::string> figure_failures;
};

StonesReportSummary write_stones_report(const StonesReportOptions& options);

}  // namespace stoneskip
