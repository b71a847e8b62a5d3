// Oracle: the rule itself on series made by hand. Errors that do not fall with the step (a scheme
// exact on the problem, measured against an inexact reference: the audit's torque-free flight
// under semi-implicit Euler against CVODE at rtol 1e-6, 1.31e-5 rad at every step, the check run's
// difference 9.37e-6) are "does not converge"; within a decade of the reference's estimated error
// the verdict's reason must say that the reference may not resolve them, and not otherwise.
#include <boost/test/unit_test.hpp>

#include <limits>
#include <string>

#include "verification/stones/realtime_convergence.hpp"

namespace stoneskip {
namespace {

ConvergenceSeries flat_series(double reference_error) {
  ConvergenceSeries s;
  s.quantity = "flight_interval_orientation";
  s.scheme = "semi_implicit_euler";
  s.formal_order = 1;
  s.h_s = {1.32579928e-3, 6.62899641e-4, 3.31449820e-4};
  s.value = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  s.error = {1.30837299e-5, 1.30837299e-5, 1.30837299e-5};
  s.reference_error = reference_error;
  return s;
}

BOOST_AUTO_TEST_SUITE(finish_series_)

BOOST_AUTO_TEST_CASE(a_flat_series_near_the_references_error_says_the_reference_may_not_resolve_it) {
  const RealtimeConvergenceOptions o;
  ConvergenceSeries near = flat_series(9.373023e-6);
  finish_series(near, o);
  BOOST_TEST(to_string(near.decision.verdict) == std::string("does not converge"));
  BOOST_TEST(near.decision.reason.find("its smallest error is 1.4× the reference's estimated error") != std::string::npos,
             near.decision.reason);
  ConvergenceSeries far = flat_series(1e-9);  // four decades below: the scheme's own
  finish_series(far, o);
  BOOST_TEST(to_string(far.decision.verdict) == std::string("does not converge"));
  BOOST_TEST(far.decision.reason.find("may not resolve") == std::string::npos, far.decision.reason);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
