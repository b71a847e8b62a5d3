// The restart strategies' stored verdict (restart_findings, rule restart_strategy) against the
// work-precision study's own choice (RestartVerdict).
#include <boost/test/unit_test.hpp>

#include "verification/stones/convergence_throw.hpp"
#include "verification/stones/stone_studies.hpp"
#include "verification/study/verdict_rules.hpp"

namespace stoneskip {
namespace {

// The convergence throw up to the end of its first contact (a bounce, with 40 rev/s of spin).
ThrowProblem short_throw() {
  ThrowProblem p = convergence_throw();
  p.reference.t_max_s = 0.12;
  p.realtime.t_max_s = 0.12;
  return p;
}

BOOST_AUTO_TEST_SUITE(work_precision_findings)

BOOST_AUTO_TEST_CASE(the_stored_restart_verdict_names_the_studys_choice) {
  // Oracle: the study's RestartVerdict (work_precision.cpp), decided independently of the rule: the
  // stored phrase names the same strategy, its inputs decide it again, and the per-strategy totals
  // are the sums of the summaries.
  WorkPrecisionOptions o;
  o.realtime.clear();
  o.dt_s.clear();
  o.methods = {ReferenceMethod::bdf};
  o.restarts = {RestartStrategy::every_event, RestartStrategy::at_jumps, RestartStrategy::never};
  o.rtol = {1e-6, 1e-8};
  o.repeats = 1;
  o.workers = 1;
  const WorkPrecisionResult wp = run_work_precision({short_throw()}, o);
  const Record r = restart_findings(wp, o, RestartStrategy::at_jumps);
  BOOST_TEST_REQUIRE(wp.restart_verdict.found);
  BOOST_TEST(r.at("verdict").text("verdict") ==
             std::string(to_string(wp.restart_verdict.restart)) + " is the cheapest strategy that keeps the contact times");
  BOOST_TEST(r.text("study_choice") == to_string(wp.restart_verdict.restart));
  BOOST_TEST(contradicted_verdicts(r).empty());
  for (RestartStrategy s : o.restarts) {
    double rhs = 0;
    for (const RestartSummary& x : wp.restarts)
      if (x.restart == s) rhs += double(x.rhs_evaluations);
    BOOST_TEST(r.at(to_string(s)).number("rhs_evaluations") == rhs);
  }
  BOOST_TEST(r.table("summaries").rows() == wp.restarts.size());
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
