#pragma once
// A report figure: named tables (units in the column names) plus a gnuplot script that refers to
// them as '<table>.dat'. Figures are built by a report's renderer from the tables stored in its
// data.h5 (the data come first; `stoneskip report render DIR` draws them again from the file).
// Rendering writes DIR/figures/<name>.png and .svg (and the .gp/.dat it used).
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "tools/io/hdf5_file.hpp"

namespace stoneskip {

// Where the points of one of a figure's tables come from: rows of a table stored in data.h5 and
// two of its columns. A plotted table may gather several sources (a step curve: the grid's counts
// and the ends of the bisected brackets); its rows that are not NaN are exactly their union. The
// figure test (tools/cli/report_command_test.cpp) checks every plotted point against them.
struct TableSource {
  enum class Rows { all, y_nonnegative, y_negative };  // a count's failed runs are stored as < 0
  std::string table;                    // data.h5 path of the stored table
  std::string x_column, y_column;
  Rows rows = Rows::all;
  double y_drawn_at = std::numeric_limits<double>::quiet_NaN();  // not NaN: every row drawn at this
                                                                  // height (a row of markers)
};
const char* rows_name(TableSource::Rows r);

struct Figure {
  std::string name;      // file stem, [a-z0-9_]
  std::string title;     // caption in the Markdown
  std::string script;    // gnuplot body: no 'set terminal'/'set output' (render adds them)
  std::vector<std::pair<std::string, Table>> tables;  // referenced as "<name>.dat" in the script
  int width_px = 900;
  int height_px = 600;
  std::string data_path;  // where its data lie in data.h5 (e.g. "/sections/convergence"), for the caption
  // Per table name, where its points come from (line figures: one entry per series, an empty list
  // for a series computed from no stored table, e.g. a reference slope). Rendering writes them to
  // <name>.sources beside the .dat files.
  std::vector<std::pair<std::string, std::vector<TableSource>>> sources;
};

// Whole figures stored under /figures/<name> (the sweep page uses it).
void store_figure(const H5Group& figures_group, const Figure& fig);

struct RenderSummary {
  int rendered = 0;
  std::vector<std::string> failures;  // "name: gnuplot said ..."
};

// Writes <dir>/figures/<name>.{gp,png,svg}, the .dat files and, for a figure with sources,
// <name>.sources (a line per source: table, data.h5 path, x column, y column, rows, drawn-at
// height or NaN, tab-separated; a table with no stored source: its name and "-"); runs gnuplot (PNG via pngcairo,
// and SVG). A figure that gnuplot rejects is listed in the summary, never silently dropped. Every
// file is written beside its final name and renamed over it: a link, FIFO or device there (or a
// `figures` that is not a plain folder) is refused with InputError before anything is written.
RenderSummary render_figures(const std::filesystem::path& dir, const std::vector<Figure>& figs);

// Markdown for a figure: ![title](figures/name.png) with a link to the SVG.
std::string figure_markdown(const Figure& fig);

// True if gnuplot can be run.
bool gnuplot_available();

}  // namespace stoneskip
