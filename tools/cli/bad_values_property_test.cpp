// Property, end to end: for every key documented in cases/README.md, a value the
// documentation makes bad goes through the command that reads it (`run` with --out for stone
// cases and scenes, `wave` for wave cases, `regress` for baselines, `sweep` for sweep files) and must give exit 2, exactly
// one line on stderr naming the key, nothing on stdout, no output or temporary file, within 30 s.
// Oracle: the README (tools/scene/documented_keys.hpp). One bad value per key, chosen by the
// key's position among its bad values so that every kind (types, NaN, inf, 1e±400, 64-bit
// overflow, bounds) is drawn across the keys; the full keys × values product runs in-process in
// tools/scene/documented_keys_property_test.cpp.
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>

#include "tools/cli/test_support.hpp"
#include "tools/scene/documented_keys.hpp"

namespace fs = std::filesystem;
using namespace stoneskip::test;

namespace {

constexpr int kTimeout_s = 30;

const char* const kStone = stoneskip::test::kPlainStoneCase;

std::string replace_once(std::string s, const std::string& from, const std::string& to) {
  return s.replace(s.find(from), from.size(), to);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(bad_values_end_to_end)

BOOST_AUTO_TEST_CASE(one_bad_value_per_documented_key_through_its_command) {
  const fs::path dir = fs::temp_directory_path() / ("stoneskip_badvalues_" + std::to_string(::getpid()));
  const fs::path out = dir / "out";
  fs::remove_all(dir);
  fs::create_directories(out);
  struct Remove {
    fs::path p;
    ~Remove() {
      std::error_code ec;
      fs::remove_all(p, ec);  // also when a requirement fails
    }
  } remove{dir};
  std::ofstream(dir / "stone.obj") << "v 0 0 0\nv 0.03 0 0\nv 0 0.03 0\nv 0 0 0.01\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n";
  const std::string state = replace_once(kStone, "speed_m_s = 8.0\npath_angle_deg = 10.0\nattack_angle_deg = 10.0\nheight_m = 0.1\n",
                                         "[throw.state]\nposition_m = [0.0, 0.0, 0.1]\nvelocity_m_s = [7.9, 0.0, -1.4]\n"
                                         "quaternion_wxyz = [1.0, 0.0, 0.0, 0.0]\nangular_velocity_rad_s = [0.0, 0.0, 62.8]\n");
  std::ofstream(dir / "stone.toml") << kStone;
  std::ofstream(dir / "state.toml") << state;
  std::ofstream(dir / "mass.toml") << replace_once(kStone, "density_kg_m3 = 2500.0", "mass_kg = 0.05");
  std::ofstream(dir / "mesh.toml") << replace_once(kStone, "shape = \"prism\"\nradius_m = 0.03\nthickness_m = 0.008\n",
                                                   "shape = \"mesh\"\nmesh_file = \"stone.obj\"\n");
  // The README's baseline, its case made absolute.
  std::string baseline;
  {
    std::ifstream in("cases/README.md");
    std::string line;
    bool after = false, in_block = false;
    while (std::getline(in, line)) {
      if (line.rfind("## ", 0) == 0 && line.find("golden baselines") != std::string::npos) after = true;
      if (!after) continue;
      if (line == "```toml") {
        in_block = true;
        continue;
      }
      if (in_block && line.rfind("```", 0) == 0) break;
      if (in_block) baseline += line + "\n";
    }
    baseline = replace_once(baseline, "case = \"cases/", "case = \"" + (fs::current_path() / "cases").string() + "/");
  }

  std::map<std::string, int> per_block;
  for (const auto& k : documented_keys()) {
    const auto bad = bad_values(k);
    BOOST_REQUIRE(!bad.empty());
    const BadValue& v = bad[static_cast<std::size_t>(per_block[k.block]++) % bad.size()];
    stoneskip::test::Args args;
    if (k.block == "stone" || k.block == "scene") {
      std::string base = (dir / "stone.toml").string();
      if (k.block == "scene") base = "cases/scenes/swell_8ms.toml";
      else if (k.section == "throw.state") base = (dir / "state.toml").string();
      else if (k.full() == "stone.mass_kg") base = (dir / "mass.toml").string();
      else if (k.full() == "stone.mesh_file" || k.full() == "stone.disk_radius_m") base = (dir / "mesh.toml").string();
      args = {"run", base, "--set", k.full() + "=" + v.text, "--out", (out / "x.h5").string()};
    } else if (k.block == "wave") {
      std::string base = "cases/wave_gaussian_five_point.toml";
      if (k.section == "stencil") base = "cases/wave_custom_stencil_pool.toml";
      else if (k.key == "radius_m") base = "cases/wave_ring_paper_eq11.toml";
      else if (k.key == "wavelength_m" || k.key == "angle_deg") base = "cases/wave_plane_wave_30deg.toml";
      args = {"wave", base, "--set", k.full() + "=" + v.text};
    } else if (k.block == "sweep") {
      // The README's sweep block, its base made absolute, the key's line rewritten.
      std::string text = sweep_text_with(k, v.text);
      BOOST_REQUIRE(!text.empty());
      if (text.find("base = \"../") != std::string::npos)
        text = replace_once(text, "base = \"../", "base = \"" + (fs::current_path() / "cases").string() + "/");
      std::ofstream(dir / "sweep.toml") << text;
      args = {"sweep", (dir / "sweep.toml").string(), "--quiet", "--out", (out / "x.h5").string()};
    } else {
      std::string text = baseline;
      const auto p = text.find("\n" + k.key + " = ");
      BOOST_REQUIRE(p != std::string::npos);
      text.replace(p + 1, text.find('\n', p + 1) - p - 1, k.key + " = " + v.text);
      std::ofstream(dir / "baseline.toml") << text;
      args = {"regress", "--baseline", (dir / "baseline.toml").string()};
    }
    const RanApart r = run_apart(args, kTimeout_s);
    BOOST_TEST_CONTEXT(k.block << ": " << k.full() << " = " << v.text << " (" << v.why << ")") {
      BOOST_TEST(r.status == 2, "exit " << r.status << ": " << r.err);
      BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1, r.err);
      BOOST_TEST(r.err.find(k.block == "sweep" ? k.key : k.section + ".") != std::string::npos, r.err);
      BOOST_TEST(r.out.empty(), r.out);
      BOOST_TEST(fs::is_empty(out));
    }
  }
  BOOST_TEST(per_block["stone"] + per_block["scene"] + per_block["wave"] + per_block["baseline"] >= 85);
  BOOST_TEST(per_block["sweep"] == 12);
}

BOOST_AUTO_TEST_SUITE_END()
