// Sweep designs against closed forms: grid endpoints exact and log-grid ratios constant
// ((to/from)^(1/(count−1))), row-major throw order, one Latin-hypercube sample per stratum per
// axis (McKay et al. 1979), uniform draws with the mean and variance of U(0, 1) within 4σ of the
// sampling error, and every value a pure function of (seed, throw, axis).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "verification/sweep/design.hpp"

using namespace stoneskip;

namespace {

constexpr double kUlps = 4e-16;  // a few ulps of a unit quantity: the grid formulas round once or twice

SweepAxis axis(const std::string& key, double from, double to, long long count, AxisScale scale = AxisScale::linear) {
  SweepAxis a;
  a.key = key;
  a.from = from;
  a.to = to;
  a.count = count;
  a.scale = scale;
  return a;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(sweep_design)

BOOST_AUTO_TEST_CASE(a_log_grid_hits_its_endpoints_exactly_and_steps_by_a_constant_ratio) {
  // Oracle: x_i = from · r^i with r = (to/from)^(1/(count−1)) = 10^(4/8) = √10.
  SweepDesign d;
  d.axes = {axis("solver.contact_dt_s", 1e-3, 10.0, 9, AxisScale::log)};
  BOOST_REQUIRE(d.is_valid(nullptr));
  const std::vector<double> v = d.grid_values(0);
  BOOST_REQUIRE_EQUAL(v.size(), 9u);
  BOOST_TEST(v.front() == 1e-3);  // exact: the endpoints are pinned
  BOOST_TEST(v.back() == 10.0);
  for (std::size_t i = 0; i + 1 < v.size(); ++i)
    BOOST_TEST(std::abs(v[i + 1] / v[i] / std::sqrt(10.0) - 1) < 8 * kUlps, "ratio " << i << ": " << v[i + 1] / v[i]);
}

BOOST_AUTO_TEST_CASE(a_linear_grid_is_equally_spaced_with_exact_endpoints) {
  // Oracle: x_i = from + i (to − from)/(count − 1).
  SweepDesign d;
  d.axes = {axis("throw.speed_m_s", 4.0, 12.0, 41)};
  const std::vector<double> v = d.grid_values(0);
  BOOST_TEST(v.front() == 4.0);
  BOOST_TEST(v.back() == 12.0);
  for (std::size_t i = 0; i < v.size(); ++i) BOOST_TEST(std::abs(v[i] - (4.0 + 0.2 * i)) < 12 * kUlps);
}

BOOST_AUTO_TEST_CASE(a_grid_of_whole_numbers_gives_whole_numbers_exactly) {
  // Oracle: 3, 4, …, 30 (28 points) and 1, 10, 100, 1000 (log, 4 points) are whole numbers, and an
  // integer key (stone.segments) refuses anything else: compared exactly, no tolerance.
  SweepDesign d;
  d.axes = {axis("stone.segments", 3.0, 30.0, 28), axis("stone.segments_b", 1.0, 1000.0, 4)};
  d.axes[1].scale = AxisScale::log;
  const std::vector<double> linear = d.grid_values(0), log = d.grid_values(1);
  for (std::size_t i = 0; i < linear.size(); ++i) BOOST_TEST(linear[i] == 3.0 + static_cast<double>(i));
  const double powers[] = {1, 10, 100, 1000};
  for (std::size_t i = 0; i < log.size(); ++i) BOOST_TEST(log[i] == powers[i]);
}

BOOST_AUTO_TEST_CASE(grid_throws_are_numbered_row_major_with_the_first_axis_slowest) {
  // Oracle: nested loops over the axes in the order given.
  SweepDesign d;
  d.axes = {axis("a", 0, 1, 2), axis("b", 10, 30, 3)};
  BOOST_REQUIRE_EQUAL(d.size(), 6u);
  std::size_t i = 0;
  for (double a : {0.0, 1.0})
    for (double b : {10.0, 20.0, 30.0}) {
      const std::vector<double> p = d.point(i++);
      BOOST_TEST(p[0] == a);
      BOOST_TEST(p[1] == b);
    }
}

BOOST_AUTO_TEST_CASE(a_latin_hypercube_has_one_sample_in_every_stratum_of_every_axis) {
  // Oracle: the definition. Stratum of x on [from, to] cut in n equal parts (in ln x on a log axis).
  SweepDesign d;
  d.kind = DesignKind::latin_hypercube;
  d.samples = 97;
  d.seed = 2024;
  d.axes = {axis("throw.speed_m_s", 2, 20, 0), axis("throw.spin_rev_s", -5, 5, 0),
            axis("environment.water_coefficient", 0.1, 10, 0, AxisScale::log)};
  BOOST_REQUIRE(d.is_valid(nullptr));
  for (std::size_t k = 0; k < d.axes.size(); ++k) {
    const SweepAxis& a = d.axes[k];
    std::vector<int> hits(static_cast<std::size_t>(d.samples), 0);
    for (std::size_t i = 0; i < d.size(); ++i) {
      const double x = d.point(i)[k];
      BOOST_REQUIRE(x >= a.from && x <= a.to);
      const double u = a.scale == AxisScale::log ? std::log(x / a.from) / std::log(a.to / a.from) : (x - a.from) / (a.to - a.from);
      ++hits[std::min<std::size_t>(static_cast<std::size_t>(u * d.samples), d.samples - 1)];
    }
    BOOST_TEST(std::all_of(hits.begin(), hits.end(), [](int h) { return h == 1; }), "axis " << a.key);
  }
}

BOOST_AUTO_TEST_CASE(latin_hypercube_strata_are_paired_differently_on_each_axis) {
  // Oracle: independent permutations per axis; identical ones would put every sample on the
  // diagonal (stratum of axis 0 = stratum of axis 1 for all n samples).
  SweepDesign d;
  d.kind = DesignKind::latin_hypercube;
  d.samples = 50;
  d.seed = 7;
  d.axes = {axis("a", 0, 1, 0), axis("b", 0, 1, 0)};
  int diagonal = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const auto p = d.point(i);
    diagonal += static_cast<int>(p[0] * 50) == static_cast<int>(p[1] * 50) ? 1 : 0;
  }
  BOOST_TEST(diagonal < 10);  // expected 1 for independent permutations; 50 if they were equal
}

BOOST_AUTO_TEST_CASE(uniform_draws_have_the_mean_and_variance_of_the_unit_interval) {
  // Oracle: U(0, 1) has mean 1/2 and variance 1/12; the sample mean's standard error is
  // 1/√(12 n), the sample variance's √((μ4 − σ⁴)/n) with μ4 = 1/80, σ⁴ = 1/144; both within 4 of them.
  SweepDesign d;
  d.kind = DesignKind::random;
  d.samples = 20000;
  d.seed = 99;
  d.axes = {axis("a", 0, 1, 0)};
  double sum = 0, sum2 = 0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const double u = d.point(i)[0];
    BOOST_REQUIRE(u > 0 && u < 1);
    sum += u;
    sum2 += u * u;
  }
  const double n = static_cast<double>(d.samples);
  const double mean = sum / n, var = sum2 / n - mean * mean;
  BOOST_TEST(std::abs(mean - 0.5) < 4 / std::sqrt(12 * n));
  BOOST_TEST(std::abs(var - 1.0 / 12) < 4 * std::sqrt(1.0 / 80 - 1.0 / 144) / std::sqrt(n));
}

BOOST_AUTO_TEST_CASE(every_point_depends_only_on_seed_throw_and_axis) {
  // Oracle: the same point whatever was computed before; another seed gives another design.
  SweepDesign d;
  d.kind = DesignKind::latin_hypercube;
  d.samples = 200;
  d.seed = 11;
  d.axes = {axis("a", 0, 1, 0), axis("b", 1, 100, 0, AxisScale::log)};
  const auto p150 = d.point(150);
  for (std::size_t i = 0; i < 150; ++i) d.point(i);
  BOOST_TEST(d.point(150) == p150);
  SweepDesign e = d;
  e.seed = 12;
  BOOST_TEST(e.point(150) != p150);
}

BOOST_AUTO_TEST_CASE(invalid_designs_name_the_axis_and_key) {
  // Oracle: the rules of design.hpp.
  auto problem = [](SweepDesign d) {
    DesignProblem p;
    BOOST_TEST(!d.is_valid(&p));
    return p;
  };
  SweepDesign d;
  d.axes = {axis("a", 1, 2, 3), axis("b", 1, 2, 0)};
  BOOST_TEST(problem(d).axis == 1);
  BOOST_TEST(problem(d).key == "count");
  d.axes = {axis("a", 0, 2, 3, AxisScale::log)};
  BOOST_TEST(problem(d).key == "from");
  d.axes = {axis("a", 3, 2, 3, AxisScale::log)};
  BOOST_TEST(problem(d).key == "to");
  d.axes = {axis("a", 1, 2, 3), axis("a", 1, 2, 3)};
  BOOST_TEST(problem(d).key == "key");
  d.axes = {axis("a", 1, 2, 1)};
  BOOST_TEST(problem(d).key == "count");
  // Several grid points on one value: identical throws, a map without x labels (accepted until
  // December 5).
  d.axes = {axis("a", 2, 2, 3)};
  const DesignProblem same = problem(d);
  BOOST_TEST(same.key == "to");
  BOOST_TEST(same.what.find("identical throws") != std::string::npos, same.what);
  d.axes = {axis("a", 2, 2, 1)};
  BOOST_TEST(d.is_valid(nullptr));
  d.axes = {};
  BOOST_TEST(problem(d).key == "vary");
  d.kind = DesignKind::random;
  d.axes = {axis("a", 1, 2, 0)};
  d.samples = 0;
  BOOST_TEST(problem(d).key == "samples");
}

BOOST_AUTO_TEST_SUITE_END()
