// Sweep files: the schema read strictly, and a throw's case equal to the case `--set` builds.
// Oracles: the file's own text (keys, lines), the TOML reader (an override's literal reads back as
// the same double), and load_stone_case with --set overrides (an independent path: text parsed
// with the assignments) against SweepCases::at (a copy of the parsed base with values set).
#include <boost/test/unit_test.hpp>

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "tools/io/input_error.hpp"
#include "tools/scene/resource_estimate.hpp"
#include "tools/scene/sweep_file.hpp"

using namespace stoneskip;
namespace fs = std::filesystem;

namespace {

// The folder of the test's sweep files, and the shipped paper throw as their base. Only named
// here: it is made when a file is first written, so that a run of this binary that skips the suite
// (which then never removes it) leaves nothing behind.
fs::path dir() { return fs::temp_directory_path() / ("stoneskip_sweepfile_" + std::to_string(::getpid())); }

// The suite's files go when it ends.
struct RemoveScratch {
  ~RemoveScratch() {
    std::error_code ec;
    fs::remove_all(dir(), ec);
  }
};

const fs::path kBase = fs::absolute("cases/paper_8ms_spin.toml");

fs::path write_sweep(const std::string& text) {
  const fs::path p = dir() / "sweeps" / "s.toml";
  fs::create_directories(p.parent_path());
  std::ofstream(p) << text;
  return p;
}

// base (relative to the sweep file) on line 1, both solvers, a 5 × 3 grid, one axis log.
const std::string kGrid = "base = \"" + fs::relative(kBase, dir() / "sweeps").string() + "\"\n" + R"(solvers = ["realtime", "reference"]
[design]
kind = "grid"
[[vary]]
key = "throw.speed_m_s"
from = 4.0
to = 12.0
count = 5
[[vary]]
key = "environment.water_coefficient"
from = 0.5
to = 2.0
count = 3
scale = "log"
)";

// The one-line error of loading (and probing) a sweep file.
std::string error_of(const std::string& text) {
  try {
    const SweepFile s = load_sweep_file(write_sweep(text).string());
    SweepCases cases(s);
  } catch (const InputError& e) {
    const std::string m = e.what();
    BOOST_TEST(m.find('\n') == std::string::npos, "one line: " << m);
    return m;
  }
  return "";
}

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto at = s.find(from);
  BOOST_REQUIRE(at != std::string::npos);
  return s.replace(at, from.size(), to);
}

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0; }

}  // namespace

BOOST_AUTO_TEST_SUITE(sweep_file, *boost::unit_test::fixture<RemoveScratch>())

BOOST_AUTO_TEST_CASE(a_grid_sweep_file_reads_as_written) {
  // Oracle: kGrid's text.
  const fs::path p = write_sweep(kGrid);
  const SweepFile s = load_sweep_file(p.string());
  BOOST_TEST(s.title == "s");
  BOOST_TEST(fs::equivalent(s.base_file, kBase));  // relative to the sweep file
  BOOST_TEST((s.solvers == SweepSolvers::both));
  BOOST_TEST(s.design.size() == 15u);
  BOOST_TEST((s.design.axes[1].scale == AxisScale::log));
  BOOST_TEST(s.axis_lines == std::vector<long>({6, 11}));
}

BOOST_AUTO_TEST_CASE(a_key_varied_twice_is_refused_however_it_is_written) {
  // Oracle: TOML 1.0, "Keys" — 'throw . "speed_m_s"' is the key throw.speed_m_s, which the case
  // reader sets (--set reads dotted keys); varied twice, the second axis would overwrite the first
  // at every point. main compared the texts and ran it.
  const std::string twice = replace(kGrid, "key = \"environment.water_coefficient\"", "key = 'throw . \"speed_m_s\"'");
  const std::string m = error_of(twice);
  BOOST_TEST(m.find("vary[2].key: \"throw.speed_m_s\" is varied twice") != std::string::npos, m);
  const SweepFile s = load_sweep_file(write_sweep(kGrid).string());
  BOOST_TEST(s.design.axes[0].key == "throw.speed_m_s");
}

BOOST_AUTO_TEST_CASE(an_override_literal_reads_back_as_the_same_double) {
  // Oracle: the TOML reader on "k = <literal>".
  for (double v : {0.1, 1.0 / 3, 1e-7, 12.0, -0.0, 2.5e20, -7.25, 4.000000000000001}) {
    const std::string a = sweep_override("k", v);
    const TomlDocument d = parse_toml_text(a.substr(0, 1) + " = " + a.substr(2), "t");
    TomlTable t = d.top();
    const double back = t.number("k");
    BOOST_TEST(std::memcmp(&back, &v, sizeof v) == 0, a);
  }
  BOOST_TEST(sweep_override("stone.segments", 12.0) == "stone.segments=12");  // an integer key stays an integer
}

BOOST_AUTO_TEST_CASE(a_throws_case_is_the_case_that_set_overrides_build) {
  // Oracle: load_stone_case(base, --set assignments), which parses the text with the overrides.
  const SweepFile s = load_sweep_file(write_sweep(kGrid).string());
  const SweepCases cases(s);
  for (std::size_t i : {0u, 7u, 14u}) {
    const std::vector<double> p = s.design.point(i);
    const StoneCase a = cases.at(p);
    const StoneCase b = load_stone_case(s.base_file, {sweep_override("throw.speed_m_s", p[0]),
                                                      sweep_override("environment.water_coefficient", p[1])});
    BOOST_TEST(same_bits(a.initial.velocity_m_s, b.initial.velocity_m_s));
    BOOST_TEST(same_bits(a.initial.angular_momentum_kg_m2_s, b.initial.angular_momentum_kg_m2_s));
    BOOST_TEST(a.environment.water_coefficient == b.environment.water_coefficient);
    BOOST_TEST(a.throw_parameters.speed_m_s == p[0]);
  }
}

BOOST_AUTO_TEST_CASE(an_integer_key_can_be_swept_with_whole_values) {
  // Oracle: segments 8..12 are whole numbers, written as TOML integers.
  const std::string text = replace(kGrid, "key = \"environment.water_coefficient\"\nfrom = 0.5\nto = 2.0\ncount = 3\nscale = \"log\"",
                                   "key = \"stone.segments\"\nfrom = 8\nto = 12\ncount = 5");
  const SweepFile s = load_sweep_file(write_sweep(text).string());
  const SweepCases cases(s);
  BOOST_TEST(cases.at({8.0, 12.0}).stone.body_mesh.triangles.size() == 48u);  // 4N triangles
}

BOOST_AUTO_TEST_CASE(an_integer_key_takes_every_whole_value_of_a_long_grid) {
  // Oracle: segments 3…30 in 28 points are the whole numbers 3…30 (4N triangles each); 3…30 in 11
  // points has 5.7, which the case reader refuses: the sweep is refused before any throw runs.
  const std::string whole = replace(kGrid, "key = \"environment.water_coefficient\"\nfrom = 0.5\nto = 2.0\ncount = 3\nscale = \"log\"",
                                    "key = \"stone.segments\"\nfrom = 3\nto = 30\ncount = 28");
  const SweepFile s = load_sweep_file(write_sweep(whole).string());
  const SweepCases cases(s);
  for (std::size_t i = 0; i < s.design.size(); ++i) {
    const std::vector<double> p = s.design.point(i);
    BOOST_TEST(cases.at(p).stone.body_mesh.triangles.size() == 4 * static_cast<std::size_t>(p[1]), "throw " << i);
  }
  const std::string m = error_of(replace(whole, "count = 28", "count = 11"));
  BOOST_TEST(m.find("vary[2]") != std::string::npos, m);
  BOOST_TEST(m.find("stone.segments=5.7") != std::string::npos, m);
}

BOOST_AUTO_TEST_CASE(a_sweep_of_more_than_ten_axes_is_held_to_its_heaviest_corner) {
  // Oracle: estimate_run at the corner that is heaviest (t_max_s and segments at their top, the
  // contact step at its bottom): the sweep's heaviest throw must be at least that heavy. Eight
  // axes of one value make eleven, past the 2ⁿ corners probed up to ten.
  // The contact step is a fixed scheme's: the base case's default adaptive stepper is set to one.
  std::string text = "base = \"" + fs::relative(kBase, dir() / "sweeps").string() +
                     "\"\nset = [\"solver.scheme=semi_implicit_euler\", \"solver.dt_s=1e-3\", \"solver.contact_dt_s=1e-5\"]\n[design]\nkind = \"grid\"\n";
  auto vary = [&](const std::string& key, double from, double to, int count) {
    text += "[[vary]]\nkey = \"" + key + "\"\nfrom = " + std::to_string(from) + "\nto = " + std::to_string(to) +
            "\ncount = " + std::to_string(count) + "\n";
  };
  vary("solver.t_max_s", 1.0, 2.0, 2);
  vary("solver.contact_dt_s", 1e-6, 1e-5, 2);
  vary("stone.segments", 11, 40, 2);
  struct Fixed { const char* key; double value; };
  const Fixed fixed[] = {{"throw.speed_m_s", 8},         {"throw.path_angle_deg", 10}, {"throw.attack_angle_deg", 10},
                         {"throw.spin_rev_s", 10},       {"throw.height_m", 0.1},      {"stone.radius_m", 0.03},
                         {"stone.thickness_m", 0.008},   {"stone.density_kg_m3", 2500}};
  for (const Fixed& f : fixed) vary(f.key, f.value, f.value, 1);
  const SweepFile s = load_sweep_file(write_sweep(text).string());
  BOOST_REQUIRE(s.design.axes.size() == 11u);
  const SweepCases cases(s);
  std::vector<double> corner = {2.0, 1e-6, 40};
  for (const Fixed& f : fixed) corner.push_back(f.value);
  const ResourceEstimate heaviest = estimate_run(cases.at(corner), RunSolvers{});
  BOOST_REQUIRE(cases.heaviest_throw().work.size() == heaviest.work.size());
  for (std::size_t i = 0; i < heaviest.work.size(); ++i)
    BOOST_TEST(cases.heaviest_throw().work[i].count >= heaviest.work[i].count, heaviest.work[i].what);
}

BOOST_AUTO_TEST_CASE(bad_sweep_files_fail_with_one_line_naming_file_line_and_key) {
  // Oracle: the line of the offending key in each broken copy of kGrid.
  struct Bad {
    std::string text, expect1, expect2;
  };
  const std::vector<Bad> bad = {
      {kGrid + "colour = 3\n", "s.toml:16: vary[2].colour", "unknown key"},
      {"typo = 1\n" + kGrid, "s.toml:1: typo", "unknown key"},
      {replace(kGrid, "count = 5", "count = 0"), "s.toml:9: vary[1].count", ">= 1"},
      {replace(kGrid, "count = 5", "count = -2"), "s.toml:9: vary[1].count", ">= 1"},
      {replace(kGrid, "from = 0.5", "from = 3.0"), "s.toml:13: vary[2].to", "must not exceed"},
      {replace(kGrid, "from = 0.5", "from = 0.0"), "s.toml:12: vary[2].from", "log axis"},
      {replace(kGrid, "environment.water_coefficient", "environment.convention"), "s.toml:11: vary[2].key", "not a numeric key"},
      {replace(kGrid, "throw.speed_m_s", "throw.sped_m_s"), "s.toml:6: vary[1].key", "unknown key"},
      // A misspelt table: the reader's words ("--set thrw") were a command line's, not the file's.
      {replace(kGrid, "key = \"environment.water_coefficient\"", "key = \"environmnt.water_coefficient\""),
       "s.toml:11: vary[2].key", "the varied key environmnt: unknown key"},
      {replace(kGrid, "from = 4.0", "from = -4.0"), "s.toml:6: vary[1]", "speed_m_s"},
      {replace(kGrid, "paper_8ms_spin.toml", "missing.toml"), "s.toml:1: base", "no such file"},
      {replace(kGrid, "kind = \"grid\"", "kind = \"grid\"\nseed = 3"), "s.toml:5: design.seed", "random designs"},
      {replace(kGrid, "kind = \"grid\"", "kind = \"random\"\nsamples = 10"), "design.seed", "missing"},
      {replace(kGrid, "kind = \"grid\"", "kind = \"random\"\nsamples = 10\nseed = 1"), "s.toml:11: vary[1].count", "for grids"},
      {replace(kGrid, "kind = \"grid\"", "kind = \"sobol\""), "s.toml:4: design.kind", "latin_hypercube"},
      {replace(kGrid, "\"reference\"]", "\"cvode\"]"), "s.toml:2: solvers", "\"cvode\""},
      {replace(kGrid, "to = 12.0", "to = \"fast\""), "s.toml:8: vary[1].to", "expected a number"},
      {replace(kGrid, "key = \"environment.water_coefficient\"\nfrom = 0.5\nto = 2.0\ncount = 3\nscale = \"log\"",
               "key = \"stone.segments\"\nfrom = 11\nto = 12\ncount = 3"),
       "s.toml:11: vary[2]", "expected an integer"},
      // An override that does not apply is the `set` line's fault, not the base's (which loads alone).
      {replace(kGrid, "solvers =", "set = [\"throw.spinn_rev_s=3\"]\nsolvers ="), "s.toml:2: set", "spinn_rev_s"},
      {replace(kGrid, "solvers =", "set = [\"throw.spin_rev_s=fast\"]\nsolvers ="), "s.toml:2: set", "expected a number"},
      {replace(kGrid, "solvers =", "set = [\"throw.speed_m_s=-1\"]\nsolvers ="), "s.toml:2: set", "speed_m_s"},
      // An array over several lines: the entry's own line.
      {replace(kGrid, "solvers =", "set = [\n  \"throw.spin_rev_s=3\",\n  \"throw.spin_rev_s=fast\",\n]\nsolvers ="), "s.toml:4: set",
       "entry throw.spin_rev_s"},
  };
  for (const auto& b : bad) {
    const std::string m = error_of(b.text);
    BOOST_TEST(m.find(b.expect1) != std::string::npos, "'" << b.expect1 << "' not in: " << m);
    BOOST_TEST(m.find(b.expect2) != std::string::npos, "'" << b.expect2 << "' not in: " << m);
  }
}

BOOST_AUTO_TEST_SUITE_END()
