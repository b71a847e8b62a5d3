#include "verification/captures/nudged_agreement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "solvers/realtime/clocks.hpp"
#include "solvers/reference/cvode_stone.hpp"
#include "verification/study/verdict_rules.hpp"

namespace stoneskip {

bool NudgedAgreementOptions::valid(std::string* why) const {
  auto fail = [&](const std::string& w) {
    if (why) *why = w;
    return false;
  };
  if (members < 0 || members % 2 != 0 || members > 1000) return fail("the count ensembles' members must be even, in [0, 1000]");
  if (!(perturbation_smallest > 0) || !(perturbation_largest >= perturbation_smallest) || !(perturbation_largest < 1))
    return fail("the count ensembles' perturbations must satisfy 0 < smallest <= largest < 1");
  return true;
}

NudgedAgreement nudged_agreement(const Stone& stone, const Environment& env, const RigidState& initial,
                                 const RealtimeOptions& realtime, const ReferenceOptions& reference,
                                 const NudgedAgreementOptions& o) {
  NudgedAgreement out;
  if (o.members == 0) return out;
  const CpuTimer cpu;
  const WallTimer wall;
  out.factors = perturbation_factors(o.members, o.perturbation_smallest, o.perturbation_largest);
  RealtimeOptions ro = realtime;
  ro.record_trajectory = false;
  ReferenceOptions co = reference;
  co.record_trajectory = false;
  std::vector<double> realtime_ran, reference_ran;
  for (double factor : out.factors) {
    RigidState s = initial;
    s.velocity_m_s *= factor;  // the speed, relatively; direction, attitude and spin kept
    const ThrowResult a = run_realtime(stone, env, s, ro);
    const ThrowResult b = run_reference(stone, env, s, co);
    // A failed run's bounces until the failure are not its count.
    out.realtime.push_back(a.outcome == Outcome::failed ? -1.0 : double(a.bounces));
    out.reference.push_back(b.outcome == Outcome::failed ? -1.0 : double(b.bounces));
    if (a.outcome == Outcome::failed) ++out.realtime_failed;
    else realtime_ran.push_back(a.bounces);
    if (b.outcome == Outcome::failed) ++out.reference_failed;
    else reference_ran.push_back(b.bounces);
  }
  out.difference = welch_difference(realtime_ran, reference_ran);
  out.cpu_s = cpu.seconds();
  out.wall_s = wall.seconds();
  return out;
}

void decide_nudged_agreement(Record& r, const std::string& key, const NudgedAgreement& a, const std::string& single,
                             const std::string& realtime_name, const std::string& reference_name) {
  const MeanDifference& d = a.difference;
  r.set("count_ensemble_members", a.factors.size());
  r.set("count_ensemble_cpu_s", a.cpu_s).set("count_ensemble_wall_s", a.wall_s);
  Table e{{"factor", "realtime_bounces", "reference_bounces"}, {}};
  for (std::size_t k = 0; k < a.factors.size(); ++k) e.add_row({a.factors[k], a.realtime[k], a.reference[k]});
  r.set_table("count_ensemble", e);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Record in;
  in.set("valid", d.valid);
  in.set("difference_low", d.valid ? d.low : nan).set("difference_high", d.valid ? d.high : nan);
  in.set("count_spread", d.valid ? d.sd_a + d.sd_b : nan);
  in.set("exact_p", d.exact_p).set("alpha", d.alpha);
  in.set("realtime_failed", a.realtime_failed).set("reference_failed", a.reference_failed);
  std::string reason = single;
  if (a.factors.empty()) {
    reason += "; no ensembles were run, and a chaotic count is not judged on single runs";
  } else {
    double smallest = 1, largest = 0;  // the relative perturbations |factor − 1|
    for (double f : a.factors) {
      smallest = std::min(smallest, std::abs(f - 1));
      largest = std::max(largest, std::abs(f - 1));
    }
    char b[500];
    std::snprintf(b, sizeof b,
                  "; over %zu throws each (speed × 1 ± %.3g … %.3g) %s %.3g ± %.2g, %s %.3g ± %.2g bounces (mean ± sd; "
                  "%d and %d failed); difference %.3g, 95 %% interval [%.3g, %.3g]%s",
                  a.factors.size(), smallest, largest, realtime_name.c_str(), d.mean_a, d.sd_a, reference_name.c_str(),
                  d.mean_b, d.sd_b, a.realtime_failed, a.reference_failed, d.difference, d.low, d.high,
                  std::isnan(d.exact_p) ? "" : " (no spread: the exact permutation test decides)");
    reason += b;
  }
  decide_verdict(r, key, "ensemble_bounce_agreement", in, reason);
}

}  // namespace stoneskip
