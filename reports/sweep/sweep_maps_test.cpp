// Sweep maps against hand-computed answers: cell edges midway between grid values (in ln x on a
// log axis), threshold contours on the cell edges where a step field passes the level, means over
// the other axes of a grid, and the figures a design gets (names, cells, histogram totals).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>

#include "reports/sweep/sweep_maps.hpp"
#include "tools/io/input_error.hpp"
#include "verification/sweep/sweep_run.hpp"

using namespace stoneskip;

namespace {

constexpr double kRoundoff = 1e-14;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();  // a few ulps of the values involved

SweepData grid_data(std::vector<long long> counts, SweepSolvers solvers, std::vector<std::string> keys = {}) {
  SweepData d;
  d.solvers = solvers;
  for (std::size_t k = 0; k < counts.size(); ++k) {
    SweepAxis a;
    a.key = k < keys.size() ? keys[k] : "k" + std::to_string(k);
    a.from = 1;
    a.to = static_cast<double>(counts[k]);
    a.count = counts[k];
    d.design.axes.push_back(a);
  }
  d.throws.columns = sweep_record(d.design, solvers).columns();
  return d;
}

// Fills the table: bounces(point) for each solver present, outcome "sank".
template <class F>
void fill(SweepData& d, F bounces) {
  const std::size_t w = d.throws.columns.size();
  d.throws.values.assign(d.design.size() * w, 0.0);
  for (std::size_t i = 0; i < d.design.size(); ++i) {
    const auto p = d.design.point(i);
    double* row = &d.throws.values[i * w];
    row[0] = static_cast<double>(i);
    for (std::size_t k = 0; k < p.size(); ++k) row[1 + k] = p[k];
    for (std::size_t c = 0; c < w; ++c) {
      if (d.throws.columns[c] == "realtime_bounces") row[c] = bounces(p, 0);
      if (d.throws.columns[c] == "reference_bounces") row[c] = bounces(p, 1);
    }
  }
}

const Figure& figure(const std::vector<Figure>& figs, const std::string& name) {
  for (const auto& f : figs)
    if (f.name == name) return f;
  BOOST_FAIL("no figure " << name);
  return figs.front();
}

const Table& table(const Figure& f, const std::string& name) {
  for (const auto& [n, t] : f.tables)
    if (n == name) return t;
  BOOST_FAIL("no table " << name << " in " << f.name);
  return f.tables.front().second;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(sweep_maps)

BOOST_AUTO_TEST_CASE(cell_edges_lie_midway_between_grid_values) {
  // Oracle: arithmetic midpoints (linear), geometric ones (log), half a step beyond the ends.
  const auto lin = cell_edges({1, 2, 4}, false);
  BOOST_TEST(lin == std::vector<double>({0.5, 1.5, 3, 5}));
  const auto log = cell_edges({1, 10, 100}, true);
  const std::vector<double> expect = {std::pow(10, -0.5), std::pow(10, 0.5), std::pow(10, 1.5), std::pow(10, 2.5)};
  for (std::size_t i = 0; i < 4; ++i) BOOST_TEST(std::abs(log[i] / expect[i] - 1) < kRoundoff);
}

BOOST_AUTO_TEST_CASE(a_step_field_has_its_threshold_on_the_cell_edges_between_the_steps) {
  // Oracle: value 1 for x >= 3, else 0, on x = 1..4, y = 1..3: the level ½ is the line x = 2.5,
  // made of one edge per row; a NaN cell breaks it.
  GridMap m;
  m.x_values = {1, 2, 3, 4};
  m.y_values = {1, 2, 3};
  for (double y : m.y_values)
    for (double x : m.x_values) m.value.push_back(x >= 3 ? 1 : 0 * y);
  auto e = threshold_edges(m, 0.5, false, false);
  BOOST_REQUIRE_EQUAL(e.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    BOOST_TEST(e[i].x0 == 2.5);
    BOOST_TEST(e[i].x1 == 2.5);
    BOOST_TEST(e[i].y0 == 0.5 + i);
    BOOST_TEST(e[i].y1 == 1.5 + i);
  }
  m.value[1 * 4 + 2] = NAN;  // (x = 3, y = 2)
  BOOST_TEST(threshold_edges(m, 0.5, false, false).size() == 2u);
  BOOST_TEST(threshold_edges(m, 1.5, false, false).empty());
}

BOOST_AUTO_TEST_CASE(a_pair_map_is_the_mean_over_the_other_axes) {
  // Oracle: column = x0 + 10 x1 + 100 x2 on a 2 × 3 × 4 grid (values 1..count); the mean over x2
  // is x0 + 10 x1 + 100 · 2.5.
  SweepData d = grid_data({2, 3, 4}, SweepSolvers::realtime);
  fill(d, [](const std::vector<double>&, int) { return 0.0; });
  std::vector<double> column;
  for (std::size_t i = 0; i < d.design.size(); ++i) {
    const auto p = d.design.point(i);
    column.push_back(p[0] + 10 * p[1] + 100 * p[2]);
  }
  const GridMap m = grid_mean(d, column, 0, 1);
  BOOST_REQUIRE_EQUAL(m.value.size(), 6u);
  for (std::size_t iy = 0; iy < 3; ++iy)
    for (std::size_t ix = 0; ix < 2; ++ix)
      BOOST_TEST(std::abs(m.at(ix, iy) - (m.x_values[ix] + 10 * m.y_values[iy] + 250)) < kRoundoff * 300);
}

BOOST_AUTO_TEST_CASE(an_axis_whose_values_are_one_ulp_apart_gets_its_tics_in_finite_time) {
  // A valid design (from < to) whose two values are 0.1 and the next double: the tic step (a fifth
  // of the range, rounded) is below 0.1's resolution, and summing it from 0.1 never reached the
  // end (sweep-plot hung). Oracle: the tics are multiples of the step inside [from, to], so here
  // 1 or 2 distinct labels, each reading 0.1 at 10 digits, at most 11 of them in any case.
  SweepData d = grid_data({2, 3}, SweepSolvers::realtime);
  d.design.axes[0].from = 0.1;
  d.design.axes[0].to = std::nextafter(0.1, 1.0);
  fill(d, [](const std::vector<double>& p, int) { return p[1]; });
  const auto figs = sweep_map_figures(d);
  const std::string& script = figure(figs, "sweep_bounces_realtime_0_1").script;
  const std::size_t at = script.find("set xtics (");
  BOOST_TEST_REQUIRE(at != std::string::npos, script);
  const std::string tics = script.substr(at, script.find('\n', at) - at);
  std::size_t labels = 0;
  for (std::size_t q = tics.find('\''); q != std::string::npos; q = tics.find('\'', tics.find('\'', q + 1) + 1)) {
    BOOST_TEST(tics.compare(q, 5, "'0.1'") == 0, tics);  // quoted(num(·)): 10 digits, 0.1 either way
    ++labels;
  }
  BOOST_TEST(labels >= 1u, tics);
  BOOST_TEST(labels <= 2u, tics);
}

BOOST_AUTO_TEST_CASE(a_two_key_grid_with_both_solvers_gets_count_and_disagreement_maps) {
  // Oracle: bounces = k0 + k1 (real-time) and k0 (reference) on a 3 × 4 grid; the disagreement
  // is k1; count thresholds are drawn between the counts present.
  SweepData d = grid_data({3, 4}, SweepSolvers::both);
  fill(d, [](const std::vector<double>& p, int solver) { return solver == 0 ? p[0] + p[1] : p[0]; });
  const auto figs = sweep_map_figures(d);
  BOOST_TEST(figs.size() == 3u);
  const Table& cells = table(figure(figs, "sweep_bounces_realtime_0_1"), "sweep_bounces_realtime_0_1_cells");
  const Table& diff = table(figure(figs, "sweep_disagreement_0_1"), "sweep_disagreement_0_1_cells");
  BOOST_REQUIRE_EQUAL(cells.rows(), 12u);
  for (std::size_t r = 0; r < cells.rows(); ++r) {
    BOOST_TEST(cells.values[r * 6 + 4] == cells.values[r * 6 + 2] + cells.values[r * 6 + 3]);
    BOOST_TEST(diff.values[r * 6 + 4] == diff.values[r * 6 + 3]);
  }
  // Counts 2..7: five thresholds, every one drawn (fewer than max_contour_levels).
  const Figure& f = figure(figs, "sweep_bounces_realtime_0_1");
  std::size_t levels = 0;
  for (const auto& [name, t] : f.tables) levels += name.find("_level") != std::string::npos ? 1 : 0;
  BOOST_TEST(levels == 5u);  // thresholds 2|3, 3|4, 4|5, 5|6, 6|7
}

BOOST_AUTO_TEST_CASE(over_a_third_axis_the_disagreement_map_is_the_share_of_throws_that_differ) {
  // Oracle: hand counts on a 2 × 3 × 2 grid. Real-time minus reference is +1 at k2 = 1 and −1 at
  // k2 = 2 where k0 = 1 (a mean over k2 of 0: the map showed agreement there), +1 and 0 where k0 = 2.
  // The share of throws that differ over k2 is 1 and ½; the (k0, k2) map, over k1, has 1 and 0 or 1.
  SweepData d = grid_data({2, 3, 2}, SweepSolvers::both);
  fill(d, [](const std::vector<double>& p, int solver) {
    if (solver == 1) return 5.0;
    if (p[0] == 1) return p[2] == 1 ? 6.0 : 4.0;
    return p[2] == 1 ? 6.0 : 5.0;
  });
  const auto figs = sweep_map_figures(d);
  const Figure& f = figure(figs, "sweep_disagreement_0_1");
  BOOST_TEST(f.title.find("Share of throws with differing counts") != std::string::npos, f.title);
  BOOST_TEST(f.title.find("(over k2)") != std::string::npos, f.title);
  const Table& cells = table(f, "sweep_disagreement_0_1_cells");
  BOOST_REQUIRE_EQUAL(cells.rows(), 6u);
  const std::size_t w = cells.columns.size();
  for (std::size_t r = 0; r < cells.rows(); ++r) {
    const double k0 = cells.values[r * w + 2], share = cells.values[r * w + 4];
    BOOST_TEST(share == (k0 == 1 ? 1.0 : 0.5), "k0 " << k0 << ": share " << share);
  }
  const Table& k0k2 = table(figure(figs, "sweep_disagreement_0_2"), "sweep_disagreement_0_2_cells");
  for (std::size_t r = 0; r < k0k2.rows(); ++r) {
    const double k0 = k0k2.values[r * w + 2], k2 = k0k2.values[r * w + 3], share = k0k2.values[r * w + 4];
    BOOST_TEST(share == (k0 == 2 && k2 == 2 ? 0.0 : 1.0), "k0 " << k0 << ", k2 " << k2 << ": share " << share);
  }
}

BOOST_AUTO_TEST_CASE(a_grid_with_one_value_on_an_axis_is_drawn_as_boxes_and_its_tables_carry_units) {
  // Oracle: gnuplot draws nothing `with image` under 2 × 2 cells ("Image grid must be at least 4
  // points"): a 3 × 1 grid's map was a white picture counted as drawn. Its cells are boxes
  // instead, each coloured by its value; the cells' units come from the axes' keys.
  SweepData d = grid_data({3, 1}, SweepSolvers::realtime, {"throw.speed_m_s", "throw.spin_rev_s"});
  fill(d, [](const std::vector<double>& p, int) { return p[0]; });
  const std::vector<Figure> figs = sweep_map_figures(d);
  const Figure& f = figure(figs, "sweep_bounces_realtime_0_1");
  BOOST_TEST(f.script.find("with image") == std::string::npos, f.script);
  BOOST_TEST(f.script.find("with boxxyerror fs solid 1.0 noborder fc palette") != std::string::npos, f.script);
  const Table& cells = table(f, "sweep_bounces_realtime_0_1_cells");
  BOOST_TEST(cells.rows() == 3u);
  const std::vector<std::string> units{"1", "1", "m/s", "rev/s", "1", "1"};
  BOOST_TEST(cells.units == units, boost::test_tools::per_element());
  // A full grid keeps the image.
  SweepData full = grid_data({3, 2}, SweepSolvers::realtime);
  fill(full, [](const std::vector<double>& p, int) { return p[0]; });
  BOOST_TEST(figure(sweep_map_figures(full), "sweep_bounces_realtime_0_1").script.find("with image") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_one_axis_count_curve_holds_each_count_to_halfway_and_marks_a_failed_run) {
  // Oracle: hand-drawn outline (reports/README.md's convention). Grid 1..5, counts 1, 1, 2, (failed),
  // 3: each count held to halfway to its neighbours with a count, the outline broken at the failed
  // run (a NaN row: a blank line), never bridged; the failed run a cross at −1.
  SweepData d = grid_data({5}, SweepSolvers::realtime, {"throw.spin_rev_s"});
  fill(d, [](const std::vector<double>& p, int) { return p[0] < 2.5 ? 1.0 : p[0] < 4.5 ? 2.0 : 3.0; });
  const std::size_t w = d.throws.columns.size(), failed_row = 3;
  for (std::size_t c = 0; c < w; ++c)
    if (d.throws.columns[c] == "realtime_outcome") d.throws.values[failed_row * w + c] = kOutcomeFailed;
  const std::vector<Figure> figs = sweep_map_figures(d);
  const Figure& f = figure(figs, "sweep_bounces");
  const Table& outline = table(f, "sweep_bounces_0_outline");
  const std::vector<std::vector<double>> expected{{1, 1}, {1.5, 1}, {1.5, 1}, {2.5, 1}, {2.5, 2}, {3, 2},
                                                  {kNaN, kNaN}, {5, 3}, {5, 3}, {kNaN, kNaN}};
  BOOST_REQUIRE_EQUAL(outline.rows(), expected.size());
  for (std::size_t r = 0; r < expected.size(); ++r)
    for (std::size_t c = 0; c < 2; ++c) {
      const double got = outline.values[r * 2 + c], want = expected[r][c];
      BOOST_TEST((std::isnan(want) ? std::isnan(got) : got == want), "row " << r << " column " << c << ": " << got);
    }
  const Table& failed = table(f, "sweep_bounces_0_failed");
  BOOST_REQUIRE_EQUAL(failed.rows(), 1u);
  BOOST_TEST(failed.values[0] == 4);
  BOOST_TEST(failed.values[1] == -1);
  BOOST_TEST(f.script.find("linespoints") == std::string::npos, f.script);
  const std::vector<std::string> units{"rev/s", "1"};
  BOOST_TEST(outline.units == units, boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(a_throw_without_a_result_is_a_grey_cell_not_a_hole_in_the_image) {
  // Oracle: one failed throw at grid point (1, 2) of a 3 × 4 grid.
  SweepData d = grid_data({3, 4}, SweepSolvers::realtime);
  fill(d, [](const std::vector<double>& p, int) { return p[0]; });
  const std::size_t w = d.throws.columns.size(), failed = 1 * 4 + 2;
  for (std::size_t c = 0; c < w; ++c)
    if (d.throws.columns[c] == "realtime_outcome") d.throws.values[failed * w + c] = kOutcomeFailed;
  const std::vector<Figure> figs = sweep_map_figures(d);
  const Figure& f = figure(figs, "sweep_bounces_realtime_0_1");
  const Table& cells = table(f, "sweep_bounces_realtime_0_1_cells");
  BOOST_TEST(cells.rows() == 12u);  // every cell present: an image needs a full grid
  const Table& empty = table(f, "sweep_bounces_realtime_0_1_empty");
  BOOST_REQUIRE_EQUAL(empty.rows(), 1u);
  BOOST_TEST(empty.values[0] == 1);
  BOOST_TEST(empty.values[1] == 2);
}

BOOST_AUTO_TEST_CASE(a_column_mapped_twice_is_one_line_of_bad_input_naming_it) {
  // Oracle: the exit-status rule (tools/README.md) — `--map X --map X` is bad input: one InputError
  // (exit 2) naming --map and the column, where main wrote the figures twice and failed inside
  // HDF5 ("cannot create group", exit 3). A column mapped once is drawn.
  SweepData d = grid_data({3, 4}, SweepSolvers::realtime);
  fill(d, [](const std::vector<double>& p, int) { return p[0]; });
  SweepMapOptions o;
  o.columns = {"realtime_bounces"};
  BOOST_CHECK_NO_THROW(sweep_map_figures(d, o));
  o.columns = {"realtime_bounces", "k0", "realtime_bounces"};
  BOOST_CHECK_EXCEPTION(sweep_map_figures(d, o), InputError, [](const InputError& e) {
    const std::string m = e.what();
    BOOST_TEST(m == "--map realtime_bounces: given more than once (each column is mapped once)");
    return m.find('\n') == std::string::npos;
  });
}

BOOST_AUTO_TEST_CASE(a_random_design_gets_scatter_maps_and_histograms_that_count_every_throw) {
  // Oracle: the number of throws.
  SweepData d;
  d.solvers = SweepSolvers::both;
  d.design.kind = DesignKind::random;
  d.design.samples = 50;
  d.design.seed = 3;
  for (const char* k : {"a", "b", "c"}) d.design.axes.push_back(SweepAxis{k, 0, 1, 0, AxisScale::linear});
  d.throws.columns = sweep_record(d.design, d.solvers).columns();
  fill(d, [](const std::vector<double>& p, int solver) { return std::floor(4 * p[0]) + solver; });
  const auto figs = sweep_map_figures(d);
  BOOST_TEST(figs.size() == 3u * 3u + 2u);  // 3 pairs × (2 solvers + disagreement) + 2 histograms
  const Figure& h = figure(figs, "sweep_bounce_histogram");
  for (std::size_t s = 0; s < 2; ++s) {
    double total = 0;
    for (double n : table(h, "sweep_bounce_histogram_" + std::to_string(s)).column("throws")) total += n;
    BOOST_TEST(total == 50);
  }
  const Table& dh = table(figure(figs, "sweep_disagreement_histogram"), "sweep_disagreement_histogram_0");
  BOOST_TEST(dh.rows() == 1u);  // every throw differs by exactly −1
  BOOST_TEST(dh.values[0] == -1);
  BOOST_TEST(dh.values[1] == 50);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(sweep_colour_bars)

// The ticks gnuplot draws on a colour bar from "set cbrange [a:b]" and "set cbtics start, step".
int colour_ticks(const std::string& script) {
  const auto r = script.find("set cbrange ["), t = script.find("set cbtics ");
  if (r == std::string::npos || t == std::string::npos) return -1;
  const double a = std::stod(script.substr(r + 13)), b = std::stod(script.substr(script.find(':', r) + 1));
  const double start = std::stod(script.substr(t + 11)), step = std::stod(script.substr(script.find(',', t) + 1));
  int n = 0;
  for (double v = start; v <= b; v += step) n += v >= a;
  return n;
}

BOOST_AUTO_TEST_CASE(a_count_map_of_54_counts_has_at_most_ten_colour_bar_ticks) {
  // Oracle: counts 0 … 53 over a 6 × 9 grid (count = 9 i + j): one tick per count was 54 ticks; a
  // step of 1, 2 or 5 × 10^k keeps them to ≤ 10 (here a step of 10: 0, 10, …, 50, six ticks), each
  // tick on a whole count, the first at or below the smallest count.
  SweepData d = grid_data({6, 9}, SweepSolvers::realtime);
  fill(d, [](const std::vector<double>& p, int) { return 9 * (p[0] - 1) + (p[1] - 1); });
  int maps = 0;
  for (const auto& f : sweep_map_figures(d)) {
    const int n = colour_ticks(f.script);
    if (n < 0) continue;
    BOOST_TEST_CONTEXT(f.name) {
      BOOST_TEST(n >= 2);
      BOOST_TEST(n <= 10);
    }
    ++maps;
  }
  BOOST_TEST(maps >= 1);
}

BOOST_AUTO_TEST_SUITE_END()
