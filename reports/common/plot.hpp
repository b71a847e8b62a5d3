#pragma once
// Builders for report figures: x–y line plots of several series, each
// series a table stored with the figure (so `stoneskip plot DIR` redraws it from data.h5).
#include <string>
#include <vector>

#include "reports/common/figure.hpp"

namespace stoneskip {

struct PlotSeries {
  std::string title;             // legend entry
  std::vector<double> x, y;      // NaN points are skipped by gnuplot
  std::string style = "linespoints";  // gnuplot "with" clause
};

struct PlotAxes {
  std::string x_label, y_label;
  bool log_x = false, log_y = false;
  std::string extra;             // extra gnuplot lines (ranges, keys, labels)
};

// Columns of each stored table: x_label and y_label with units (e.g. "dt_s", "error_m").
Figure line_figure(const std::string& name, const std::string& title, const PlotAxes& axes,
                   const std::vector<PlotSeries>& series, const std::string& x_column, const std::string& y_column);

// Gnuplot needs quotes escaped in titles.
std::string gnuplot_quote(const std::string& s);

}  // namespace stoneskip
