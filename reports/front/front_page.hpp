#pragma once
// The front page of a main job's output (`stoneskip report front OUT`): OUT/index.md and
// OUT/index.html, linking every report in OUT (each a folder with data.h5), the movies and the
// shipped throws. For each report: its title, its verdicts in one line and a picture; then "What
// we found", each report's findings as its own opening states them (reports/common/summary.hpp).
// Everything on it is read from the reports' data.h5, the throws' .h5 and the files present:
// it decides nothing and runs nothing.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "reports/common/stored_report.hpp"

namespace stoneskip {

struct FrontReport {
  std::string folder;                 // relative to OUT: "waves"
  std::string kind, title;            // the stored kind; the page's level-1 heading
  std::string code_version, created_utc;
  std::vector<std::string> findings;  // report_findings() of its page
  std::string picture;                // a figure of it, relative to OUT ("waves/figures/x.png"); empty: none drawn
  // Its figures/: "folder" (its own), "link" (a link, not followed) or "" (none).
  std::string figures = "folder";
};

struct FrontMovie {
  std::string file;     // relative to OUT
  double size_mb = 0;
  std::string picture;  // a still beside it (or the scene report's), relative to OUT; may be empty
};

struct FrontThrowRun {
  std::string solver, outcome;
  double bounces = 0, distance_m = 0;
};

struct FrontThrow {
  std::string file, title, case_file;  // file relative to OUT
  std::vector<FrontThrowRun> runs;     // in stored order: realtime, reference
};

// Something in OUT that looked like a report, a movie or a throw and is not shown, and why.
struct FrontSkipped {
  std::string path;    // relative to OUT
  std::string reason;  // one line
};

struct FrontPageInput {
  std::vector<FrontReport> reports;
  std::vector<FrontMovie> movies;
  std::vector<FrontThrow> throws;
  std::vector<FrontSkipped> skipped;  // listed on the page under "Not shown", never dropped silently
};

// Reads OUT: every sub-folder holding a report's data.h5 (rendered in memory by `render`, which
// draws nothing), OUT/movies/*.mp4 and OUT/throws/*.h5. InputError naming OUT when it holds no report.
// A linked sub-folder or file is not followed, a data.h5 that cannot be read as a report, a movie
// stoneskip did not make (no mark, foreign_output.hpp) and a throw file that is not a throw's are
// not shown: each goes into `skipped` with its reason.
FrontPageInput read_front_page_input(const std::filesystem::path& out,
                                     const std::function<RenderedReport(const StoredReport&)>& render);

// The page's Markdown (links to the reports' index.md; the HTML page links their index.html).
std::string front_page_markdown(const FrontPageInput& in);

// Writes OUT/index.md and OUT/index.html, with a line of links to its sections (summary.hpp)
// (atomically; a link or FIFO there is refused).
void write_front_page(const std::filesystem::path& out, const std::string& markdown);

}  // namespace stoneskip
