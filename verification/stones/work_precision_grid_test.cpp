// A small work-precision grid (2 spins × 1 attack angle) run end to end: every throw is either kept
// or set aside with its reason, every family runs on every kept throw, and a check that could fail:
// CVODE at a tight rtol keeps the truth's bounce count and contact list on every kept throw.
#include "verification/stones/work_precision_grid.hpp"

#include <boost/test/unit_test.hpp>

#include <cmath>

#include "verification/stones/convergence_throw.hpp"

namespace stoneskip {
namespace {

// CVODE at rtol 1e-8 against its truth at 1e-11: contact times agree to far better than this
// (the reference-tolerance study shows errors of order rtol × the contact's time scale).
constexpr double kTightCvodeTime_s = 1e-5;

BOOST_AUTO_TEST_SUITE(work_precision_grid)

BOOST_AUTO_TEST_CASE(a_two_throw_grid_keeps_or_sets_aside_each_throw_and_tight_cvode_agrees_on_every_kept_one) {
  // Oracle: CVODE BDF at rtol 1e-8 solves the same equations as the truth (rtol 1e-11) and must
  // reproduce its bounce count and contact list on every throw whose two truths agree; the counts
  // of the summaries follow from the grid (kept throws × settings). The convergence throw (one
  // bounce, then a planing run) at 0 and 40 rev/s, α = 20°: about 2 s of CPU.
  WorkPrecisionGridOptions o;
  o.spins_rev_s = {0, 40};
  o.attack_angles_deg = {20};
  o.adaptive_rtol = {1e-5, 1e-8};
  o.fixed_schemes = {Scheme::rk4};
  o.dt_s = {1e-3};
  o.cvode_rtol = {1e-8};
  o.budget_rhs_per_frame = {8, 1000000};
  o.workers = 2;
  const WorkPrecisionGridResult r = run_work_precision_grid(convergence_throw(), o);
  BOOST_TEST_REQUIRE(r.throws.size() == 2u);
  BOOST_TEST(r.throws[1].spin_rev_s == 40.0);
  int kept = 0;
  for (const GridThrow& t : r.throws) {
    BOOST_TEST(t.set_aside == !t.set_aside_reason.empty());
    BOOST_TEST(t.set_aside == (t.truth_bounces != t.check_bounces), t.label << ": " << t.set_aside_reason);
    kept += t.set_aside ? 0 : 1;
  }
  BOOST_TEST(kept + r.chaotic + r.truth_failed == 2);
  BOOST_TEST_REQUIRE(kept >= 1);  // the convergence throw's count is not chaotic at these tolerances
  // two bs32 tolerances, two budgets, one rk4 step, one CVODE rtol
  BOOST_TEST(r.runs.size() == std::size_t(kept) * 6);
  BOOST_TEST_REQUIRE(r.summaries.size() == 6u);
  for (const GridSummary& s : r.summaries) {
    BOOST_TEST(s.n == kept, s.family);
    BOOST_TEST(s.agreeing + s.failed <= s.n);
    BOOST_TEST(s.agreement.low <= s.agreement.estimate);
    BOOST_TEST(s.agreement.estimate <= s.agreement.high);
  }
  const GridSummary& cvode = r.summaries.back();
  BOOST_TEST(cvode.family == cvode_family_name(ReferenceMethod::bdf));
  BOOST_TEST(cvode.agreeing == kept);
  BOOST_TEST(cvode.timed == kept);
  BOOST_TEST(cvode.max_contact_time_error_s <= kTightCvodeTime_s);
  BOOST_TEST(cvode.failed == 0);
  // The choice names the adaptive family and states the default beside it.
  BOOST_TEST(r.adaptive_family == adaptive_family_name(Scheme::bs32));
  BOOST_TEST(r.choice.default_tolerance == kDefaultAdaptiveTolerance);
  BOOST_TEST(r.choice.tolerances.size() == 2u);
  // The budget (oracle: the budget itself): at 8 right-hand sides per 1/90 s frame a contact needs
  // more, so steps are forced and accepted over the tolerance (ratio > 1); at a million per frame
  // none is, and every accepted step passed the error test (ratio ≤ 1).
  BOOST_TEST(r.budget_family == budget_family_name(Scheme::bs32, o.budget_frame_dt_s));
  for (const GridSummary& s : r.summaries) {
    if (s.family != r.budget_family) continue;
    if (s.setting == 8) {
      BOOST_TEST(s.forced_step_fraction > 0);
      BOOST_TEST(s.max_error_ratio > 1);
    } else {
      BOOST_TEST(s.forced_step_fraction == 0);
      BOOST_TEST(s.max_error_ratio <= 1);
    }
  }
  BOOST_TEST((r.budget_choice.budgets == std::vector<double>{1000000, 8}));
  // The findings hold a row per family and setting, the families by name, the default beside the choice.
  const Record f = work_precision_grid_findings(r, o);
  BOOST_TEST(f.table("summary").rows() == r.summaries.size());
  BOOST_TEST(f.strings("families").size() == 4u);
  BOOST_TEST(f.at("budget_choice").table("per_budget").rows() == 2u);
  BOOST_TEST(f.number("kept") == kept);
  BOOST_TEST(f.at("default_choice").number("default_tolerance") == kDefaultAdaptiveTolerance);
  for (const GridSummary& s : r.summaries)
    BOOST_TEST_MESSAGE(s.family << " at " << s.setting << ": " << s.agreeing << "/" << s.n << ", median time error "
                                << s.median_contact_time_error_s << " s, " << s.mean_rhs_evaluations << " RHS");
  BOOST_TEST_MESSAGE(r.choice.reason);
}

BOOST_AUTO_TEST_CASE(a_paper_convention_base_throw_is_refused) {
  // Oracle: the grid's contract (work_precision_grid.hpp): it chooses the default for throws in the
  // physical convention, so a base throw in another is an error, not a silent change of convention.
  WorkPrecisionGridOptions o;
  BOOST_CHECK_THROW(run_work_precision_grid(with_convention(convergence_throw(), Convention::paper), o),
                    std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
