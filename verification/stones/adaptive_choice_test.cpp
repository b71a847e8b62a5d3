// The work-precision study's choice of the adaptive tolerance (choose_adaptive_tolerance): the
// loosest tolerance that, with every tighter one, keeps the truth's contact list on every
// physical-convention throw; paper-convention throws are set aside (their contact lists are
// chaotic). Oracle: the choice worked out by hand on made-up study points.
#include <boost/test/unit_test.hpp>

#include "verification/stones/work_precision.hpp"

namespace stoneskip {
namespace {

const char* const kFamily = "realtime bs32 (adaptive)";

WorkPoint point(double tol, bool ok, double contact_error_s) {
  WorkPoint p;
  p.family = kFamily;
  p.adaptive = true;
  p.setting = tol;
  p.ok = ok;
  p.contact_time_error_s = contact_error_s;
  p.rhs_evaluations = 100;
  return p;
}

// A throw that keeps its contact list at every tolerance up to `loosest_kept` (and loses it above).
WorkPrecisionThrow throw_keeping_up_to(const std::string& label, Convention c, double loosest_kept) {
  WorkPrecisionThrow t;
  t.label = label;
  t.convention = c;
  for (double tol : {1e-10, 1e-9, 1e-8, 1e-7}) t.points.push_back(point(tol, tol <= loosest_kept, tol * 10));
  return t;
}

const std::vector<WorkPrecisionOptions::RealtimeFamily> kFamilies{{Scheme::rk4, 0.1}, {Scheme::bs32, 0.0}};
const std::vector<double> kTolerances{1e-7, 1e-10, 1e-8, 1e-9};  // any order: sorted tightest first

BOOST_AUTO_TEST_SUITE(adaptive_choice)

BOOST_AUTO_TEST_CASE(the_choice_is_the_loosest_tolerance_every_physical_throw_keeps_and_paper_throws_are_set_aside) {
  // Physical throws keep their lists up to 1e-8 and 1e-9: the choice is 1e-9. The paper-convention
  // throw keeps its list only at 1e-10; counted, it would force 1e-10.
  const std::vector<WorkPrecisionThrow> throws{throw_keeping_up_to("a", Convention::physical, 1e-8),
                                               throw_keeping_up_to("b", Convention::physical, 1e-9),
                                               throw_keeping_up_to("printed", Convention::paper, 1e-10)};
  const AdaptiveToleranceChoice a = choose_adaptive_tolerance(throws, kFamilies, kTolerances);
  BOOST_TEST(a.studied);
  BOOST_TEST(a.family == kFamily);
  BOOST_TEST(a.throws == 2);
  BOOST_TEST(a.set_aside == std::vector<std::string>{"printed"}, boost::test_tools::per_element());
  BOOST_TEST(a.found);
  BOOST_TEST(a.tolerance == 1e-9);
  BOOST_TEST(a.worst_contact_time_error_s == 1e-8, boost::test_tools::tolerance(1e-12));  // 10 × tol at the choice
  BOOST_TEST(a.rhs_evaluations == 200);
  BOOST_TEST(a.throws_keeping_contacts == (std::vector<int>{2, 2, 1, 0}), boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(a_tolerance_lost_below_a_kept_one_ends_the_choice_there) {
  // "With every tighter one": a throw that loses its list at 1e-9 but keeps it at 1e-8 (a lucky
  // coarse run) does not make 1e-8 the choice.
  WorkPrecisionThrow odd = throw_keeping_up_to("odd", Convention::physical, 1e-8);
  odd.points[1].ok = false;  // 1e-9 lost
  const AdaptiveToleranceChoice a = choose_adaptive_tolerance({odd}, kFamilies, kTolerances);
  BOOST_TEST(a.found);
  BOOST_TEST(a.tolerance == 1e-10);
}

BOOST_AUTO_TEST_CASE(only_paper_convention_throws_leave_nothing_to_choose_on) {
  const AdaptiveToleranceChoice a =
      choose_adaptive_tolerance({throw_keeping_up_to("printed", Convention::paper, 1e-7)}, kFamilies, kTolerances);
  BOOST_TEST(a.throws == 0);
  BOOST_TEST(!a.found);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
