// Oracle: the JSON schema of verification/README.md ("Benchmarks") and identities between its own figures that a wrong
// measurement would break — not the speeds themselves (speed is quoted from the benchmark, never
// asserted): thread CPU ≤ wall for the one-thread scene, the fraction of the copy bound is the
// cell rate over the bound, the per-cell ratio is the 500² rate over the large grid's, the sweep's
// summed CPU fits in workers × wall, and the counts are duration × rate and spins × angles.
// The sweep's agreement with CVODE is recomputed from the per-throw counts it stores, and those
// counts against `stoneskip run` on the same throw (an independent path: the case parsed with --set).
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tools/cli/test_support.hpp"

namespace {

// One quick bench for the tests that read its JSON (it costs seconds).
const nlohmann::json& quick_bench_json() {
  static const nlohmann::json j = [] {
    const auto r = stoneskip::test::run_stoneskip("bench --quick --json", false);
    BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
    return nlohmann::json::parse(r.out);
  }();
  return j;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(bench_command_)

BOOST_AUTO_TEST_CASE(bench_json_names_every_headline_figure_and_they_agree) {
  constexpr double kRoundoff = 1e-12;   // a ratio recomputed from printed doubles (17 digits)
  constexpr double kClockSlack = 0.05;  // thread-CPU and wall clocks read at different instants, coarse CPU ticks on a VM
  const nlohmann::json& j = quick_bench_json();
  // --quick measures the large grid at 1024²: its figures are under _1024 keys, the 2048² keys null.
  BOOST_TEST(j["stencil_n_large"].get<long>() == 1024);
  for (const char* key : {"scene_fps_1core", "scene_fps_2cores", "stencil_cells_per_s_500", "stencil_cells_per_s_1024",
                          "bandwidth_fraction_1024", "sweep_throws_per_s", "scene_fps_1core_cpu", "per_cell_ratio_500_over_1024",
                          "copy_bound_cells_per_s_1024", "scene_wall_s_1core", "scene_cpu_s_1core", "sweep_wall_s", "sweep_cpu_s"}) {
    BOOST_REQUIRE_MESSAGE(j.contains(key), key);
    const double v = j[key];
    BOOST_TEST((std::isfinite(v) && v > 0), key << " = " << v);
  }
  for (auto it = j.begin(); it != j.end(); ++it)
    if (it.key().find("_2048") != std::string::npos) BOOST_TEST(it.value().is_null(), it.key() << " = " << it.value());
  const double d = j["bandwidth_fraction_1024"].get<double>() -
                   j["stencil_cells_per_s_1024"].get<double>() / j["copy_bound_cells_per_s_1024"].get<double>();
  BOOST_TEST(std::abs(d) <= kRoundoff * j["bandwidth_fraction_1024"].get<double>());
  const double ratio = j["stencil_cells_per_s_500"].get<double>() / j["stencil_cells_per_s_1024"].get<double>();
  BOOST_TEST(std::abs(j["per_cell_ratio_500_over_1024"].get<double>() - ratio) <= kRoundoff * ratio);
  // One thread: its CPU time cannot exceed the wall time it ran in.
  BOOST_TEST(j["scene_cpu_s_1core"].get<double>() <= (1 + kClockSlack) * j["scene_wall_s_1core"].get<double>());
  BOOST_TEST(j["scene_fps_1core"].get<double>() * j["scene_wall_s_1core"].get<double>() == j["scene_frames"].get<double>(),
             boost::test_tools::tolerance(kRoundoff));
  // The sweep's throws ran on sweep_workers threads during its wall time.
  BOOST_TEST(j["sweep_cpu_s"].get<double>() <= (1 + kClockSlack) * j["sweep_workers"].get<double>() * j["sweep_wall_s"].get<double>());
  BOOST_TEST(j["scene_frames"].get<long>() == 45);  // the quick scene: 0.5 s at 90 frames/s
  BOOST_TEST(j["scene_repeats"].get<long>() == 1);   // --quick without --repeats: each part once
  BOOST_TEST(j["sweep_repeats"].get<long>() == 1);
  BOOST_TEST(j["sweep_throws"].get<long>() == 6);   // 3 spins × 2 attack angles
  BOOST_TEST(j["sweep_throws_per_s"].get<double>() * j["sweep_wall_s"].get<double>() == 6.0, boost::test_tools::tolerance(kRoundoff));
}

BOOST_AUTO_TEST_CASE(bench_sweep_match_fraction_is_its_own_counts_and_the_counts_are_stoneskip_run_s) {
  constexpr double kRoundoff = 1e-15;  // one division of two small whole numbers
  const nlohmann::json& j = quick_bench_json();
  // The sweep names its stepper: the adaptive one at its default tolerance, rtol = atol_m.
  BOOST_TEST(j["sweep_scheme"].get<std::string>() == "bs32");
  BOOST_TEST(j["sweep_rtol"].get<double>() == 1e-9);
  BOOST_TEST(j["sweep_atol_m"].get<double>() == j["sweep_rtol"].get<double>());
  const auto rt = j["sweep_bounces"].get<std::vector<int>>();
  const auto cv = j["sweep_cvode_bounces"].get<std::vector<std::vector<int>>>();
  const auto tols = j["sweep_cvode_rtols"].get<std::vector<double>>();
  BOOST_REQUIRE_EQUAL(rt.size(), 6u);  // 3 spins × 2 attack angles
  BOOST_REQUIRE_EQUAL(cv.size(), 2u);
  BOOST_REQUIRE(tols == (std::vector<double>{1e-8, 1e-10}));
  long agreeing = 0, matched = 0;
  for (std::size_t i = 0; i < rt.size(); ++i) {
    BOOST_REQUIRE(cv[0].size() == rt.size() && cv[1].size() == rt.size());
    if (cv[0][i] < 0 || cv[0][i] != cv[1][i]) continue;
    ++agreeing;
    if (rt[i] == cv[0][i]) ++matched;
  }
  BOOST_TEST(j["sweep_cvode_agreeing_throws"].get<long>() == agreeing);
  BOOST_TEST(j["sweep_cvode_matched_throws"].get<long>() == matched);
  BOOST_REQUIRE(agreeing > 0);  // the quick throws are not all chaotic
  const double fraction = j["sweep_cvode_match_fraction"].get<double>();
  BOOST_TEST(std::abs(fraction - double(matched) / agreeing) <= kRoundoff);
  BOOST_TEST((fraction >= 0 && fraction <= 1));
  // Passivity (oracle: the physical convention's water and air forces only take energy from the
  // stone; a gain over a contact is the integrator's): none of the quick grid's throws gains any.
  BOOST_TEST(j["sweep_max_energy_gain_J"].get<double>() == 0.0);
  BOOST_TEST(j["sweep_throws_gaining_energy"].get<long>() == 0);
  // Throw 3 of the grid (spins outer, attacks inner: spin 20 rev/s, attack 20°) through `run`.
  const std::string run = "run cases/spin_sweep_base.toml --set throw.spin_rev_s=20 --set throw.attack_angle_deg=20 --json";
  const auto a = stoneskip::test::run_stoneskip(run + " --solver realtime --set solver.scheme=bs32 --set solver.rtol=1e-9 --set solver.atol_m=1e-9", false);
  BOOST_REQUIRE_MESSAGE(a.status == 0, a.out);
  BOOST_TEST(nlohmann::json::parse(a.out)["bounces"].get<int>() == rt[3]);
  for (int k = 0; k < 2; ++k) {
    char set[96];
    std::snprintf(set, sizeof set, " --set reference.rtol=%g --set reference.atol=%g", tols[k], tols[k]);
    const auto c = stoneskip::test::run_stoneskip(run + " --solver reference" + set, false);
    BOOST_REQUIRE_MESSAGE(c.status == 0, c.out);
    BOOST_TEST(nlohmann::json::parse(c.out)["bounces"].get<int>() == cv[k][3], "CVODE rtol " << tols[k]);
  }
}

BOOST_AUTO_TEST_CASE(bench_short_flight_split_is_recounted_from_stoneskip_run_s_contact_lists) {
  // Oracle: an independent path to each quick throw's reference contacts, `stoneskip run --solver
  // reference` at the finer of bench's CVODE tolerances with the throw given by --set; its shortest
  // flight (the least gap between consecutive contacts' end and start) against the bench's 1 ms
  // line recounts the split of the agreement. Exact: counts of whole throws, one division.
  constexpr double kRoundoff = 1e-15;
  const nlohmann::json& j = quick_bench_json();
  const auto rt = j["sweep_bounces"].get<std::vector<int>>();
  const auto cv = j["sweep_cvode_bounces"].get<std::vector<std::vector<int>>>();
  const double line = j["sweep_cvode_short_flight_s"].get<double>();
  BOOST_TEST(line == 1e-3);
  const double spins[] = {0, 20, 40}, attacks[] = {10, 20};  // bench --quick's grid, spins outer
  long with = 0, matched_with = 0, without = 0, matched_without = 0;
  for (std::size_t i = 0; i < rt.size(); ++i) {
    if (cv[0][i] < 0 || cv[0][i] != cv[1][i]) continue;
    char cmd[256];
    std::snprintf(cmd, sizeof cmd,
                  "run cases/spin_sweep_base.toml --set throw.spin_rev_s=%g --set throw.attack_angle_deg=%g --json "
                  "--solver reference --set reference.rtol=1e-10 --set reference.atol=1e-10",
                  spins[i / 2], attacks[i % 2]);
    const auto r = stoneskip::test::run_stoneskip(cmd, false);
    BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
    const nlohmann::json c = nlohmann::json::parse(r.out)["contacts"];
    double shortest = INFINITY;
    for (std::size_t k = 1; k < c.size(); ++k)
      shortest = std::min(shortest, c[k]["start_s"].get<double>() - c[k - 1]["end_s"].get<double>());
    const bool matched = rt[i] == cv[1][i];
    if (shortest < line) {
      ++with;
      if (matched) ++matched_with;
    } else {
      ++without;
      if (matched) ++matched_without;
    }
  }
  BOOST_TEST(j["sweep_cvode_throws_with_short_flight"].get<long>() == with);
  BOOST_TEST(j["sweep_cvode_matched_with_short_flight"].get<long>() == matched_with);
  BOOST_REQUIRE(without > 0);
  BOOST_TEST(std::abs(j["sweep_cvode_match_fraction_without_short_flight"].get<double>() - double(matched_without) / without) <=
             kRoundoff);
}

BOOST_AUTO_TEST_CASE(bench_budget_ladder_counts_are_stoneskip_run_s_and_its_matches_are_recounted) {
  // Oracles: (1) `stoneskip run` with the same budget in the case ([solver] rhs_per_frame, parsed
  // with --set): an independent path to the same throw's count; (2) the matches recounted from the
  // stored counts against CVODE's agreed ones; (3) the smallest budget meeting the target, found
  // again from the stored fractions by its rule (at it and at every larger one).
  const nlohmann::json& j = quick_bench_json();
  const auto cv = j["sweep_cvode_bounces"].get<std::vector<std::vector<int>>>();
  const auto& ladder = j["budget_ladder"];
  BOOST_REQUIRE(ladder.is_array());
  BOOST_REQUIRE_EQUAL(ladder.size(), 2u);  // --quick: 16 and 64
  BOOST_TEST(std::abs(j["budget_frame_dt_s"].get<double>() - 1.0 / 90) <= 1e-15);
  for (const auto& r : ladder) {
    const auto b = r["bounces"].get<std::vector<int>>();
    BOOST_REQUIRE_EQUAL(b.size(), 6u);
    long compared = 0, matched = 0;
    for (std::size_t i = 0; i < b.size(); ++i) {
      if (cv[0][i] < 0 || cv[0][i] != cv[1][i] || b[i] < 0) continue;
      ++compared;
      if (b[i] == cv[0][i]) ++matched;
    }
    BOOST_TEST(r["cvode_compared_throws"].get<long>() == compared);
    BOOST_TEST(r["cvode_matched_throws"].get<long>() == matched);
    BOOST_TEST(r["forced_step_fraction"].get<double>() >= 0);
    BOOST_TEST(r["forced_step_fraction"].get<double>() <= 1);
    // Passivity under a budget: forced steps are inaccurate, and must still not create energy on
    // these physical throws (as for the sweep itself).
    BOOST_TEST(r["max_energy_gain_J"].get<double>() == 0.0);
    BOOST_TEST(r["throws_gaining_energy"].get<long>() == 0);
  }
  // At 16 right-hand sides per 11.1 ms frame (a 1.4 ms step at best) a contact's steps are forced.
  BOOST_TEST(ladder[0]["forced_step_fraction"].get<double>() > 0);
  BOOST_TEST(ladder[0]["max_error_ratio"].get<double>() > 1);
  const std::string run = "run cases/spin_sweep_base.toml --set throw.spin_rev_s=20 --set throw.attack_angle_deg=20 --json"
                          " --solver realtime --set solver.scheme=bs32 --set solver.rtol=1e-9 --set solver.atol_m=1e-9"
                          " --set solver.rhs_per_frame=64";
  const auto a = stoneskip::test::run_stoneskip(run, false);
  BOOST_REQUIRE_MESSAGE(a.status == 0, a.out);
  BOOST_TEST(nlohmann::json::parse(a.out)["bounces"].get<int>() == ladder[1]["bounces"][3].get<int>());
  long smallest = -1;
  for (std::size_t k = ladder.size(); k-- > 0;) {
    if (!(ladder[k]["cvode_match_fraction_low"].get<double>() >= 0.98)) break;
    smallest = ladder[k]["rhs_per_frame"].get<long>();
  }
  const auto& key = j["budget_rhs_per_frame_for_match_target"];
  if (smallest < 0)
    BOOST_TEST(key.is_null());
  else
    BOOST_TEST(key.get<long>() == smallest);
}

BOOST_AUTO_TEST_CASE(bench_scene_is_held_to_the_scene_limits) {
  // Oracle: `scene` refuses this case (its 1e6 s of 500² water is 2e13 cell updates, past the
  // 5e10 limit of tools/scene/resource_estimate.hpp); `bench --scene` runs the same scene, so it
  // must refuse it the same way — exit 2, one line naming the case — before measuring anything.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("stoneskip_bench_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path heavy = dir / "heavy.toml";
  std::string text = stoneskip::test::read_file("cases/scenes/seed_8ms.toml");
  const auto at = text.find("duration_s = 3.0");
  BOOST_REQUIRE(at != std::string::npos);
  text.replace(at, 16, "duration_s = 1.0e6");
  std::ofstream(heavy) << text;
  for (const char* command : {"scene", "bench --repeats 1 --scene"}) {
    const auto r = stoneskip::test::run_stoneskip(std::string(command) + " " + heavy.string());
    BOOST_TEST(r.status == 2, command << ": exit " << r.status << ": " << r.out);
    BOOST_TEST(r.out.find(heavy.string()) != std::string::npos, r.out);
    BOOST_TEST(std::count(r.out.begin(), r.out.end(), '\n') == 1, r.out);
  }
  std::filesystem::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(bench_text_names_the_grid_it_measured) {
  // Oracle: --quick measures the large stencil at 1024² (HeadlineSpeedOptions::stencil_large_n),
  // so its text must say 1024² and never 2048².
  const auto r = stoneskip::test::run_stoneskip("bench --quick --repeats 1", false);
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  BOOST_TEST(r.out.find("1024²") != std::string::npos, r.out);
  BOOST_TEST(r.out.find("2048²") == std::string::npos, r.out);
}

BOOST_AUTO_TEST_CASE(bench_sweep_only_claims_nothing_it_did_not_measure_and_judges_on_the_interval) {
  // Oracle: --sweep-only runs no scene and no stencil, so their keys are null (they were zeros, and
  // the text said "met" and "MISSED" of them); the sweep's match fraction carries its 95 % Wilson
  // interval, recomputed here from its counts, and the verdict reads its lower end: 6 of 6 (lower
  // end 6/(6 + z²) = 0.61) does not show 0.98.
  const auto r = stoneskip::test::run_stoneskip("bench --quick --sweep-only --json", false);
  BOOST_REQUIRE_MESSAGE(r.status == 0, r.out);
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"scene_fps_1core", "scene_fps_2cores", "scene_frames", "stencil_cells_per_s_500", "stencil_isa",
                          "bandwidth_fraction_2048", "per_cell_ratio_500_over_2048", "temporal_blocking_fraction_2048",
                          "plain_loop_cells_per_s_500"})
    BOOST_TEST(j[key].is_null(), key << " = " << j[key].dump());
  BOOST_TEST(j["sweep_throws_per_s"].get<double>() > 0);
  const double n = j["sweep_cvode_agreeing_throws"].get<double>(), k = j["sweep_cvode_matched_throws"].get<double>();
  const double z = 1.959963984540054, p = k / n;
  const double low = (p + z * z / (2 * n) - z * std::sqrt(p * (1 - p) / n + z * z / (4 * n * n))) / (1 + z * z / n);
  BOOST_TEST(j["sweep_cvode_match_fraction_low"].get<double>() == low, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(j["sweep_cvode_match_fraction_low"].get<double>() < 0.98);
  const auto t = stoneskip::test::run_stoneskip("bench --quick --sweep-only", false);
  BOOST_REQUIRE_MESSAGE(t.status == 0, t.out);
  BOOST_TEST(t.out.find("not measured (--sweep-only)") != std::string::npos, t.out);
  BOOST_TEST(t.out.find("seed's scene") == std::string::npos, t.out);
  BOOST_TEST(t.out.find("(95 % interval)  MISSED") != std::string::npos, t.out);
}

BOOST_AUTO_TEST_CASE(bench_names_another_scene_by_its_file_and_holds_it_to_no_target) {
  // Oracle: the bench's targets (README, "Speed"): 3000 frames/s is the seed's scene's; a scene
  // given with --scene is another workload, which had been labelled "seed's scene" and marked
  // against that target.
  const auto other = stoneskip::test::run_stoneskip("bench --quick --scene cases/scenes/swell_8ms.toml", false);
  BOOST_REQUIRE_MESSAGE(other.status == 0, other.out);
  BOOST_TEST(other.out.find("seed's scene") == std::string::npos, other.out);
  const auto at = other.out.find("scene swell_8ms.toml (");
  BOOST_REQUIRE_MESSAGE(at != std::string::npos, other.out);
  const std::string row = other.out.substr(at, other.out.find('\n', at) - at);
  BOOST_TEST(row.find(">=") == std::string::npos, row);
  const auto seed = stoneskip::test::run_stoneskip("bench --quick --scene cases/scenes/seed_8ms.toml", false);
  BOOST_REQUIRE_MESSAGE(seed.status == 0, seed.out);
  const auto seed_at = seed.out.find("seed's scene (");
  BOOST_REQUIRE_MESSAGE(seed_at != std::string::npos, seed.out);
  const std::string seed_row = seed.out.substr(seed_at, seed.out.find('\n', seed_at) - seed_at);
  BOOST_TEST(seed_row.find(">= 3000") != std::string::npos, seed_row);  // a whole target in full
}

BOOST_AUTO_TEST_CASE(bench_refuses_a_bad_repeat_count) {
  // Oracle: the input rules — one line naming the option, exit 2.
  const auto r = stoneskip::test::run_stoneskip("bench --quick --repeats 0");
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.out.find("--repeats") != std::string::npos, r.out);
}

BOOST_AUTO_TEST_CASE(bench_refuses_a_sweep_tolerance_of_zero_or_below_rather_than_reading_it_as_the_default) {
  // Oracle: the input rules (no silent default for a bad value) — one line naming the option, exit 2.
  for (const char* v : {"0", "-1e-8", "1"}) {
    const auto r = stoneskip::test::run_stoneskip(std::string("bench --quick --sweep-only --sweep-rtol ") + v);
    BOOST_TEST(r.status == 2, v);
    BOOST_TEST(r.out.find("--sweep-rtol") != std::string::npos, r.out);
  }
}

BOOST_AUTO_TEST_CASE(bench_sweeps_with_the_named_adaptive_pair_and_refuses_a_fixed_scheme) {
  // Oracles: the input rules (one line naming the option, exit 2, for a scheme that takes no
  // tolerance or does not exist); and `run`: with --sweep-scheme dp54 the sweep's count for a
  // throw is the one `stoneskip run` gives that throw under dp54 at the same tolerance.
  for (const char* v : {"rk4", "dp45"}) {
    const auto r = stoneskip::test::run_stoneskip(std::string("bench --quick --sweep-only --sweep-scheme ") + v);
    BOOST_TEST(r.status == 2, v);
    BOOST_TEST(r.out.find("--sweep-scheme") != std::string::npos, r.out);
  }
  const auto b = stoneskip::test::run_stoneskip("bench --quick --sweep-only --sweep-scheme dp54 --json", false);
  BOOST_REQUIRE_MESSAGE(b.status == 0, b.out);
  const nlohmann::json j = nlohmann::json::parse(b.out);
  BOOST_TEST(j["sweep_scheme"].get<std::string>() == "dp54");
  const auto rt = j["sweep_bounces"].get<std::vector<int>>();
  BOOST_REQUIRE_EQUAL(rt.size(), 6u);  // 3 spins × 2 attack angles
  // Throw 5 of the grid (spins outer, attacks inner: spin 40 rev/s, attack 20°).
  const auto a = stoneskip::test::run_stoneskip(
      "run cases/spin_sweep_base.toml --set throw.spin_rev_s=40 --set throw.attack_angle_deg=20 --json --solver realtime "
      "--set solver.scheme=dp54 --set solver.rtol=1e-9 --set solver.atol_m=1e-9",
      false);
  BOOST_REQUIRE_MESSAGE(a.status == 0, a.out);
  BOOST_TEST(nlohmann::json::parse(a.out)["bounces"].get<int>() == rt[5]);
}

BOOST_AUTO_TEST_CASE(bench_refuses_a_live_water_sweep_case_rather_than_timing_it_on_still_water) {
  // Oracle: the input rules. The sweep's throws and CVODE's run on still water, so a sweep case
  // with [water] (the shipped swell, thrown from [throw] parameters) was timed as if its surface
  // were still: one line naming the case and the key, exit 2.
  const auto r = stoneskip::test::run_stoneskip("bench --quick --sweep-only --sweep-case cases/scenes/swell_8ms.toml");
  BOOST_TEST(r.status == 2, r.out);
  BOOST_TEST(r.out.find("cases/scenes/swell_8ms.toml") != std::string::npos, r.out);
  BOOST_TEST(r.out.find("water") != std::string::npos, r.out);
  BOOST_TEST(std::count(r.out.begin(), r.out.end(), '\n') == 1, r.out);
}

BOOST_AUTO_TEST_SUITE_END()
