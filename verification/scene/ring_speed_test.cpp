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

BOOST_AUTO_TEST_SUITE_END()
