// Water and air forces (model/README.md §1.4–1.6): closed-form loads in both conventions. The sign of the
// fluid power over random states, per law and convention, is in water_laws_test.cpp.
#include <boost/test/unit_test.hpp>

#include <numbers>

#include "model/stone/rigid_body.hpp"
#include "model/stone/throw.hpp"

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

BOOST_AUTO_TEST_SUITE_END()
