// Water and air forces (model/README.md §1.4–1.6): closed-form loads in both conventions. The sign of the
// fluid power over random states, per law and convention, is in water_laws_test.cpp.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <numbers>

#include "model/stone/rigid_body.hpp"
#include "model/stone/throw.hpp"
#include "model/stone/water_laws.hpp"
#include "model/stone/water_surface.hpp"

using namespace stoneskip;

namespace {

Stone test_stone(int n = 11) {
  const Mesh m = make_prism(0.03, 0.008, n);
  return make_stone(m, mass_properties_from_density(m, 2500), 0.03, "test prism");
}

}  // namespace

BOOST_AUTO_TEST_SUITE(fluid_forces)

BOOST_AUTO_TEST_CASE(a_flat_plate_sinking_flat_feels_cw_rho_s_w_squared) {
  // Oracle: Newtonian impact law (Eq. 2) on a fully wetted bottom face moving straight down:
  // F = C_w ρ_w S w² upward, no torque; rim faces move tangentially (u = 0) and carry no load.
  const Stone s = test_stone();
  Environment env;
  env.water_coefficient = 0.7;
  RigidState st;
  st.position_m = Vec3(0, 0, 0.004 - 1e-4);  // bottom face 0.1 mm under water, top face dry
  st.velocity_m_s = Vec3(0, 0, -3.0);
  const WaterLoads w = water_loads(s, env, st);
  const double S = 0.5 * 11 * 0.03 * 0.03 * std::sin(2 * std::numbers::pi / 11);
  const double expected = 0.7 * 1000 * S * 9.0;
  BOOST_TEST(std::abs(w.force_N.z() - expected) <= 1e-12 * expected);
  BOOST_TEST(std::abs(w.force_N.x()) + std::abs(w.force_N.y()) <= 1e-12 * expected);
  BOOST_TEST(w.torque_N_m.norm() <= 1e-12 * expected * 0.03);
  BOOST_TEST(std::abs(w.wetted_area_m2 - S - 11 * 0.03 * std::sin(std::numbers::pi / 11) * 2 * 1e-4) <= 1e-12);
}

BOOST_AUTO_TEST_CASE(air_drag_opposes_the_normal_velocity_in_the_physical_convention_only) {
  // Oracle: Eq. 6 closed form. Moving up along the normal (u > 0): physical F = −C ρ u² S n
  // (down), paper F = −C ρ u² S n too; moving down (u < 0): physical pushes up, paper still down.
  const Stone s = test_stone();
  Environment phys, paper;
  paper.convention = Convention::paper;
  RigidState st;
  st.position_m = Vec3(0, 0, 1);
  st.velocity_m_s = Vec3(0, 0, -2);
  const double mag = 1.2 * s.disk_area_m2 * 4.0;
  BOOST_TEST(std::abs(air_loads(s, phys, st).force_N.z() - mag) <= 1e-14);
  BOOST_TEST(std::abs(air_loads(s, paper, st).force_N.z() + mag) <= 1e-14);
}

BOOST_AUTO_TEST_CASE(the_printed_torque_is_the_negative_of_the_physical_one_without_spin) {
  // Oracle: Eq. 3 as printed is F × r = −(r × F). With no spin, v_i is the same in both
  // conventions, and for a face that advances into the water the forces agree: a tilted plate
  // falling straight down has every wet face advancing, so τ_paper = −τ_physical exactly.
  const Stone s = test_stone();
  Environment phys, paper;
  paper.convention = Convention::paper;
  // The plate is tilted by 0.2 rad and only its low edge is under water: the wet faces are the
  // bottom and the low side of the rim, whose outward normals point down, so with no spin every
  // wet face advances (u ≥ 0) while the plate falls straight down.
  RigidState st;
  st.orientation = Quat(Eigen::AngleAxisd(-0.2, Vec3::UnitY()));
  st.velocity_m_s = Vec3(0, 0, -2);
  st.position_m = Vec3(0, 0, 0.03 * std::sin(0.2) - 1e-3);
  const WaterLoads c = water_loads(s, phys, st), d = water_loads(s, paper, st);
  BOOST_TEST(c.torque_N_m.norm() > 0);
  BOOST_TEST((c.torque_N_m + d.torque_N_m).norm() <= 1e-9 * c.torque_N_m.norm() + 1e-15);
}

BOOST_AUTO_TEST_CASE(the_printed_eq1_reverses_the_spin_term_of_a_flat_face) {
  // Oracle: closed form of spec §1.6's printed Eq. 1–3 on the N = 11 prism's bottom face (n = −z),
  // centre of mass at the origin, the face 1e-9 m under, v = (0, 0, −1) m/s, ω = (100, 0, 0) rad/s.
  // Printed Eq. 1: v_i = v + r_i × ω = (0, z ω, −1 − y_i ω), so u_i = v_i · n = 1 + y_i ω; Eq. 2
  // gives F_i = ρ u_i² S_i upward; Eq. 3 as printed, τ = Σ F_i × r_i, has τ_x = −Σ F_i y_i. The fan's
  // mirror symmetry in y (Σ S y = Σ S y³ = 0) leaves F_z = ρ (S + ω² Σ S y²) and τ_x = −2 ρ ω Σ S y²,
  // with each triangle's S_t = R² sin(2π/N)/2 and centroid at (2/3) R cos(π/N) from the axis:
  // Σ S y² = S_t d² N/2 = 4.9275e-7 m⁴, so F_z = 7.6037 N and τ_x = −0.098550 N m. A repaired Eq. 1
  // (v + ω × r, u_i = 1 − y_i ω) keeps F_z but turns τ_x to +0.098550: this test tells them apart.
  // Tolerance 1e-6 relative: the rim's 1e-9 m wet strips carry about 1e-7 N.
  const Stone s = test_stone();
  Environment paper;
  paper.convention = Convention::paper;
  RigidState st;
  st.position_m = Vec3(0, 0, 0.004 - 1e-9);
  st.velocity_m_s = Vec3(0, 0, -1);
  set_body_angular_velocity(s, st, Vec3(100, 0, 0));  // body = world: the identity orientation
  const double R = 0.03, N = 11, w = 100, rho = 1000;
  const double St = 0.5 * R * R * std::sin(2 * std::numbers::pi / N);
  const double d = 2.0 / 3.0 * R * std::cos(std::numbers::pi / N);
  const double Sy2 = St * d * d * N / 2;
  const WaterLoads l = water_loads(s, paper, st);
  BOOST_TEST(l.force_N.z() == rho * (N * St + w * w * Sy2), boost::test_tools::tolerance(1e-6));
  BOOST_TEST(l.torque_N_m.x() == -2 * rho * w * Sy2, boost::test_tools::tolerance(1e-6));
}

BOOST_AUTO_TEST_CASE(a_nan_state_or_surface_gives_nan_loads_not_dry_ones) {
  // Oracle: IEEE: a NaN in the state or the surface must reach the loads, so that the solvers fail
  // saying where. The law's `!(u > 0)` read a NaN normal speed as "no water", and std::max skipped a
  // NaN depth: a stone over a NaN field flew on as if over none.
  const Stone s = test_stone();
  RigidState st;
  st.position_m = Vec3(0, 0, 0.002);  // half under
  st.velocity_m_s = Vec3(3, 0, -1);
  for (WaterLaw law : {WaterLaw::newtonian, WaterLaw::planing, WaterLaw::nagahiro_hayakawa})
    for (PressureDistribution dist : {PressureDistribution::uniform, PressureDistribution::savitsky_wagner}) {
      Environment env;
      env.water_law = law;
      env.pressure_distribution = dist;
      BOOST_TEST_CONTEXT(to_string(law) << ", " << to_string(dist)) {
        BOOST_TEST(std::isnan(law_pressure_Pa(env, std::numeric_limits<double>::quiet_NaN(), 3.0)));
        RigidState spin = st;
        spin.angular_momentum_kg_m2_s = Vec3(0, 0, std::numeric_limits<double>::quiet_NaN());
        BOOST_TEST(!water_loads(s, env, spin).force_N.allFinite());
        struct NanSurface : WaterSurface {
          double height_m(double, double) const override { return std::numeric_limits<double>::quiet_NaN(); }
        } nan_surface;
        BOOST_TEST(!water_loads(s, env, st, &nan_surface).force_N.allFinite());
        BOOST_TEST(water_loads(s, env, st).force_N.allFinite());  // the same state over still water
      }
    }
}

BOOST_AUTO_TEST_SUITE_END()
