#pragma once
// Figures of a stored sweep (its /throws table and design, verification/sweep/sweep_result.hpp):
// the library behind `stoneskip sweep-plot`, for any report that keeps its sweeps in that form.
//
//   grid designs    per solver and per pair of varied keys, a heat map of the bounce count
//                   (cells centred on the grid values; with more than two keys, the mean over
//                   the others, said in the title) with the count's thresholds as contours: the
//                   cell edges across which the count passes k + ½, i.e. as far as the grid
//                   resolves where the stone starts bouncing k + 1 times. One key: count
//                   against the key, per solver.
//   random designs  per solver and pair, the samples coloured by their count; histograms of
//                   the count per solver.
//   both solvers    the real-time − reference count per throw: a map (grid) or a scatter
//                   (random) on a diverging palette, and a histogram.
//   columns         any other column asked for (SweepMapOptions::columns): the same maps on a
//                   continuous colour scale; with one key, the column against the key.
// Throws whose solve failed or whose case could not be built are left out of every bounce-count
// figure (they are counted in the page's table). An unknown column is an InputError.
#include <string>
#include <vector>

#include "reports/common/figure.hpp"
#include "verification/sweep/sweep_result.hpp"

namespace stoneskip {

struct SweepMapOptions {
  std::string prefix = "sweep";      // figure names: <prefix>_<what>[_<solver>]_<i>_<j>
  std::size_t max_contour_levels = 6;  // thresholds drawn per map (spread over the count's range)
  std::vector<std::string> columns;  // more maps, of any column of the table on a continuous
                                     // scale (e.g. realtime_distance_m, cost_realtime_wall_s)
};

std::vector<Figure> sweep_map_figures(const SweepData& data, const SweepMapOptions& options = {});

// Building blocks (exposed for tests and for reports that draw their own maps).

// The edges of the cells around grid values (ascending): midway between neighbours, in ln x on
// a log axis; the outer edges half a spacing (ratio) beyond the end values. n values → n + 1 edges.
std::vector<double> cell_edges(const std::vector<double>& values, bool log_scale);

// A gridded map: value(ix, iy) with ix over x_values, iy over y_values; NaN = no value.
struct GridMap {
  std::vector<double> x_values, y_values;
  std::vector<double> value;  // x fastest: value[iy * nx + ix]
  double at(std::size_t ix, std::size_t iy) const { return value[iy * x_values.size() + ix]; }
};

struct Segment {
  double x0, y0, x1, y1;
};
// The cell edges across which the map passes `level` (one side <= level, the other > level,
// neither NaN): the contour of a piecewise-constant field as far as the grid resolves it.
std::vector<Segment> threshold_edges(const GridMap& map, double level, bool log_x, bool log_y);

// The mean of a column over every throw of a grid sweep, per cell of two of its axes (NaN where
// no throw has a value): the map of that column over the pair.
GridMap grid_mean(const SweepData& data, const std::vector<double>& column, std::size_t axis_x, std::size_t axis_y);

// The bounce counts of a solver's column with failed and unbuilt throws as NaN.
std::vector<double> usable_counts(const SweepData& data, const std::string& solver);

}  // namespace stoneskip
