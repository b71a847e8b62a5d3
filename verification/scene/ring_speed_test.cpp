// The scheme's dispersion against closed forms, and the ring's speed on the seed's scene shrunk.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "model/stone/throw.hpp"
#include "verification/scene/ring_speed.hpp"

using namespace stoneskip;

BOOST_AUTO_TEST_SUITE(ring_speed_)

BOOST_AUTO_TEST_CASE(discrete_speeds_match_the_dispersion_relation_closed_forms) {
  // Oracle: spec §2.2 — to leading order the γ = 1/3 stencil's phase speed is c(1 − (kd)²/24)
  // in every direction, and the leapfrog adds (σ kd)²/24: c_p/c = 1 − (1 − σ²)(kd)²/24 + O(kd⁴);
  // the group speed (d/dk of ω = c k (1 − a k²)) is 1 − 3(1 − σ²)(kd)²/24. At kd = 0.1 the O(kd⁴)
  // rest is below 1e-5: tolerance 2e-5. At σ = 1 the five-point leapfrog is exact along the axes
  // only; its direction mean is below 1.
  const Stencil iso = named_stencil("nine_point_isotropic");
  const double kd = 0.1, sigma = 0.5, a = (1 - sigma * sigma) * kd * kd / 24;
  BOOST_TEST(std::abs(discrete_phase_speed(iso, sigma, kd) - (1 - a)) <= 2e-5);
  BOOST_TEST(std::abs(discrete_group_speed(iso, sigma, kd) - (1 - 3 * a)) <= 2e-5);
  BOOST_TEST(discrete_phase_speed(iso, sigma, 1.0) < discrete_phase_speed(iso, sigma, 0.5));
}

BOOST_AUTO_TEST_CASE(a_bounce_ring_spreads_between_the_schemes_group_speed_and_c) {
  // Oracle: spec §2.4 — a bounce makes a ring whose radius grows at c less the stencil's
  // dispersion: the leading edge carries the ring's longest waves, so its speed lies between the
  // scheme's group speed at the ring's dominant kd (dispersion relation, tested above) and c.
  // The seed's throw (it sinks in its first contact, x ≈ 0.4 m) on a 3 m pond of 150² cells.
  SceneOptions o;
  const Mesh m = make_prism(0.03, 0.008, 11);
  o.stone = make_stone(m, mass_properties_from_density(m, 2500), 0.03, "prism");
  ThrowParameters tp;
  tp.speed_m_s = 8;
  tp.path_angle_deg = 10;
  tp.attack_angle_deg = 10;
  tp.spin_rev_s = 10;
  tp.height_m = 0.1;
  o.initial = initial_state(o.stone, tp);
  o.stone_steps.contact_dt_s = 1e-5;
  SceneWater w;
  w.field.nx = w.field.ny = 150;
  w.field.cell_m = 0.02;
  w.field.wave_speed_m_s = 0.5;
  w.field.damping_per_s = 0.2;
  w.field.dt_s = 1.0 / 90;
  w.field.stencil = named_stencil("nine_point_isotropic");
  w.field.boundary = Boundary::reflecting;
  w.placement.origin_x_m = -1.1;
  w.placement.origin_y_m = -1.5;
  o.water = w;
  o.duration_s = 1.2;
  RingSpeedOptions ro;
  ro.start_after_s = 0.2;
  ro.end_after_s = 0.9;
  ro.max_radius_m = 0.9;  // the wall nearest the contact is 1.1 m away: clear of its echo in the window
  const RingSpeed r = measure_ring_speed(o, ro);
  BOOST_TEST_REQUIRE(r.found, r.problem);
  BOOST_TEST(r.speed_low_m_s <= r.c_m_s);
  BOOST_TEST(r.speed_high_m_s >= r.group_speed_m_s, "speed [" << r.speed_low_m_s << ", " << r.speed_high_m_s << "], group " << r.group_speed_m_s);
  BOOST_TEST(r.group_speed_m_s < r.c_m_s);
}

BOOST_AUTO_TEST_SUITE_END()
