#pragma once
// The page of a stored sweep (`stoneskip sweep-plot FILE.h5 --out DIR`): DIR/index.md and the same page as index.html (what was
// swept, outcomes and bounce counts per solver, agreement of the solvers, what the throws cost and
// how the run scaled), DIR/data.h5 (/figures: every figure's tables and gnuplot script, so
// `stoneskip plot DIR` redraws them) and DIR/figures/*.png|svg (sweep_maps.hpp).
#include <filesystem>
#include <string>
#include <vector>

#include "reports/common/figure.hpp"
#include "reports/sweep/sweep_maps.hpp"
#include "verification/sweep/sweep_result.hpp"

namespace stoneskip {

std::string sweep_markdown(const SweepData& data, const std::vector<Figure>& figures, const std::string& source_file);

struct SweepPageSummary {
  std::size_t figures = 0;
  RenderSummary render;
};
// Writes the folder; render = false stores the figures without running gnuplot.
SweepPageSummary write_sweep_page(const std::filesystem::path& dir, const SweepData& data, const std::string& source_file,
                                  const SweepMapOptions& maps = {}, bool render = true);

}  // namespace stoneskip
