// `stoneskip bench --quick --json`: not a timing test (speed is quoted from the benchmark, never
// asserted), only that the figures the README and issue 9 name are there, and are positive and
// finite. Oracle: the JSON schema of the README; a fraction of a copy bound must lie in (0, 10)
// (above 1 only where the step beats the copy kernel in cache, never by orders of magnitude).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <nlohmann/json.hpp>

#include "tools/cli/test_support.hpp"

BOOST_AUTO_TEST_SUITE(bench_command_)

BOOST_AUTO_TEST_CASE(bench_json_names_every_headline_figure) {
  const auto r = stoneskip::test::run_stoneskip("bench --quick --json", false);
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"scene_fps_1core", "scene_fps_2cores", "stencil_cells_per_s_500", "stencil_cells_per_s_2048",
                          "bandwidth_fraction_2048", "sweep_throws_per_s", "scene_fps_1core_cpu", "per_cell_ratio_500_over_2048"}) {
    BOOST_REQUIRE_MESSAGE(j.contains(key), key);
    const double v = j[key];
    BOOST_TEST((std::isfinite(v) && v > 0), key << " = " << v);
  }
  BOOST_TEST(j["bandwidth_fraction_2048"].get<double>() < 10.0);
  BOOST_TEST(j["scene_frames"].get<long>() == 45);  // the quick scene: 0.5 s at 90 frames/s
  BOOST_TEST(j["sweep_throws"].get<long>() == 6);
}

BOOST_AUTO_TEST_SUITE_END()
