#pragma once
// The report page of one capture (`stoneskip capture validate FILE --out DIR`): DIR/data.h5 first
// (the trace as read and as processed, timing, saturation, the estimates with their intervals, the
// ensemble, the solvers' trajectories, the figures' tables and scripts, provenance), then the
// figures rendered from it (traces with the release marked and clipped spans shaded, timing,
// the stone's speed, bounce-count distribution, trajectories), then DIR/index.md in words.
#include <filesystem>
#include <string>
#include <vector>

#include "reports/common/figure.hpp"
#include "verification/captures/capture_throw.hpp"

namespace stoneskip {

struct CaptureReportContext {
  std::string case_file;         // the stone case the throw ran with
  std::string case_text;
  std::string stone_description;
  std::string command_line;      // how the report was made
};

struct CaptureReportSummary {
  std::filesystem::path index_md;
  RenderSummary figures;
  bool gnuplot = false;
};

CaptureReportSummary write_capture_report(const std::filesystem::path& dir, const CaptureAnalysis& a,
                                          const CaptureSimulation& sim, const CaptureReportContext& context);

// DIR/index.md listing several captures' verdicts, linking their pages (relative folders).
struct CaptureIndexEntry {
  std::string folder;
  const CaptureAnalysis* analysis = nullptr;
  const CaptureSimulation* simulation = nullptr;
};
void write_capture_index(const std::filesystem::path& dir, const std::vector<CaptureIndexEntry>& entries,
                         const CaptureReportContext& context);

}  // namespace stoneskip
