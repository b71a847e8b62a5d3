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
  // A count's failed runs are stored as < 0; y_positive: a row with y ≤ 0 is a gap in the line.
  enum class Rows { all, y_nonnegative, y_negative, y_positive, y_nonpositive };
  std::string table;                    // data.h5 path of the stored table
  std::string x_column, y_column;
  Rows rows = Rows::all;
  double y_drawn_at = std::numeric_limits<double>::quiet_NaN();  // not NaN: every row drawn at this
                                                                  // height (a row of markers)
  double x_power = 1;                   // drawn x = stored x^x_power (1 or 2: against V², Ω²)
  double y_scale = 1;                   // drawn y = y_scale · stored y (a change of unit)
  std::string where_column;             // not empty: only the rows where this column …
  double where_value = 0;               // … equals this value (one family of a long table)
};
const char* rows_name(TableSource::Rows r);

// A series drawn from no stored table directly, with what it must satisfy (the figure test checks
// it): the step outline through another series' points, a guide y = c·x^p, or the line
// y = a + b·x whose a and b are numbers stored in a record.
struct DerivedSeries {
  enum class Kind { outline, power_law, line };
  Kind kind = Kind::power_law;
  std::string of_table;                 // outline: the figure table holding its points
  int of_offset = 1;                    // outline, in a PlotSeries list: that series' place after this one
  double exponent = 1;                  // power_law: p
  std::string record, intercept_key, slope_key;  // line: data.h5 path of the record, and its keys
};

// A figure table that is columns of a stored table, every row in order (a capture's samples), or,
// with `estimates`, a row per stored estimate: a position, then its numbers nominal, low and high.
struct TableCopy {
  std::string table;                    // data.h5 path of the stored table
  std::vector<std::string> columns;     // in the figure table's order; none: every column ("*")
  std::vector<std::string> estimates;   // instead: the data.h5 path of each row's estimate record
  std::string computed;                 // neither: why the table is computed from no stored one
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
  std::vector<std::pair<std::string, DerivedSeries>> derived;  // per table name, when drawn from no table
  std::vector<std::pair<std::string, TableCopy>> copies;       // per table name, a stored table's columns
};

// Whole figures stored under /figures/<name> (the sweep page uses it).
void store_figure(const H5Group& figures_group, const Figure& fig);

struct RenderSummary {
  int rendered = 0;
  std::vector<std::string> failures;  // "name.kind: gnuplot said ..."
  // Per figure with a file not drawn, in the figures' order: its name and the first failure's words.
  std::vector<std::pair<std::string, std::string>> not_drawn;
  bool scripts_written = true;  // false where gnuplot was not found and nothing was written
};

// Writes <dir>/figures/<name>.{gp,png,svg}, the .dat files and, for a figure with sources,
// <name>.sources, tab-separated, a line per source: "table, data.h5 path, x column, y column, rows,
// drawn-at height or NaN, x power, y scale, where column or -, where value"; "table, outline, other
// table"; "table, power_law, p"; "table, line, record path, intercept key, slope key"; "table, copy,
// data.h5 path, columns joined by ','"; "table, estimates, record paths joined by ','"; "table, -,
// why it is computed from no stored table"; a line-figure series with none of these: "table, -");
// runs gnuplot (PNG via pngcairo,
// and SVG). A figure that gnuplot rejects is listed in the summary, never silently dropped. Every
// file is written beside its final name and renamed over it: a link, FIFO or device there (or a
// `figures` that is not a plain folder) is refused with InputError before anything is written.
RenderSummary render_figures(const std::filesystem::path& dir, const std::vector<Figure>& figs);

// Every file render_figures writes for figs, relative to dir ("figures/<name>.png", …).
std::vector<std::filesystem::path> figure_files(const std::vector<Figure>& figs);

// Removes from dir every file render_figures would write for figs, where they are (each checked
// first, as render_figures checks them: a link, FIFO or device among them is refused with InputError
// and nothing removed). Where gnuplot cannot be run no picture, script or table of an earlier
// rendering, drawn from other data, stays beside a page that says no figure was drawn.
void remove_figure_files(const std::filesystem::path& dir, const std::vector<Figure>& figs);

// Markdown for a figure: ![title](figures/name.png) with a link to the SVG.
std::string figure_markdown(const Figure& fig);

// The page's Markdown with each figure of `s.not_drawn` shown as a paragraph that names it and says
// why it was not drawn, where its data and script are, in place of its image: a link to a picture
// that is not there reads as a broken page, not as a result. A figure whose Markdown is not in the
// page is left as it is.
std::string mark_figures_not_drawn(std::string markdown, const std::vector<Figure>& figs, const RenderSummary& s);

// The paragraph that stands for a figure not drawn, with gnuplot's (or the renderer's) words, and
// where its script is when it was written.
std::string figure_not_drawn_markdown(const Figure& fig, const std::string& why, bool script_written = true);

// True if gnuplot can be run.
bool gnuplot_available();

}  // namespace stoneskip
