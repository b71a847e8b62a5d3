#pragma once
// A report figure: named tables (units in the column names) plus a gnuplot script that refers to
// them as '<table>.dat'. Figures are built by a report's renderer from the tables stored in its
// data.h5 (the data come first; `stoneskip report render DIR` draws them again from the file).
// Rendering writes DIR/figures/<name>.png and .svg (and the .gp/.dat it used).
#include <filesystem>
#include <string>
#include <vector>

#include "tools/io/hdf5_file.hpp"

namespace stoneskip {

struct Figure {
  std::string name;      // file stem, [a-z0-9_]
  std::string title;     // caption in the Markdown
  std::string script;    // gnuplot body: no 'set terminal'/'set output' (render adds them)
  std::vector<std::pair<std::string, Table>> tables;  // referenced as "<name>.dat" in the script
  int width_px = 900;
  int height_px = 600;
  std::string data_path;  // where its data lie in data.h5 (e.g. "/sections/convergence"), for the caption
};

// Whole figures stored under /figures/<name> (the sweep page uses it).
void store_figure(const H5Group& figures_group, const Figure& fig);

struct RenderSummary {
  int rendered = 0;
  std::vector<std::string> failures;  // "name: gnuplot said ..."
};

// Writes <dir>/figures/<name>.{gp,png,svg} and the .dat files; runs gnuplot (PNG via pngcairo,
// and SVG). A figure that gnuplot rejects is listed in the summary, never silently dropped. Every
// file is written beside its final name and renamed over it: a link, FIFO or device there (or a
// `figures` that is not a plain folder) is refused with InputError before anything is written.
RenderSummary render_figures(const std::filesystem::path& dir, const std::vector<Figure>& figs);

// Markdown for a figure: ![title](figures/name.png) with a link to the SVG.
std::string figure_markdown(const Figure& fig);

// True if gnuplot can be run.
bool gnuplot_available();

}  // namespace stoneskip
