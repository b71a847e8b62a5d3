#include "verification/stones/work_precision_grid_stats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "verification/study/words.hpp"

namespace stoneskip {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double median(std::vector<double> v) {
  if (v.empty()) return kNaN;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

bool meets(const GridSummary& s, const GridDefaultRule& rule) {
  const double a = rule.bound == AgreementBound::wilson_lower ? s.agreement.low : s.agreement.estimate;
  return s.n > 0 && a >= rule.agreement_target && s.median_contact_time_error_s < rule.contact_time_threshold_s;
}

}  // namespace

ProportionInterval wilson_interval(int k, int n, double z) {
  ProportionInterval p;
  if (n <= 0) {
    p.estimate = kNaN;
    return p;
  }
  // Wilson 1927; Newcombe 1998, Eq. for method 3: (2np + z² ± z √(z² + 4npq)) / (2(n + z²)).
  const double nn = n, kk = k, z2 = z * z;
  const double centre = kk + z2 / 2;
  const double half = z * std::sqrt(kk * (nn - kk) / nn + z2 / 4);
  p.estimate = kk / nn;
  p.low = std::max(0.0, (centre - half) / (nn + z2));
  p.high = std::min(1.0, (centre + half) / (nn + z2));
  return p;
}

int throws_to_show(double target, double z) {
  // All n agreeing: the lower bound is n / (n + z²) (k = n above).
  return static_cast<int>(std::ceil(target * z * z / (1 - target) - 1e-9));
}

std::vector<GridSummary> summarise_grid_runs(const std::vector<GridRun>& runs) {
  std::vector<GridSummary> out;
  std::vector<std::vector<double>> errors, rhs, cpu;
  for (const GridRun& r : runs) {
    std::size_t i = 0;
    while (i < out.size() && !(out[i].family == r.family && out[i].setting == r.setting)) ++i;
    if (i == out.size()) {
      out.push_back(GridSummary{});
      out.back().family = r.family;
      out.back().setting = r.setting;
      errors.emplace_back();
      rhs.emplace_back();
      cpu.emplace_back();
    }
    GridSummary& s = out[i];
    ++s.n;
    rhs[i].push_back(double(r.rhs_evaluations));
    cpu[i].push_back(r.cpu_s);
    if (!r.ok) {
      ++s.failed;
      s.failures.push_back(r.throw_label + ": " + r.problem);
      continue;
    }
    if (r.same_count) ++s.agreeing;
    if (r.same_contacts) errors[i].push_back(r.contact_time_error_s);
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    GridSummary& s = out[i];
    s.agreement = wilson_interval(s.agreeing, s.n);
    s.timed = static_cast<int>(errors[i].size());
    s.median_contact_time_error_s = median(errors[i]);
    s.max_contact_time_error_s = errors[i].empty() ? kNaN : *std::max_element(errors[i].begin(), errors[i].end());
    double sr = 0, sc = 0;
    for (double x : rhs[i]) sr += x;
    for (double x : cpu[i]) sc += x;
    s.mean_rhs_evaluations = sr / s.n;
    s.mean_cpu_s = sc / s.n;
  }
  return out;
}

const char* to_string(AgreementBound b) {
  switch (b) {
    case AgreementBound::point_estimate: return "point_estimate";
    case AgreementBound::wilson_lower: return "wilson_lower";
  }
  return "?";
}

bool parse_agreement_bound(const std::string& s, AgreementBound& out) {
  for (AgreementBound b : {AgreementBound::point_estimate, AgreementBound::wilson_lower})
    if (s == to_string(b)) {
      out = b;
      return true;
    }
  return false;
}

const char* to_string(DefaultAgreement a) {
  switch (a) {
    case DefaultAgreement::same: return "same";
    case DefaultAgreement::default_tighter: return "default_tighter";
    case DefaultAgreement::default_looser: return "default_looser";
    case DefaultAgreement::no_choice: return "no_choice";
  }
  return "?";
}

const char* phrase(DefaultAgreement a) {
  switch (a) {
    case DefaultAgreement::same: return "the grid agrees with the default";
    case DefaultAgreement::default_tighter: return "the default is tighter than the grid needs";
    case DefaultAgreement::default_looser: return "the default is looser than the grid supports";
    case DefaultAgreement::no_choice: return "the grid supports no tolerance run";
  }
  return "?";
}

GridDefaultChoice choose_grid_default(const std::vector<GridSummary>& summaries, const GridDefaultRule& rule,
                                      double default_tolerance) {
  GridDefaultChoice c;
  c.default_tolerance = default_tolerance;
  c.throws_to_show_target = rule.agreement_target < 1 ? throws_to_show(rule.agreement_target) : 0;
  std::vector<const GridSummary*> fam;
  for (const GridSummary& s : summaries)
    if (s.family == rule.family) fam.push_back(&s);
  std::sort(fam.begin(), fam.end(), [](const GridSummary* a, const GridSummary* b) { return a->setting < b->setting; });
  bool all_so_far = true;
  std::string first_miss;
  for (const GridSummary* s : fam) {
    const bool m = meets(*s, rule);
    c.tolerances.push_back(s->setting);
    c.meets.push_back(m);
    if (!m && first_miss.empty())
      first_miss = "at " + num(s->setting, 2) + " the agreement is " + std::to_string(s->agreeing) + " of " +
                   std::to_string(s->n) + " (" + (rule.bound == AgreementBound::wilson_lower ? "Wilson lower bound " : "") +
                   num(rule.bound == AgreementBound::wilson_lower ? s->agreement.low : s->agreement.estimate) +
                   ") and the median contact-time error " + num(s->median_contact_time_error_s, 2) + " s";
    all_so_far = all_so_far && m;
    if (all_so_far) {
      c.found = true;
      c.tolerance = s->setting;
      c.at = *s;
    }
  }
  if (!c.found)
    c.agreement = DefaultAgreement::no_choice;
  else if (c.tolerance == default_tolerance)
    c.agreement = DefaultAgreement::same;
  else
    c.agreement = default_tolerance < c.tolerance ? DefaultAgreement::default_tighter : DefaultAgreement::default_looser;
  const std::string by = rule.bound == AgreementBound::wilson_lower ? "the Wilson 95 % lower bound of the count agreement"
                                                                    : "the count agreement (point estimate)";
  c.reason = "rule: the loosest tolerance at which, and at every tighter one, " + by + " is at least " +
             num(rule.agreement_target) + " and the median contact-time error is below " +
             num(rule.contact_time_threshold_s, 2) + " s; ";
  if (fam.empty())
    c.reason += "the family " + rule.family + " was not run";
  else if (c.found)
    c.reason += "met up to " + num(c.tolerance, 2) + " (" + std::to_string(c.at.agreeing) + " of " + std::to_string(c.at.n) +
                " throws agree, 95 % interval " + num(c.at.agreement.low) + "–" + num(c.at.agreement.high) +
                "; median contact-time error " + num(c.at.median_contact_time_error_s, 2) + " s)" +
                (first_miss.empty() ? "" : "; not beyond: " + first_miss);
  else
    c.reason += "not met even at the tightest tolerance: " + first_miss;
  return c;
}

}  // namespace stoneskip
