// Property: every key documented in cases/README.md — stone cases, a stone on live
// water, wave cases, golden baselines, sweep files — refuses every value the documentation makes bad (another
// type; NaN, ±inf; 1e±400; integers beyond 64 bits and huge counts; zero, signs and numbers just
// outside the documented bounds) with an InputError of one line naming the key, within a time
// bound. Oracle: the README itself (tools/scene/documented_keys.hpp reads its TOML blocks), so a
// documented bound the code does not enforce fails here. The full product of keys × values runs
// in-process; tools/cli/bad_values_property_test.cpp runs one value per key through the command.
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

#include "tools/io/input_error.hpp"
#include "tools/scene/baseline_file.hpp"
#include "tools/scene/documented_keys.hpp"
#include "tools/scene/stone_case.hpp"
#include "tools/scene/sweep_file.hpp"
#include "tools/scene/wave_case.hpp"

using namespace stoneskip;
using namespace stoneskip::test;
namespace fs = std::filesystem;

namespace {

// A whole second per value: a parse takes well under a millisecond; this only catches a hang or a
// run started by mistake.
constexpr double kMaxSecondsPerValue = 1.0;

const char* const kStone = stoneskip::test::kPlainStoneCase;

const char* const kWater = stoneskip::test::kPlainWater;

const char* kWave = R"([water]
stencil = "five_point"
nx = 32
ny = 32
cell_m = 0.03125
wave_speed_m_s = 1.0
dt_s = 0.01
t_end_s = 0.1
[initial]
kind = "gaussian"
amplitude_m = 0.01
width_m = 0.1
x_m = 0.5
y_m = 0.5
)";

std::string replace_once(std::string s, const std::string& from, const std::string& to) {
  const auto p = s.find(from);
  BOOST_REQUIRE_MESSAGE(p != std::string::npos, "base text lacks '" << from << "'");
  return s.replace(p, from.size(), to);
}

struct Bases {
  fs::path dir = fs::temp_directory_path() / ("documented_keys_" + std::to_string(::getpid()));
  std::string obj;
  Bases() {
    fs::create_directories(dir);
    obj = (dir / "stone.obj").string();
    std::ofstream(obj) << "v 0 0 0\nv 0.03 0 0\nv 0 0.03 0\nv 0 0 0.01\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
  }
  ~Bases() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  // The case text on which a key of a stone-like block is exercised.
  std::string stone_text(const DocumentedKey& k) const {
    if (k.block == "scene") return std::string(kStone) + kWater;
    if (k.section == "throw.state")
      return replace_once(kStone, "speed_m_s = 8.0\npath_angle_deg = 10.0\nattack_angle_deg = 10.0\nheight_m = 0.1\n",
                          "[throw.state]\nposition_m = [0.0, 0.0, 0.1]\nvelocity_m_s = [7.9, 0.0, -1.4]\n"
                          "quaternion_wxyz = [1.0, 0.0, 0.0, 0.0]\nangular_velocity_rad_s = [0.0, 0.0, 62.8]\n");
    if (k.full() == "stone.mass_kg") return replace_once(kStone, "density_kg_m3 = 2500.0", "mass_kg = 0.05");
    if (k.full() == "stone.mesh_file" || k.full() == "stone.disk_radius_m")
      return replace_once(kStone, "shape = \"prism\"\nradius_m = 0.03\nthickness_m = 0.008\n",
                          "shape = \"mesh\"\nmesh_file = \"" + obj + "\"\n");
    return kStone;
  }
  std::string wave_text(const DocumentedKey& k) const {
    if (k.section == "stencil") return replace_once(kWave, "stencil = \"five_point\"", "stencil = \"custom\"") +
                                       "[stencil]\ncentre = -3.5\north = 0.75\ndiag = 0.125\n";
    if (k.key == "radius_m") return replace_once(kWave, "kind = \"gaussian\"", "kind = \"ring\"\nradius_m = 0.2");
    if (k.key == "wavelength_m" || k.key == "angle_deg")
      return replace_once(kWave, "kind = \"gaussian\"\namplitude_m = 0.01\nwidth_m = 0.1\nx_m = 0.5\ny_m = 0.5\n",
                          "kind = \"plane_wave\"\namplitude_m = 0.01\nwavelength_m = 0.25\n");
    return kWave;
  }
};

// The README's baseline block, as a file (a valid baseline of the shipped convergence throw).
std::string readme_baseline() {
  std::ifstream in("cases/README.md");
  std::string line, text;
  bool in_block = false, after_heading = false;
  while (std::getline(in, line)) {
    if (line.find("golden baselines") != std::string::npos && line.rfind("## ", 0) == 0) after_heading = true;
    if (!after_heading) continue;
    if (line == "```toml") {
      in_block = true;
      continue;
    }
    if (in_block && line.rfind("```", 0) == 0) break;
    if (in_block) text += line + "\n";
  }
  return text;
}

// The InputError's message, or "" (and how long it took).
std::string refusal(const std::function<void()>& f, double& seconds) {
  const auto t0 = std::chrono::steady_clock::now();
  std::string out;
  try {
    f();
  } catch (const InputError& e) {
    out = e.what();
  }
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(documented_key_values)

BOOST_AUTO_TEST_CASE(the_readme_documents_the_keys_with_their_bounds) {
  // Oracle: the blocks of cases/README.md, counted by hand when this test was written.
  const auto keys = documented_keys();
  std::map<std::string, int> per_block;
  int bounded = 0;
  for (const auto& k : keys) {
    ++per_block[k.block];
    bounded += k.has_lo || k.has_hi;
  }
  BOOST_TEST(per_block["stone"] >= 36);
  BOOST_TEST(per_block["scene"] >= 13);
  BOOST_TEST(per_block["wave"] >= 22);
  BOOST_TEST(per_block["baseline"] >= 14);
  BOOST_TEST(per_block["sweep"] == 12);  // title, base, set, solvers; kind, samples, seed; key, from, to, count, scale
  BOOST_TEST(bounded >= 44);
}

BOOST_AUTO_TEST_CASE(every_documented_key_refuses_every_bad_value_in_one_line) {
  const Bases bases;
  const std::string baseline = readme_baseline();
  BOOST_REQUIRE(!baseline.empty());
  int checked = 0;
  double slowest = 0;
  for (const auto& k : documented_keys()) {
    for (const auto& bad : bad_values(k)) {
      double seconds = 0;
      std::string e;
      if (k.block == "stone" || k.block == "scene") {
        const std::string text = bases.stone_text(k);
        e = refusal([&] { stone_case_from_document(parse_toml_text(text, "c.toml", std::vector<std::string>{k.full() + "=" + bad.text})); }, seconds);
      } else if (k.block == "wave") {
        const std::string text = bases.wave_text(k);
        e = refusal([&] { wave_case_from_document(parse_toml_text(text, "w.toml", std::vector<std::string>{k.full() + "=" + bad.text})); }, seconds);
      } else if (k.block == "sweep") {
        // Sweep files: the README's block with the key's line rewritten, read and probed as
        // `stoneskip sweep` does before any throw (the base resolves from cases/sweeps/).
        const std::string text = sweep_text_with(k, bad.text);
        BOOST_REQUIRE_MESSAGE(!text.empty(), k.full());
        e = refusal([&] { SweepCases cases(sweep_file_from_text(text, "cases/sweeps/s.toml")); }, seconds);
      } else {
        // Baselines are files: the key's line is rewritten.
        std::string text = baseline;
        const auto p = text.find("\n" + k.key + " = ");
        BOOST_REQUIRE_MESSAGE(p != std::string::npos, k.full());
        const auto end = text.find('\n', p + 1);
        text.replace(p + 1, end - p - 1, k.key + " = " + bad.text);
        const fs::path file = bases.dir / "b.toml";
        std::ofstream(file) << text;
        e = refusal([&] { sweep_of(read_baseline(file.string())); }, seconds);
      }
      BOOST_TEST_CONTEXT(k.block << ": " << k.full() << " = " << bad.text << " (" << bad.why << ")") {
        BOOST_TEST(!e.empty(), "accepted");
        BOOST_TEST(e.find('\n') == std::string::npos, e);
        // The key's table is named; a scalar key by its own name (a [result] array may be
        // blamed on its partner when their lengths differ).
        if (!k.section.empty()) BOOST_TEST(e.find(k.block == "sweep" ? error_name(k).substr(0, error_name(k).rfind('.') + 1) : k.section + ".") != std::string::npos, e);
        if (k.kind != KeyKind::array) BOOST_TEST(e.find(error_name(k)) != std::string::npos, e);
        BOOST_TEST(seconds < kMaxSecondsPerValue);
      }
      if (std::getenv("STONESKIP_SHOW_REFUSALS")) BOOST_TEST_MESSAGE(k.full() << " = " << bad.text << " -> " << e);
      slowest = std::max(slowest, seconds);
      ++checked;
    }
  }
  BOOST_TEST_MESSAGE(checked << " bad values refused; the slowest took " << slowest << " s");
  BOOST_TEST(checked >= 900);
}

BOOST_AUTO_TEST_SUITE_END()

