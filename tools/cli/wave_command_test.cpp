// End-to-end tests of `stoneskip wave`: the built executable run on the shipped wave cases.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <nlohmann/json.hpp>

#include "model/water/leapfrog_kernel.hpp"
#include "tools/cli/test_support.hpp"

namespace {

using stoneskip::test::Ran;
using stoneskip::test::run_stoneskip;
namespace fs = std::filesystem;

nlohmann::json run_json(const std::string& args, int status = 0) {
  Ran r = run_stoneskip(args + " --json", false);  // stderr may carry notes; stdout is the JSON
  BOOST_REQUIRE_MESSAGE(r.status == status, r.out);
  return nlohmann::json::parse(r.out);
}

BOOST_AUTO_TEST_SUITE(wave_command_)

BOOST_AUTO_TEST_CASE(leapfrog_time_error_falls_fourfold_when_the_step_is_halved) {
  // Oracle: the leapfrog is second order in time, so against the stencil's exact semi-discrete
  // solution ([reference] symbol = "stencil") halving dt divides the error by 4; 3.6–4.4 allows
  // the O(dt⁴) remainder at sigma = 0.25.
  const std::string base = "wave cases/wave_gaussian_five_point.toml --set reference.symbol=stencil";
  nlohmann::json a = run_json(base + " --set water.dt_s=0.001953125");
  nlohmann::json b = run_json(base + " --set water.dt_s=0.0009765625");
  BOOST_TEST(a["steps"].get<long>() == 256);
  BOOST_TEST(b["steps"].get<long>() == 512);
  BOOST_TEST(a["stencil"].get<std::string>() == "five_point");
  const double ratio = a["l2_error"].get<double>() / b["l2_error"].get<double>();
  BOOST_TEST(ratio >= 3.6);
  BOOST_TEST(ratio <= 4.4);
  const double ratio_max = a["max_error"].get<double>() / b["max_error"].get<double>();
  BOOST_TEST(ratio_max >= 3.6);
  BOOST_TEST(ratio_max <= 4.4);
}

BOOST_AUTO_TEST_CASE(lengyel_counterexample_grows_by_the_predicted_factor) {
  // Oracle: model/README.md §2.2 — five-point, μΔt = 0.5, σ = 0.75: the checkerboard grows by
  // (5 + √10)/5 ≈ 1.632 per step; after 60 steps from a 1 cm impulse the RMS is ~1.63^60 × the
  // impulse's share of that mode, far above any physical height (we ask for > 1e6 m).
  // An unstable run exits 1 (cases/README.md) and says why in JSON.
  nlohmann::json j = run_json("wave cases/wave_lengyel_counterexample.toml", 1);
  BOOST_TEST(j["courant"].get<double>() > j["stability_limit"].get<double>());
  BOOST_TEST(j["solution_rms_m"].get<double>() > 1e6);
  BOOST_TEST(j["stable"].get<bool>() == false);
  BOOST_TEST(j["stability"].get<std::string>().find("sigma = 0.7500 exceeds the von Neumann limit 0.7071 of five_point") == 0u);
}

BOOST_AUTO_TEST_CASE(a_run_above_the_limit_is_reported_unstable_before_its_error_and_exits_1) {
  // Oracle: σ = c dt/d = 1 × 0.0056 / 0.0078125 = 0.7168 > 1/√2, the five-point limit at every μΔt
  // (model/README.md §2.2). The run is too short to grow visibly (its L2 looks like 1.5e-6 m, a
  // converged number): stdout must say UNSTABLE before it, JSON stable = false, exit 1.
  const std::string line = "wave cases/wave_gaussian_five_point.toml --set water.dt_s=0.0056 --set water.damping_per_s=0";
  const Ran r = run_stoneskip(line, false);
  BOOST_TEST(r.status == 1);
  const auto unstable = r.out.find("UNSTABLE: sigma = 0.7168 exceeds the von Neumann limit 0.7071 of five_point");
  BOOST_TEST(unstable != std::string::npos, r.out);
  BOOST_TEST(unstable < r.out.find("L2 (RMS)"), r.out);
  BOOST_TEST(r.out.find("not a discretisation error") != std::string::npos, r.out);
  const nlohmann::json j = run_json(line, 1);
  BOOST_TEST(j["stable"].get<bool>() == false);
  BOOST_TEST(j["l2_error"].is_number());
  // Below the limit: stable, exit 0.
  const nlohmann::json ok = run_json("wave cases/wave_gaussian_five_point.toml");
  BOOST_TEST(ok["stable"].get<bool>() == true);
  BOOST_TEST(ok["stability"].get<std::string>().find("is within the von Neumann limit") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_surface_whose_squares_overflow_still_has_a_finite_rms) {
  // Oracle: for N values, max/√N ≤ RMS ≤ max. The Lengyel case run to 25 s reaches 8.6e221 m, whose
  // square overflows; main printed "L2 (RMS) inf m" and JSON l2_error null with no reason.
  const nlohmann::json j = run_json("wave cases/wave_lengyel_counterexample.toml --set water.t_end_s=25", 1);
  BOOST_TEST(j["finite"].get<bool>() == true);
  BOOST_TEST(j["stable"].get<bool>() == false);
  const double rms = j["solution_rms_m"].get<double>(), l2 = j["l2_error"].get<double>(), mx = j["max_error"].get<double>();
  const double n = 32.0 * 32.0;
  BOOST_TEST(mx > 1e200);
  // kRms: a few roundings of the scaled sum; the checkerboard's heights are nearly equal, so l2 ≈ max.
  constexpr double kRms = 1e-12;
  BOOST_TEST(l2 <= mx * (1 + kRms));
  BOOST_TEST(l2 >= mx / std::sqrt(n) * (1 - kRms));
  BOOST_TEST(rms > 1e200);
}

BOOST_AUTO_TEST_CASE(a_walled_pool_is_measured_against_the_walled_reference) {
  // Oracle: the stencil-symbol reference is exact for the leapfrog's walls (solvers/spectral/
  // walled_wave_test.cpp), so what `wave` reports against it is the time error alone, O(Δt²):
  // halving dt_s from σ = 0.2 divides it by 4 (within 10 %: the Δt⁴ term at σ ≤ 0.2 on this
  // 5-cell-wide Gaussian is a few % of it). Against the continuum reference the error includes the
  // space error, which does not fall with Δt, so it is larger. Both boundaries; JSON names the reference.
  for (const char* boundary : {"reflecting", "fixed"}) {
    const std::string c = std::string("wave cases/wave_custom_stencil_pool.toml --set water.boundary=") + boundary;
    const nlohmann::json coarse = run_json(c + " --set water.dt_s=0.005 --set reference.symbol=stencil --json");
    const nlohmann::json fine = run_json(c + " --set water.dt_s=0.0025 --set reference.symbol=stencil --json");
    const nlohmann::json continuum = run_json(c + " --set water.dt_s=0.0025 --json");
    BOOST_TEST(coarse["reference"] == "stencil");
    BOOST_TEST(continuum["reference"] == "continuum");
    BOOST_TEST(coarse["initial_fits_grid"].get<bool>());  // a narrow Gaussian far from the walls
    const double ratio = coarse["l2_error"].get<double>() / fine["l2_error"].get<double>();
    BOOST_TEST(std::abs(ratio - 4) <= 0.4, boundary << ": l2 ratio " << ratio);
    BOOST_TEST(continuum["l2_error"].get<double>() > 2 * fine["l2_error"].get<double>(), boundary);
    BOOST_TEST(fine["solution_rms_m"].get<double>() > 0.0);
  }
  // A plane wave across a reflecting pond meets its walls with a kink: said (initial_fits_grid false,
  // the note naming the share of the surface in the short waves), with the continuum reference only.
  const std::string plane = "wave cases/wave_plane_wave_30deg.toml --set water.boundary=reflecting --json";
  const nlohmann::json p = run_json(plane);
  BOOST_TEST(!p["initial_fits_grid"].get<bool>());
  BOOST_TEST(p["note"].get<std::string>().find("upper half of the reflecting pond's modes") != std::string::npos, p["note"]);
  BOOST_TEST(run_json(plane + " --set reference.symbol=stencil")["initial_fits_grid"].get<bool>());
}

BOOST_AUTO_TEST_CASE(a_surface_that_is_zero_everywhere_says_its_zero_error_means_nothing) {
  // main printed "L2 (RMS) 0 m" with nothing beside it. Oracle: a zero amplitude gives the zero
  // surface, whose error is zero whatever the scheme.
  Ran r = run_stoneskip("wave cases/wave_gaussian_five_point.toml --set initial.amplitude_m=0");
  BOOST_TEST(r.status == 0, r.out);
  BOOST_TEST(r.out.find("the solution is zero everywhere") != std::string::npos, r.out);
  Ran n = run_stoneskip("wave cases/wave_gaussian_five_point.toml");
  BOOST_TEST(n.out.find("zero everywhere") == std::string::npos, n.out);
}

BOOST_AUTO_TEST_CASE(misspelt_key_is_rejected_with_its_name_and_status_2) {
  // Oracle: cases/README.md — an unknown key is an error naming the key, exit status 2.
  Ran r = run_stoneskip("wave cases/wave_gaussian_five_point.toml --set water.wave_sped_m_s=2");
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.out.find("water.wave_sped_m_s") != std::string::npos, r.out);
  Ran k = run_stoneskip("wave cases/wave_gaussian_five_point.toml --set initial.wavelength_m=0.2");
  BOOST_TEST(k.status == 2);  // a key the gaussian does not use
}

// STONESKIP_ISA for the child processes of one test, restored after.
struct IsaEnvironment {
  std::string saved;
  bool had = false;
  IsaEnvironment() {
    if (const char* e = std::getenv("STONESKIP_ISA")) {
      had = true;
      saved = e;
    }
  }
  void set(const std::string& v) { setenv("STONESKIP_ISA", v.c_str(), 1); }
  ~IsaEnvironment() {
    if (had) setenv("STONESKIP_ISA", saved.c_str(), 1);
    else unsetenv("STONESKIP_ISA");
  }
};

BOOST_AUTO_TEST_CASE(every_instruction_set_gives_the_same_wave_bit_for_bit) {
  // Oracle: the run under STONESKIP_ISA=scalar. Every kernel path computes the same bits
  // (model/water/leapfrog_kernel.hpp), so the errors and the RMS, printed to 17 digits, must be
  // equal exactly on every path this CPU supports, for the 5-point and the 9-point stencil.
  IsaEnvironment env;
  for (const std::string stencil : {"five_point", "nine_point_isotropic"}) {
    const std::string line = "wave cases/wave_gaussian_five_point.toml --set water.stencil=" + stencil;
    env.set("scalar");
    const nlohmann::json ref = run_json(line);
    for (stoneskip::SimdPath p : stoneskip::supported_simd_paths()) {
      BOOST_TEST_CONTEXT(stencil << " on " << stoneskip::to_string(p)) {
        env.set(stoneskip::to_string(p));
        const nlohmann::json j = run_json(line);
        for (const char* key : {"l2_error", "max_error", "solution_rms_m"})
          BOOST_TEST(j[key].get<double>() == ref[key].get<double>());
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(an_unknown_instruction_set_is_bad_input) {
  // Oracle: the exit-status rule — a value of STONESKIP_ISA that names no path is bad input: exit
  // 2, one line on stderr naming the variable and the value, nothing on stdout.
  IsaEnvironment env;
  env.set("avx1024");
  const auto r = stoneskip::test::run_apart("wave cases/wave_gaussian_five_point.toml --json");
  BOOST_TEST(r.status == 2);
  BOOST_TEST(r.out.empty());
  BOOST_TEST(r.err.find("STONESKIP_ISA") != std::string::npos);
  BOOST_TEST(r.err.find("avx1024") != std::string::npos);
  BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
}

BOOST_AUTO_TEST_CASE(a_plane_wave_that_does_not_fit_the_periodic_grid_says_so) {
  // Oracle: the geometry. The shipped 30° case fits the grid (whole wavelengths along x and y); at
  // 31° cos and sin times L/λ are not whole, the periodic copy has a seam, and the run said nothing
  // while its error doubled. JSON initial_fits_grid false with a note; true, no note, at 30°.
  const nlohmann::json fits = run_json("wave cases/wave_plane_wave_30deg.toml");
  BOOST_TEST(fits["initial_fits_grid"].get<bool>());
  BOOST_TEST(!fits.contains("note"));
  const nlohmann::json seam = run_json("wave cases/wave_plane_wave_30deg.toml --set initial.angle_deg=31");
  BOOST_TEST(!seam["initial_fits_grid"].get<bool>());
  BOOST_TEST(seam["note"].get<std::string>().find("does not fit the periodic grid") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_gaussian_wide_against_its_periodic_grid_says_its_images_add_up) {
  // Oracle: Poisson summation. On 4 x 4 cells of 1/128 m (L = 0.03125 m) the shipped Gaussian
  // (w = 0.1 m, A = 0.01 m) sums with its images to A (√π w / L)² [1 + 2 Σ e^{−(π k w/L)²}]² at its
  // centre; the terms are below e^{−100}, so A π w² / L² = 0.3217 m, 32 times its amplitude, and the
  // run said nothing of it. The shipped 128 x 128 grid holds the bump: no note.
  const nlohmann::json shipped = run_json("wave cases/wave_gaussian_five_point.toml");
  BOOST_TEST(!shipped.contains("note"));
  const nlohmann::json wide = run_json("wave cases/wave_gaussian_five_point.toml --set water.nx=4 --set water.ny=4");
  const double L = 4 * 0.0078125, peak = 0.01 * M_PI * 0.1 * 0.1 / (L * L);
  char expected[64];
  std::snprintf(expected, sizeof expected, "it sums to %.4g m at its centre", peak);
  BOOST_TEST(std::string(expected).find("0.3217") != std::string::npos);
  BOOST_TEST(!wide["initial_fits_grid"].get<bool>());
  BOOST_TEST(wide["note"].get<std::string>().find(expected) != std::string::npos, wide["note"].get<std::string>());
}

BOOST_AUTO_TEST_CASE(a_title_with_control_characters_is_printed_escaped) {
  // Oracle: printable_text's escapes. The text summary printed the case's title as written.
  std::ifstream in("cases/wave_gaussian_five_point.toml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string from = "title = \"Gaussian bump, five-point stencil\"";
  BOOST_REQUIRE(text.find(from) != std::string::npos);
  text.replace(text.find(from), from.size(), "title = \"w\\u0007v\\u001b[31m\"");
  const fs::path p = fs::temp_directory_path() / ("stoneskip_wave_ctrl_" + std::to_string(::getpid()) + ".toml");
  std::ofstream(p) << text;
  const Ran r = run_stoneskip("wave " + p.string() + " --set water.nx=16 --set water.ny=16", false);
  fs::remove(p);
  BOOST_REQUIRE(r.status == 0);
  BOOST_TEST(r.out.find("w\\x07v\\x1B[31m: five_point") != std::string::npos, r.out);
  BOOST_TEST(r.out.find('\a') == std::string::npos);
  BOOST_TEST(r.out.find('\x1b') == std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_ring_too_large_for_its_periodic_images_is_refused_naming_its_key) {
  // A ring of radius 5 m on the 1 m ring case reaches past the images the sum holds
  // (model/water/disturbance.hpp; the sum itself is tested there against a direct one).
  // Oracle: the input rules, one line naming the key and the reach, exit 2.
  const Ran ring = run_stoneskip("wave cases/wave_ring_paper_eq11.toml --set initial.radius_m=5");
  BOOST_TEST(ring.status == 2, ring.out);
  BOOST_TEST(ring.out.find("initial.radius_m: a ring of radius_m + 6.5 width_m = 5.195 m reaches past 3 periods") !=
                 std::string::npos,
             ring.out);
  BOOST_TEST(std::count(ring.out.begin(), ring.out.end(), '\n') == 1, ring.out);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
