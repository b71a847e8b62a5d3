#pragma once
// Builders for report figures: x–y line plots of several series, each
// series a table stored with the figure (so `stoneskip plot DIR` redraws it from data.h5).
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "reports/common/figure.hpp"
#include "verification/study/record.hpp"

namespace stoneskip {

struct PlotSeries {
  std::string title;             // legend entry ("" for none: a second drawing of a series)
  std::vector<double> x, y;      // NaN points are skipped by gnuplot (a NaN row breaks a line)
  std::string style = "linespoints";  // gnuplot "with" clause
  std::vector<TableSource> sources;   // where x, y come from in data.h5 (empty: computed here)
  std::optional<DerivedSeries> derived;  // with no source: what the points must satisfy
};

// A series of two columns of a table stored in a record, with its source (rows as selected; a
// y_drawn_at height replaces y, for a row of markers).
PlotSeries table_series(const std::string& title, const Record& r, const std::string& table, const std::string& x_column,
                        const std::string& y_column, const std::string& style = "linespoints",
                        TableSource::Rows rows = TableSource::Rows::all,
                        double y_drawn_at = std::numeric_limits<double>::quiet_NaN());

// The same with every choice of TableSource: rows selected by `how.rows` and `how.where_column`,
// x raised to how.x_power and y times how.y_scale (how.table is filled in from r and table).
PlotSeries table_series(const std::string& title, const Record& r, const std::string& table, TableSource how,
                        const std::string& style = "linespoints");

// The k-th (0-based) of many series told apart: a gnuplot colour clause (" lc rgb '#rrggbb'") from
// 16 distinct colours dark enough on white, and a dash type that changes each time they come round
// (" dt 1", then 3, 4): gnuplot's own cycle has 8 colours, so series 1 and 9 were drawn alike.
std::string series_colour(int k);
std::string series_dash(int k);

// A guide through (x0, y0) with slope p on log axes: y = y0 (x / x0)^p at each x.
PlotSeries power_law_guide(const std::string& title, const std::vector<double>& x, double x0, double y0, double p,
                           const std::string& style = "lines dt 2");

// The line y = a + b·x at each x, with a and b the numbers `intercept_key` and `slope_key` of r.
PlotSeries record_line(const std::string& title, const Record& r, const std::string& intercept_key, const std::string& slope_key,
                       const std::vector<double>& x, const std::string& style = "lines");

// A figure table that is table `table` of r as stored — the named columns in that order, or every
// column — recorded as such in the figure's .sources (the figure test reads it back from data.h5).
void add_stored_table(Figure& f, const std::string& name, const Record& r, const std::string& table,
                      const std::vector<std::string>& columns = {});

// A figure table computed here from stored values, with a sentence saying how (in the .sources).
void add_computed_table(Figure& f, const std::string& name, Table t, const std::string& how);

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
// The title drawn over a plot from its caption: the caption whole where it fits the plot's width
// (110 characters), else without a closing parenthetical, else cut at a word with " …".
std::string plot_title(const std::string& caption);

}  // namespace stoneskip
