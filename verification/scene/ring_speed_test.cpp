// The scheme's dispersion against closed forms, and the ring's speed on the seed's scene shrunk.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "solvers/scene/seed_throw_scene.hpp"
#include "verification/scene/ring_speed.hpp"

using namespace stoneskip;

BOOST_AUTO_TEST_SUITE(ring_speed_)

BOOST_AUTO_TEST_CASE(discrete_speeds_match_the_dispersion_relation_closed_forms) {
  // Oracle: model/README.md §2.2 — to leading order the γ = 1/3 stencil's phase speed is c(1 − (kd)²/24)
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
  // Oracle: model/README.md §2.4 — a bounce makes a ring whose radius grows at c less the stencil's
  // dispersion: the leading edge carries the ring's longest waves, so its speed lies between the
  // scheme's group speed at the ring's dominant kd (dispersion relation, tested above) and c.
  // The seed's throw (it sinks in its first contact, x ≈ 0.4 m) on a 3 m pond of 150² cells, two-way.
  const SceneOptions o = seed_throw_scene(150, 150, -1.1, -1.5, 1.2);
  RingSpeedOptions ro;
  ro.start_after_s = 0.2;
  ro.end_after_s = 0.9;
  ro.max_radius_m = 0.9;  // the walls are 1.5 m from the contact: no echo inside 0.9 m within the window
  const RingSpeed r = measure_ring_speed(o, ro);
  BOOST_TEST_REQUIRE(r.found, r.problem);
  BOOST_TEST(r.speed_low_m_s <= r.c_m_s);
  BOOST_TEST(r.speed_high_m_s >= r.group_speed_m_s, "speed [" << r.speed_low_m_s << ", " << r.speed_high_m_s << "], group " << r.group_speed_m_s);
  BOOST_TEST(r.group_speed_m_s < r.c_m_s);
}

BOOST_AUTO_TEST_SUITE_END()
