// Plausibility bounds and limits of stone and wave cases: what main ran as a throw — a
// stone of 1e-30 m (exit speed 7.6e22 m/s), water of density 0, a release 1 m under water, an
// unstable scene water blamed on the stone — is refused with the key and the bound, and every
// shipped case stays inside the bounds and the limits. Oracles: the bounds documented per key in
// cases/README.md, the exact von Neumann limit of the stencil (model/water/stencil.hpp), and
// the arithmetic of the estimates (array counts × cells × 8 bytes).
#include <boost/test/unit_test.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "tools/io/input_error.hpp"
#include "tools/scene/documented_keys.hpp"
#include "tools/scene/baseline_file.hpp"
#include "tools/scene/resource_estimate.hpp"
#include "tools/scene/stone_case.hpp"
#include "tools/scene/wave_case.hpp"

using namespace stoneskip;
namespace fs = std::filesystem;

namespace {

const char* const kCase = stoneskip::test::kPlainStoneCase;

std::string error_of(const std::string& text, const std::vector<std::string>& overrides) {
  try {
    stone_case_from_document(parse_toml_text(text, "c.toml", overrides));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::vector<fs::path> shipped(const fs::path& dir, const std::string& prefix = "") {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".toml" && e.path().filename().string().rfind(prefix, 0) == 0) out.push_back(e.path());
  return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(case_limits)

BOOST_AUTO_TEST_CASE(the_issues_implausible_throws_are_refused_with_key_and_bound) {
  struct Case {
    std::string set, fragment;
  };
  for (const Case& c : {Case{"stone.radius_m=1e-30", "c.toml: --set stone.radius_m: must be in [0.001, 10] (got 1e-30)"},
                        Case{"environment.water_density_kg_m3=0", "--set environment.water_density_kg_m3: must be in [1, 100000]"},
                        Case{"throw.height_m=-1", "--set throw.height_m: must be in [0, 10000] (got -1)"},
                        Case{"throw.height_m=1e6", "--set throw.height_m: must be in [0, 10000]"},
                        Case{"throw.speed_m_s=1e30", "--set throw.speed_m_s: must be in [0, 1000]"},
                        Case{"solver.contact_dt_s=1e-300", "--set solver.contact_dt_s: must be in [1e-09, 1]"}}) {
    const std::string e = error_of(kCase, {c.set});
    BOOST_TEST(e.find(c.fragment) != std::string::npos, c.set << " -> " << e);
    BOOST_TEST(e.find("c.toml: --set ") == 0u, e);
  }
  // A fixed step longer than the run is refused by its own key (it was blamed on output_dt_s, which
  // the case never wrote: its default is dt_s).
  const std::string long_step = error_of(kCase, {"solver.dt_s=0.5", "solver.t_max_s=0.01"});
  BOOST_TEST(long_step.find("solver.dt_s: must not exceed t_max_s = 0.01 s (got 0.5)") != std::string::npos, long_step);
  // contact_dt_s with no scheme is the fixed-step case, and the missing dt_s says so.
  std::string no_dt = kCase;
  no_dt.replace(no_dt.find("dt_s = 1.0e-3\n"), 14, "");
  const std::string missing = error_of(no_dt, {});
  BOOST_TEST(missing.find("solver.dt_s: missing key: a [solver] that types contact_dt_s and names no scheme") != std::string::npos,
             missing);
  // What a key only implies: 1 kg in a 3 cm prism is a density of 44 000 kg/m³ (allowed), 100 kg
  // is 4.4e6 (no stone).
  std::string text = kCase;
  text.replace(text.find("density_kg_m3 = 2500.0"), 22, "mass_kg = 100.0");
  const std::string e = error_of(text, {});
  BOOST_TEST(e.find("c.toml: stone: mass 100 kg in a volume of") == 0u, e);
  BOOST_TEST(e.find("outside [1, 100000]") != std::string::npos, e);
}

BOOST_AUTO_TEST_CASE(a_mesh_file_that_is_no_file_names_the_key_and_the_path) {
  // Oracle: the key as written: "" names nothing; a folder and a FIFO are not OBJ files.
  const std::string dir = fs::temp_directory_path() / ("mesh_keys_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string fifo = dir + "/stone.obj";
  ::mkfifo(fifo.c_str(), 0644);
  std::string text = kCase;
  const std::string dims = "shape = \"prism\"\nradius_m = 0.03\nthickness_m = 0.008\n";
  text.replace(text.find(dims), dims.size(), "shape = \"mesh\"\n");
  const std::string empty = error_of(text, {"stone.mesh_file=\"\""});
  BOOST_TEST(empty == "c.toml: --set stone.mesh_file: must name a Wavefront OBJ file (got an empty string)");
  const std::string folder = error_of(text, {"stone.mesh_file=\"" + dir + "\""});
  BOOST_TEST(folder.find("stone.mesh_file: " + dir + ": cannot read: it is a folder") != std::string::npos, folder);
  const std::string f = error_of(text, {"stone.mesh_file=\"" + fifo + "\""});
  BOOST_TEST(f.find("it is a FIFO, not a regular file") != std::string::npos, f);
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_mesh_in_millimetres_is_named_as_one_before_its_mass_is_judged) {
  // Oracle: a 60 mm cube written in millimetres is a 60 m cube: its corners reach √3 · 30 = 52 m
  // from its centre, outside the stone's [.., 10] m, and at 2500 kg/m³ it weighs 5.4e8 kg, outside
  // the mass bound too. The size is the cause, so it is what the line names (it named the mass).
  const std::string dir = fs::temp_directory_path() / ("mesh_mm_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string obj = dir + "/cube_mm.obj";
  std::ofstream(obj) << "v 0 0 0\nv 60 0 0\nv 60 60 0\nv 0 60 0\nv 0 0 60\nv 60 0 60\nv 60 60 60\nv 0 60 60\n"
                        "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 4 8 7\nf 4 7 3\nf 1 5 8\nf 1 8 4\n"
                        "f 2 3 7\nf 2 7 6\n";
  std::string text = kCase;
  const std::string dims = "shape = \"prism\"\nradius_m = 0.03\nthickness_m = 0.008\n";
  text.replace(text.find(dims), dims.size(), "shape = \"mesh\"\n");
  const std::string e = error_of(text, {"stone.mesh_file=\"" + obj + "\""});
  BOOST_TEST(e.find("the stone reaches 51.96") != std::string::npos, e);
  BOOST_TEST(e.find("(a mesh in millimetres?)") != std::string::npos, e);
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(a_loose_vertex_in_an_obj_stone_is_refused_naming_its_line) {
  // Oracle: a closed, outward 6 cm cube (lines 1–8 its corners, 10–21 its faces) with a stray
  // point on line 9 that no face names: the case is refused, naming the file, that line and why.
  const std::string dir = fs::temp_directory_path() / ("mesh_loose_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string obj = dir + "/cube.obj";
  const std::string cube = "v 0 0 0\nv 0.06 0 0\nv 0.06 0.06 0\nv 0 0.06 0\nv 0 0 0.06\nv 0.06 0 0.06\nv 0.06 0.06 0.06\nv 0 0.06 0.06\n";
  const std::string faces = "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 4 8 7\nf 4 7 3\nf 1 5 8\nf 1 8 4\n"
                            "f 2 3 7\nf 2 7 6\n";
  std::string text = kCase;
  const std::string dims = "shape = \"prism\"\nradius_m = 0.03\nthickness_m = 0.008\n";
  text.replace(text.find(dims), dims.size(), "shape = \"mesh\"\n");
  std::ofstream(obj) << cube << faces;
  BOOST_TEST(error_of(text, {"stone.mesh_file=\"" + obj + "\""}) == "");  // the cube alone is a stone
  std::ofstream(obj) << cube << "v 0.03 0.03 -0.01\n" << faces;
  const std::string e = error_of(text, {"stone.mesh_file=\"" + obj + "\""});
  BOOST_TEST(e.find("stone.mesh_file: " + obj + ":9: 1 vertex belongs to no triangle") != std::string::npos, e);
  BOOST_TEST(e.find('\n') == std::string::npos, e);
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(an_unstable_scene_water_is_refused_naming_its_step) {
  // Oracle: the nine-point isotropic stencil's limit over the modes of this 50 × 50 reflecting pond
  // (k = πm/50, m < 50: the most negative symbol at cos k = −cos(π/50), −10/3 − (8/3)c + (2/3)c²,
  // so σ = 2/√(−s) = 0.866239, just above the plane's √3/2 = 0.866025; model/README.md §2.2): the
  // swell's 2 cm cells and c = 1.25 m/s allow Δt up to 0.866239·0.02/1.25 = 0.0138598 s. At 0.05 s
  // (σ = 3.1) main ran the throw on a blown-up surface and reported a sinking.
  const std::string text = std::string(kCase) + stoneskip::test::kPlainWater;
  BOOST_TEST(error_of(text, {}) == "");
  const std::string e = error_of(text, {"water.dt_s=0.05"});
  BOOST_TEST(e.find("c.toml: --set water.dt_s: the water would be unstable: sigma = c dt_s / cell_m = 3.125") == 0u, e);
  BOOST_TEST(e.find("take dt_s <= 0.0138598") != std::string::npos, e);
  // Two-way, the advice is the coupled limit √3/2/√2 = 0.6124 (main advised 0.01386, which the
  // coupled check then refused): 0.6124 · 0.02 / 1.25 = 0.009798 s.
  const std::string two = error_of(text, {"water.dt_s=0.05", "water.coupling=\"two_way\""});
  // The advice is rounded down, so that it passes as printed: 0.009797959 s printed to the nearest
  // (0.00979796) was itself refused (σ = 0.6123725 > 0.6123724).
  BOOST_TEST(two.find("take dt_s <= 0.00979795") != std::string::npos, two);
  BOOST_TEST(error_of(text, {"water.dt_s=0.00979795", "water.coupling=\"two_way\""}) == "");  // the advice passes
  BOOST_TEST(error_of(text, {"water.dt_s=0.00979796", "water.coupling=\"two_way\""}) != "");  // to the nearest: refused
  BOOST_TEST(error_of(text, {"water.dt_s=0.0138598"}) == "");  // the one-way advice passes too
}

BOOST_AUTO_TEST_CASE(a_scene_water_with_no_stable_step_says_so_and_gives_no_step) {
  // Oracle: model/water/stencil.hpp (Schur–Cohn) — centre 4, orth −1 has symbol 8 > 0 at (π, π),
  // a mode that grows at every σ > 0, so no dt_s is stable; the bisection's "take dt_s <= 2.1e-08"
  // named a step that does not exist. A stencil of zeros couples no cells and is stable at any σ.
  const std::string water = std::string(kCase) + stoneskip::test::kPlainWater;
  const std::string anti = error_of(water + "\n[stencil]\nname = \"anti\"\ncentre = 4.0\north = -1.0\ndiag = 0.0\n",
                                    {"water.stencil=\"custom\""});
  BOOST_TEST(anti.find("the anti stencil has no stable step") != std::string::npos, anti);
  BOOST_TEST(anti.find("take dt_s") == std::string::npos, anti);
  const std::string zeros = error_of(water + "\n[stencil]\nname = \"zeros\"\ncentre = 0.0\north = 0.0\ndiag = 0.0\n",
                                     {"water.stencil=\"custom\"", "water.dt_s=0.05"});
  BOOST_TEST(zeros == "", zeros);  // σ = 3.125, stable: nothing to refuse
}

BOOST_AUTO_TEST_CASE(the_limit_wave_and_scene_share_is_exact_at_every_damping) {
  // Oracle: σ_max = 2/√8 = 1/√2 for the five-point stencil at every μΔt ≥ 0 (model/water/stencil.hpp),
  // from water_stability, which both `wave` and `scene` call;
  // the bisection gave 0.7071068157 at μΔt = 390.6, above the true limit. Exact to the last bit.
  HeightFieldOptions w;
  w.stencil = named_stencil("five_point");
  w.cell_m = 1;
  w.wave_speed_m_s = 1;
  for (double mu : {0.0, 0.5, 390.6 / 0.7})
    for (double sigma : {0.7, 0.7071067811866, 0.72}) {
      w.dt_s = sigma;
      w.damping_per_s = mu;
      const WaterStability s = water_stability(w);
      BOOST_TEST(s.limit == 2 / std::sqrt(8.0));
      BOOST_TEST(s.stable() == (sigma < 0.7071067811865), sigma << " at mu " << mu);
      // Four decimals where they tell sigma from the limit; where they do not, the digits that do
      // ("0.7071 exceeds the von Neumann limit 0.7071" was true and read as false).
      const std::string said = sigma == 0.7 ? "sigma = 0.7000 is within the von Neumann limit 0.7071 of five_point"
                               : sigma == 0.72
                                   ? "sigma = 0.7200 exceeds the von Neumann limit 0.7071 of five_point"
                                   : "sigma = 0.7071067811866 exceeds the von Neumann limit 0.7071067811865 of five_point";
      BOOST_TEST(s.reason().find(said) != std::string::npos, s.reason());
    }
}

BOOST_AUTO_TEST_CASE(a_scene_initial_surface_too_wide_or_too_large_for_its_periodic_images_is_refused) {
  // Oracle: model/water/disturbance.hpp on the plain 50 × 50 pond of 2 cm cells (1 m × 1 m): a
  // ring of radius 5 m reaches past 3 periods; a Gaussian of width 1e6 m sums to about
  // A π w² / L² = 0.02 π 1e12 m, far above the 1000 m bound; a Gaussian of 0.1 m is taken.
  const std::string plain = std::string(kCase) + stoneskip::test::kPlainWater;
  const std::string wave = "[water.initial]\nkind = \"plane_wave\"\namplitude_m = 0.02\nwavelength_m = 1.0\n";
  const auto at = plain.find(wave);
  BOOST_REQUIRE(at != std::string::npos);
  auto with_initial = [&](const std::string& initial) { return std::string(plain).replace(at, wave.size(), initial); };
  const std::string ring = error_of(with_initial("[water.initial]\nkind = \"ring\"\namplitude_m = 0.02\nwidth_m = 0.05\n"
                                                 "radius_m = 5.0\nx_m = 0.5\ny_m = 0.5\n"), {});
  BOOST_TEST(ring.find("water.initial.radius_m: a ring of radius_m + 6.5 width_m") != std::string::npos, ring);
  const std::string wide = error_of(with_initial("[water.initial]\nkind = \"gaussian\"\namplitude_m = 0.02\nwidth_m = 1.0e6\n"
                                                 "x_m = 0.5\ny_m = 0.5\n"), {});
  BOOST_TEST(wide.find("water.initial.width_m: a Gaussian of width_m 1e+06") != std::string::npos, wide);
  BOOST_TEST(error_of(with_initial("[water.initial]\nkind = \"gaussian\"\namplitude_m = 0.02\nwidth_m = 0.1\n"
                                   "x_m = 0.5\ny_m = 0.5\n"), {}) == "");
}

BOOST_AUTO_TEST_CASE(estimates_count_what_the_run_will_hold) {
  // Oracle: arithmetic. A periodic wave case holds 10.5 arrays of nx·ny doubles (a walled one 11.5): 16384² cells are
  // 22.5 GB, above the 8 GB default; its work is cells × ⌈t_end/Δt⌉. A throw of t_max / contact_dt
  // = 1e8 steps recording every one (output_dt_s = 0) holds 1e8 samples.
  const std::string wave = R"([water]
stencil = "five_point"
nx = 16384
ny = 16384
cell_m = 0.001
wave_speed_m_s = 1.0
dt_s = 0.0005
t_end_s = 0.001
[initial]
kind = "impulse"
amplitude_m = 0.01
x_m = 0.5
y_m = 0.5
)";
  const WaveCase w = wave_case_from_document(parse_toml_text(wave, "w.toml"));
  const ResourceEstimate we = estimate_wave(w);
  BOOST_TEST(we.memory_bytes == 10.5 * 8 * 16384.0 * 16384.0);
  BOOST_TEST(we.work.at(0).count == 2 * 16384.0 * 16384.0);
  // Walled, the reference is the cosine (sine) one: 11.5 arrays (walled_wave.hpp's, with the run's).
  WaveCase walled = w;
  walled.water.boundary = Boundary::reflecting;
  BOOST_TEST(estimate_wave(walled).memory_bytes == 11.5 * 8 * 16384.0 * 16384.0);
  BOOST_CHECK_THROW(enforce_limits(we, ResourceLimits{}, "w.toml"), InputError);
  BOOST_CHECK_NO_THROW(enforce_limits(we, ResourceLimits{23e9, false}, "w.toml"));

  const StoneCase c = stone_case_from_document(
      parse_toml_text(kCase, "c.toml", {"solver.t_max_s=1000", "solver.dt_s=1e-5", "solver.output_dt_s=0", "throw.height_m=100"}));
  const ResourceEstimate ce = estimate_run(c, RunSolvers{});
  BOOST_TEST(ce.memory_bytes >= 1e8 * sizeof(TrajectorySample));
  BOOST_TEST(ce.work.at(0).count == 1e8 * 44);  // steps × 1 right-hand side × 44 triangles
  BOOST_CHECK_THROW(enforce_limits(ce, ResourceLimits{}, "c.toml"), InputError);
  // bs32 takes no step longer than dt_s, its largest: dt_s = 1e-9 over 10 s is 1e10 steps of 6
  // right-hand sides, not the 1.7e5 of its assumed 6e-5 s step (a run that went on for hours).
  const StoneCase b = stone_case_from_document(
      parse_toml_text(kCase, "b.toml", {"solver.scheme=bs32", "solver.t_max_s=10", "solver.dt_s=1e-9"}));
  const ResourceEstimate be = estimate_run(b, RunSolvers{});
  BOOST_TEST(be.work.at(0).count == 1e10 * 6 * 44);
  BOOST_CHECK_THROW(enforce_limits(be, ResourceLimits{}, "b.toml"), InputError);
  // The reference interpolates every output time inside its steps: output_dt_s = 1e-9 over 10 s is
  // 1e10 samples however few steps it takes, not its max_steps (2e6). Estimated as its steps, such
  // a run was let start and ran out of memory. The real-time stepper records at most one sample a
  // step, so its estimate stays bounded by its steps.
  const StoneCase r = stone_case_from_document(parse_toml_text(kCase, "r.toml", {"solver.t_max_s=10", "solver.output_dt_s=1e-9"}));
  const ResourceEstimate re = estimate_run(r, RunSolvers{false, true, false});
  BOOST_TEST(re.memory_bytes >= 1e10 * sizeof(TrajectorySample));
  BOOST_CHECK_THROW(enforce_limits(re, ResourceLimits{}, "r.toml"), InputError);
  BOOST_CHECK_NO_THROW(enforce_limits(estimate_run(r, RunSolvers{true, false, false}), ResourceLimits{}, "r.toml"));
}

BOOST_AUTO_TEST_CASE(every_shipped_case_and_baseline_is_inside_the_bounds_and_limits) {
  // Oracle: the shipped cases are the documented examples (cases/README.md): each must
  // load and pass the default limits with the solvers it is run with.
  int stone = 0, wave = 0;
  for (const fs::path& dir : {fs::path("cases"), fs::path("cases/hard"), fs::path("cases/scenes"), fs::path("cases/studies")}) {
    for (const auto& f : shipped(dir)) {
      const std::string name = f.filename().string();
      if (name.rfind("wave_", 0) == 0) {
        const WaveCase w = load_wave_case(f.string());
        BOOST_CHECK_NO_THROW(enforce_limits(estimate_wave(w), ResourceLimits{}, f.string()));
        ++wave;
        continue;
      }
      if (dir == "cases/studies" &&
          (name.rfind("stones", 0) == 0 || name.rfind("waves", 0) == 0 || name.rfind("scene", 0) == 0))
        continue;  // study files
      BOOST_TEST_CONTEXT(f) {
        const StoneCase c = load_stone_case(f.string());
        BOOST_CHECK_NO_THROW(enforce_limits(estimate_run(c, RunSolvers{true, !c.water, true}), ResourceLimits{}, f.string()));
        ++stone;
      }
    }
  }
  BOOST_TEST(stone >= 15);
  BOOST_TEST(wave >= 5);
  std::vector<BounceSweepSpec> sweeps;
  for (const auto& f : shipped("cases/baselines")) {
    sweeps.push_back(sweep_of(read_baseline(f.string())));
    BOOST_CHECK_NO_THROW(enforce_limits(estimate_regress({sweeps.back()}), ResourceLimits{}, f.string()));
  }
  const ResourceEstimate all = estimate_regress(sweeps);
  BOOST_TEST_MESSAGE("shipped regress: " << all.work.back().count << " " << all.work.back().what);
  BOOST_CHECK_NO_THROW(enforce_limits(all, ResourceLimits{}, "regress"));
}

BOOST_AUTO_TEST_SUITE_END()
