#pragma once
// A report as stored in its data.h5 (reports/common/report_build.hpp writes it): the provenance,
// the settings it was computed from, the report-wide record and the section records in order.
// Every renderer takes this and nothing else, so `stoneskip report render DIR` rebuilds index.md
// and the figures from the file alone, byte for byte.
#include <filesystem>
#include <string>
#include <vector>

#include "reports/common/figure.hpp"
#include "reports/common/section.hpp"
#include "verification/study/record.hpp"

namespace stoneskip {

struct StoredReport {
  std::filesystem::path file;
  std::string kind;          // "waves", "stones", …
  std::string code_version, created_utc, settings, command;
  Record report;             // /report
  Record sections;           // /sections, children in the order the study stored them
};

// InputError naming the file when it is not a stoneskip report's data.h5, or one so damaged that
// reading it crashes or hangs the HDF5 library (read in a child first: tools/io/isolated_read.hpp).
StoredReport load_stored_report(const std::filesystem::path& data_h5);

struct RenderedReport {
  std::string markdown;
  std::vector<Figure> figures;
  std::string headline_figure;  // the figure the front page shows for this report; empty: the first
};

// Appends a section's output to a rendered report.
void append(RenderedReport& r, const SectionOutput& s);

// The closing block every report ends with: code version, creation time, the command and where
// the settings are.
std::string provenance_markdown(const StoredReport& s);

// Writes dir/index.md (with a line of links to its sections before the first, summary.hpp) and,
// from the same text, dir/index.html (reports/common/html_page.hpp; both
// atomically) and draws the figures into dir/figures/. Figures gnuplot
// rejects (or all of them, without gnuplot) are listed in the summary, never silently dropped.
RenderSummary write_rendered_report(const std::filesystem::path& dir, const RenderedReport& r);
// Every file write_rendered_report writes, relative to dir.
std::vector<std::filesystem::path> rendered_files(const RenderedReport& r);

}  // namespace stoneskip
