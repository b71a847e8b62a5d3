// The keys this module added to stone cases (cases/README.md): [environment] water_law with each
// law's published C_w, [reference] restart and atol_scaling; strict one-line errors for bad values
// and for a law the paper convention does not have; resolved settings that read back the same.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>

#include "tools/io/input_error.hpp"
#include "tools/scene/documented_keys.hpp"
#include "tools/scene/stone_case.hpp"

using namespace stoneskip;

namespace {

const char* const kCase = stoneskip::test::kPlainStoneCase;  // the paper's prism, 1 s (tools/scene/documented_keys.hpp)

StoneCase parse(const std::vector<std::string>& overrides) {
  return stone_case_from_document(parse_toml_text(kCase, "law.toml", overrides));
}

// The one-line message of the InputError thrown, or "" if none.
std::string error_of(const std::vector<std::string>& overrides) {
  try {
    parse(overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(stone_case_keys)

BOOST_AUTO_TEST_CASE(a_water_law_takes_its_published_coefficient_unless_one_is_given) {
  // Oracle: cases/README.md — the physical convention defaults to planing (C_w ½) with savitsky_wagner,
  // the paper convention to its printed newtonian law (C_w 1) with uniform pressure; a named law
  // takes its published C_w (newtonian 1, planing ½, nagahiro_hayakawa 0.7, environment.hpp); an
  // explicit water_coefficient wins.
  BOOST_TEST((parse({}).environment.water_law == WaterLaw::planing));
  BOOST_TEST(parse({}).environment.water_coefficient == 0.5);
  BOOST_TEST((parse({}).environment.pressure_distribution == PressureDistribution::savitsky_wagner));
  const Environment paper = parse({"environment.convention=paper"}).environment;
  BOOST_TEST((paper.water_law == WaterLaw::newtonian));
  BOOST_TEST(paper.water_coefficient == 1.0);
  BOOST_TEST((paper.pressure_distribution == PressureDistribution::uniform));
  BOOST_TEST((parse({"environment.water_law=newtonian"}).environment.water_coefficient == 1.0));
  BOOST_TEST((parse({"environment.water_law=planing"}).environment.water_law == WaterLaw::planing));
  BOOST_TEST(parse({"environment.water_law=planing"}).environment.water_coefficient == 0.5);
  BOOST_TEST(parse({"environment.water_law=nagahiro_hayakawa"}).environment.water_coefficient == 0.7);
  BOOST_TEST(parse({"environment.water_law=planing", "environment.water_coefficient=0.8"}).environment.water_coefficient == 0.8);
}

BOOST_AUTO_TEST_CASE(bad_laws_and_strategies_are_one_line_errors_naming_the_key) {
  // Oracle: the strict-parsing rule of cases/README.md: file, key and what is wrong, one line.
  const std::string misspelt = error_of({"environment.water_law=planning"});
  BOOST_TEST(misspelt.find("law.toml") != std::string::npos, misspelt);
  BOOST_TEST(misspelt.find("environment.water_law") != std::string::npos, misspelt);
  BOOST_TEST(misspelt.find("planning") != std::string::npos, misspelt);
  BOOST_TEST(misspelt.find('\n') == std::string::npos);
  const std::string paper = error_of({"environment.convention=paper", "environment.water_law=planing"});
  BOOST_TEST(paper.find("environment.water_law") != std::string::npos, paper);
  BOOST_TEST(paper.find("paper convention") != std::string::npos, paper);
  // Neither Eq. 6's C_a nor a held attitude is printed: refused in the paper convention by key,
  // taken in the physical one.
  for (const char* key : {"environment.air_coefficient=0.5", "environment.attitude=held"}) {
    const std::string e = error_of({"environment.convention=paper", key});
    BOOST_TEST(e.find(std::string(key).substr(0, std::string(key).find('='))) != std::string::npos, e);
    BOOST_TEST(e.find("with the paper convention") != std::string::npos, e);
    BOOST_TEST(e.find('\n') == std::string::npos);
    BOOST_TEST(error_of({key}).empty(), error_of({key}));
  }
  BOOST_TEST(error_of({"reference.restart=sometimes"}).find("reference.restart") != std::string::npos);
  BOOST_TEST(error_of({"reference.atol_scaling=scalar"}).find("reference.atol_scaling") != std::string::npos);
  BOOST_TEST(error_of({"reference.locate_switches=true"}).find("reference.locate_switches") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(resolved_settings_run_as_a_case_and_give_the_same_throw) {
  // Oracle: the settings a result file stores must load as a case (they held both density and
  // mass, a prism's disk_radius_m, and both [throw] and [throw.state], each refused) and give the
  // same stone and initial state: written again, the text is the same (a fixed point), and the
  // state agrees to the 12 digits written. Shipped cases: parameters and density, a mass, a mesh;
  // and the state form, made from the first by uncommenting its state and dropping [throw].
  auto reload = [](const std::string& text) { return stone_case_from_document(parse_toml_text(text, "back.toml", {})); };
  for (const char* file : {"cases/paper_8ms_spin.toml", "cases/hard/heavy_stone.toml", "cases/hard/tumbling_asymmetric.toml"}) {
    const StoneCase c = load_stone_case(file);
    const std::string text = c.resolved_settings();
    StoneCase back;
    BOOST_REQUIRE_NO_THROW(back = reload(text));
    BOOST_TEST(back.resolved_settings() == text, file);
    BOOST_TEST((back.initial.position_m - c.initial.position_m).norm() <= 1e-12, file);
    BOOST_TEST((back.initial.velocity_m_s - c.initial.velocity_m_s).norm() <= 1e-11, file);
    BOOST_TEST(std::abs(back.stone.mass.mass_kg - c.stone.mass.mass_kg) <= 1e-12 * c.stone.mass.mass_kg, file);
  }
  std::string text = load_stone_case("cases/paper_8ms_spin.toml").resolved_settings();
  const std::size_t from = text.find("\n[throw]\n"), to = text.find("\n# [throw.state]");
  BOOST_REQUIRE(from != std::string::npos);
  BOOST_REQUIRE(to != std::string::npos);
  text.erase(from, to - from);
  for (std::size_t at = text.find("\n# "); at != std::string::npos && at < text.find("\n[solver]"); at = text.find("\n# ", at))
    text.erase(at + 1, 2);
  const std::string header = "[throw.state]  (the state the parameters above give)";
  text.replace(text.find(header), header.size(), "[throw.state]");
  const StoneCase state = reload(text);
  BOOST_TEST(!state.throw_from_parameters);
  const std::string again = state.resolved_settings();
  BOOST_TEST(again.find("\n[throw.state]\n") != std::string::npos, again);
  BOOST_TEST(again.find("\n[throw]\n") == std::string::npos, again);
  // The state written from a state: the same to the digits written (the angular velocity is
  // recomputed from the angular momentum, so the last digit may move).
  const StoneCase twice = reload(again);
  BOOST_TEST((twice.initial.velocity_m_s - state.initial.velocity_m_s).norm() <= 1e-12);
  BOOST_TEST((twice.initial.angular_momentum_kg_m2_s - state.initial.angular_momentum_kg_m2_s).norm() <=
             1e-12 * state.initial.angular_momentum_kg_m2_s.norm());
  BOOST_TEST((state.initial.velocity_m_s - load_stone_case("cases/paper_8ms_spin.toml").initial.velocity_m_s).norm() <= 1e-10);
}

BOOST_AUTO_TEST_CASE(restart_and_tolerance_scaling_are_read_and_written_back) {
  // Oracle: the values given; resolved_settings() must name them so the run can be repeated.
  const StoneCase c = parse({"reference.restart=every_event", "reference.atol_scaling=uniform", "environment.water_law=planing"});
  BOOST_TEST((c.reference.restart == RestartStrategy::every_event));
  BOOST_TEST((c.reference.atol_scaling == ToleranceScaling::uniform));
  const std::string s = c.resolved_settings();
  BOOST_TEST(s.find("restart = \"every_event\"") != std::string::npos, s);
  BOOST_TEST(s.find("atol_scaling = \"uniform\"") != std::string::npos, s);
  BOOST_TEST(s.find("water_law = \"planing\"") != std::string::npos, s);
  BOOST_TEST((parse({}).reference.restart == ReferenceOptions{}.restart));
}

BOOST_AUTO_TEST_CASE(a_case_names_a_scheme_and_a_tolerance_and_old_fixed_step_cases_read_as_before) {
  // Oracle: cases/README.md's [solver] block: with no scheme named, a case that gives contact_dt_s
  // keeps semi_implicit_euler with its steps (every case written before bs32 existed), one that
  // does not gets bs32 with rtol = atol_m = 1e-9 and its dt_s as the largest step; a tolerance given
  // to a fixed scheme is a one-line error naming it; bs32's settings are written back.
  const StoneCase old = parse({});
  BOOST_TEST((old.realtime.scheme == Scheme::semi_implicit_euler));
  BOOST_TEST(old.realtime.contact_dt_s == 1e-5);
  const std::string text = std::string(kCase);
  const std::string without = text.substr(0, text.find("contact_dt_s")) + text.substr(text.find("t_max_s"));
  const StoneCase adaptive = stone_case_from_document(parse_toml_text(without, "a.toml", {}));
  BOOST_TEST((adaptive.realtime.scheme == Scheme::bs32));
  BOOST_TEST(adaptive.realtime.rtol == 1e-9);
  BOOST_TEST(adaptive.realtime.atol_m == 1e-9);
  BOOST_TEST(adaptive.realtime.dt_s == 1e-3);  // the case's dt_s, now bs32's largest step
  const StoneCase tight = stone_case_from_document(parse_toml_text(without, "a.toml", {"solver.rtol=1e-7", "solver.atol_m=1e-9"}));
  BOOST_TEST(tight.realtime.rtol == 1e-7);
  BOOST_TEST(tight.realtime.atol_m == 1e-9);
  const std::string back = tight.resolved_settings();
  BOOST_TEST(back.find("scheme = \"bs32\"") != std::string::npos, back);
  BOOST_TEST(back.find("rtol = 1e-07") != std::string::npos, back);
  BOOST_TEST(back.find("atol_m = 1e-09") != std::string::npos, back);
  BOOST_TEST((parse({"solver.scheme=bs32"}).realtime.scheme == Scheme::bs32));  // an old case switched by --set
  const std::string e = error_of({"solver.scheme=rk4", "solver.rtol=1e-8"});
  BOOST_TEST(e.find("solver.rtol") != std::string::npos, e);
  BOOST_TEST(e.find('\n') == std::string::npos, e);
  const std::string bad = error_of({"solver.scheme=bs32", "solver.rtol=0.5"});
  BOOST_TEST(bad.find("solver.rtol") != std::string::npos, bad);
}

BOOST_AUTO_TEST_CASE(a_state_quaternion_of_any_size_but_zero_is_an_orientation) {
  // Oracle: a quaternion names a rotation whatever its length. [1e300, 1e300, 0, 0] overflowed
  // the norm and was refused as "zero"; it is the quarter turn about x, (1, 1, 0, 0)/√2.
  auto with_state = [&](const std::string& q) {
    std::string c = kCase;
    const auto a = c.find("speed_m_s"), b = c.find("[solver]");
    c.replace(a, b - a,
              "[throw.state]\nposition_m = [0.0, 0.0, 0.1]\nvelocity_m_s = [7.9, 0.0, -1.4]\nquaternion_wxyz = " + q +
                  "\nangular_velocity_rad_s = [0.0, 0.0, 62.8]\n");
    return c;
  };
  const StoneCase big = stone_case_from_document(parse_toml_text(with_state("[1e300, 1e300, 0.0, 0.0]"), "q.toml"));
  const StoneCase one = stone_case_from_document(parse_toml_text(with_state("[1.0, 1.0, 0.0, 0.0]"), "q.toml"));
  BOOST_TEST(big.initial.orientation.coeffs().isApprox(one.initial.orientation.coeffs(), 1e-15));
  BOOST_TEST(std::abs(big.initial.orientation.w() - std::sqrt(0.5)) < 1e-15);
  try {
    stone_case_from_document(parse_toml_text(with_state("[0.0, 0.0, 0.0, 0.0]"), "q.toml"));
    BOOST_FAIL("a zero quaternion was accepted");
  } catch (const InputError& e) {
    BOOST_TEST(std::string(e.what()).find("must not be zero") != std::string::npos);
  }
}

BOOST_AUTO_TEST_CASE(a_key_of_another_shape_is_named_as_such_not_as_a_misspelling) {
  // Oracle: cases/README.md's [stone] keys by shape. radius_m is a prism's key: under shape "mesh"
  // the error says whose key it is (it said "unknown key (misspelt?)").
  const std::string e = error_of({"stone.shape=\"mesh\"", "stone.mesh_file=\"x.obj\""});
  BOOST_TEST(e.find("stone.radius_m: is a key of shape \"prism\" or \"lens\", not of shape \"mesh\"") != std::string::npos, e);
  const std::string f = error_of({"stone.mesh_file=\"x.obj\""});
  BOOST_TEST(f.find("stone.mesh_file: is a key of shape \"mesh\", not of shape \"prism\"") != std::string::npos, f);
}

BOOST_AUTO_TEST_CASE(a_thick_prism_or_lens_keeps_its_symmetry_axis_as_body_z) {
  // Oracle: spec §1 (body z along the symmetry axis, the normal of the flat faces) and the N-gon's
  // moments (model/README.md §1.2): for the N = 11 prism I_xx = I_zz at h = 1.686 R, for the lens (a
  // double cone, 3 m R²/10 against m (3 R²/20 + h²/40)) at h = 2.45 R. At h = 3 R the moment about
  // the axis is the smallest for both, yet body z stays the axis: every
  // vertex keeps its height ±h/2 and the air disk its radius R. The principal rule had put the
  // axis on body x (a spin about body z then tumbles the stone end over end).
  for (const char* shape : {"prism", "lens"}) {
    BOOST_TEST_CONTEXT(shape) {
      const StoneCase c = parse({std::string("stone.shape=\"") + shape + "\"", "stone.radius_m=0.01", "stone.thickness_m=0.03"});
      const Stone& s = c.stone;
      BOOST_TEST((s.body_axes_in_mesh - Mat3::Identity()).norm() == 0.0);
      double top = -1, bottom = 1;
      for (const Vec3& v : s.body_mesh.vertices) {
        top = std::max(top, v.z());
        bottom = std::min(bottom, v.z());
      }
      BOOST_TEST(top - bottom == 0.03, boost::test_tools::tolerance(1e-12));  // the thickness along body z
      BOOST_TEST(s.disk_radius_m == 0.01);
      // The axis's moment the smallest: the case the principal rule turned on its side.
      BOOST_TEST(s.inertia_body_kg_m2(2, 2) < s.inertia_body_kg_m2(0, 0));
      BOOST_TEST(s.inertia_body_kg_m2(2, 2) < s.inertia_body_kg_m2(1, 1));
    }
  }
  // The prism's moment about its axis against the closed form (a check that the axis is the z of
  // the mesh, not a relabelled one): m R² (1 + 2 cos²(π/N)) / 6.
  const StoneCase c = parse({"stone.radius_m=0.01", "stone.thickness_m=0.03"});
  const double cos_pi_n = std::cos(std::numbers::pi / c.spec.segments);
  BOOST_TEST(c.stone.inertia_body_kg_m2(2, 2) ==
                 c.stone.mass.mass_kg * 1e-4 * (1 + 2 * cos_pi_n * cos_pi_n) / 6,
             boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_SUITE_END()
