#pragma once
// The waves report (issue 3): from the results of run_wave_studies() (verification/waves/) it
// writes DIR/data.h5 (every table behind every number and figure, with the settings and the
// code version), DIR/figures/*.png|svg (gnuplot, redrawable with `stoneskip plot DIR`) and
// DIR/index.md, which explains each section for a reader who has not seen the code.
#include <filesystem>
#include <string>
#include <vector>

#include "verification/waves/wave_studies.hpp"

namespace stoneskip {

struct WavesReportSummary {
  std::filesystem::path index;
  int figures_rendered = 0;
  std::vector<std::string> figure_failures;
  std::string brief;  // one line per finding
};

WavesReportSummary write_waves_report(const WaveStudies& studies, const std::filesystem::path& dir,
                                      const std::string& command_line, double wall_s);

}  // namespace stoneskip
