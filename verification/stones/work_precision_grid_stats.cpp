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
  std::vector<long> steps, forced;
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
      steps.push_back(0);
      forced.push_back(0);
    }
    GridSummary& s = out[i];
    ++s.n;
    rhs[i].push_back(double(r.rhs_evaluations));
    cpu[i].push_back(r.cpu_s);
    steps[i] += r.steps;
    forced[i] += r.forced_steps;
    s.max_error_ratio = std::max(s.max_error_ratio, r.max_error_ratio);
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
    s.forced_step_fraction = steps[i] > 0 ? double(forced[i]) / steps[i] : 0;
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

namespace {

// The rule walked over one family's summaries from the most accurate setting on (ascending
// settings, or descending with `descending`): the last setting met with every more accurate one
// met too, each setting's verdict, and in words the first one missed.
struct RuleWalk {
  bool found = false;
  GridSummary at;
  std::vector<double> settings;
  std::vector<bool> meets;
  std::string first_miss;  // "at … the agreement is … and the median contact-time error … s"
  bool ran = false;        // the family has summaries
};

RuleWalk walk_rule(const std::vector<GridSummary>& summaries, const GridDefaultRule& rule, bool descending,
                   const std::string& setting_unit, int setting_digits) {
  RuleWalk w;
  std::vector<const GridSummary*> fam;
  for (const GridSummary& s : summaries)
    if (s.family == rule.family) fam.push_back(&s);
  std::sort(fam.begin(), fam.end(), [descending](const GridSummary* a, const GridSummary* b) {
    return descending ? a->setting > b->setting : a->setting < b->setting;
  });
  w.ran = !fam.empty();
  bool all_so_far = true;
  for (const GridSummary* s : fam) {
    const bool m = meets(*s, rule);
    w.settings.push_back(s->setting);
    w.meets.push_back(m);
    if (!m && w.first_miss.empty())
      w.first_miss = "at " + num(s->setting, setting_digits) + setting_unit + " the agreement is " + std::to_string(s->agreeing) +
                     " of " + std::to_string(s->n) + " (" + (rule.bound == AgreementBound::wilson_lower ? "Wilson lower bound " : "") +
                     num(rule.bound == AgreementBound::wilson_lower ? s->agreement.low : s->agreement.estimate) +
                     ") and the median contact-time error " + num(s->median_contact_time_error_s, 2) + " s";
    all_so_far = all_so_far && m;
    if (all_so_far) {
      w.found = true;
      w.at = *s;
    }
  }
  return w;
}

// "rule: the <which> at which, and at every <more accurate> one, … ; " and the finding.
std::string rule_reason(const GridDefaultRule& rule, const RuleWalk& w, const std::string& which,
                        const std::string& every, const std::string& met, const std::string& beyond,
                        const std::string& extreme, const std::string& setting_text) {
  const std::string by = rule.bound == AgreementBound::wilson_lower ? "the Wilson 95 % lower bound of the count agreement"
                                                                    : "the count agreement (point estimate)";
  std::string r = "rule: the " + which + " at which, and at every " + every + " one, " + by + " is at least " +
                  num(rule.agreement_target) + " and the median contact-time error is below " +
                  num(rule.contact_time_threshold_s, 2) + " s; ";
  if (!w.ran) return r + "the family " + rule.family + " was not run";
  if (!w.found) return r + "not met even at the " + extreme + ": " + w.first_miss;
  return r + met + " " + setting_text + " (" + std::to_string(w.at.agreeing) + " of " + std::to_string(w.at.n) +
         " throws agree, 95 % interval " + num(w.at.agreement.low) + "–" + num(w.at.agreement.high) +
         "; median contact-time error " + num(w.at.median_contact_time_error_s, 2) + " s)" +
         (w.first_miss.empty() ? "" : "; " + beyond + ": " + w.first_miss);
}

}  // namespace

GridDefaultChoice choose_grid_default(const std::vector<GridSummary>& summaries, const GridDefaultRule& rule,
                                      double default_tolerance) {
  GridDefaultChoice c;
  c.default_tolerance = default_tolerance;
  c.throws_to_show_target = rule.agreement_target < 1 ? throws_to_show(rule.agreement_target) : 0;
  const RuleWalk w = walk_rule(summaries, rule, false, "", 2);  // tightest tolerance first
  c.found = w.found;
  c.tolerance = w.found ? w.at.setting : 0;
  if (w.found) c.at = w.at;
  c.tolerances = w.settings;
  c.meets = w.meets;
  if (!c.found)
    c.agreement = DefaultAgreement::no_choice;
  else if (c.tolerance == default_tolerance)
    c.agreement = DefaultAgreement::same;
  else
    c.agreement = default_tolerance < c.tolerance ? DefaultAgreement::default_tighter : DefaultAgreement::default_looser;
  c.reason = rule_reason(rule, w, "loosest tolerance", "tighter", "met up to", "not beyond", "tightest tolerance",
                         num(c.tolerance, 2));
  return c;
}

GridBudgetChoice choose_grid_budget(const std::vector<GridSummary>& summaries, const GridDefaultRule& rule) {
  GridBudgetChoice c;
  // Largest budget first: the most accurate, as the tightest tolerance is for the default's rule.
  const RuleWalk w = walk_rule(summaries, rule, true, " right-hand sides per frame", 7);
  c.found = w.found;
  c.rhs_per_frame = w.found ? w.at.setting : 0;
  if (w.found) c.at = w.at;
  c.budgets = w.settings;
  c.meets = w.meets;
  c.reason = rule_reason(rule, w, "smallest budget", "larger", "met down to", "not below", "largest budget",
                         num(c.rhs_per_frame, 7) + " right-hand sides per frame");
  return c;
}

}  // namespace stoneskip
