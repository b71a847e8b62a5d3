#include "verification/stones/work_precision_grid_check.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "verification/stones/work_precision_grid_stats.hpp"

namespace stoneskip {

namespace {

// Equal to round-off (see the header), NaN equal to NaN.
bool same(double a, double b) {
  return a == b || (std::isnan(a) && std::isnan(b)) || std::abs(a - b) <= 1e-12 * std::max(std::abs(a), std::abs(b));
}

std::string text_of(double x) {
  std::ostringstream m;
  m.precision(17);
  m << x;
  return m.str();
}

// The checks of one record, each failure naming the record's path.
class Checker {
 public:
  explicit Checker(const Record& r) : r_(r) {}

  [[noreturn]] void fail(const std::string& what) const { throw RecordError(r_.path() + ": " + what); }
  void expect(const std::string& what, double stored, double expected) const {
    if (!same(stored, expected))
      fail(what + " is " + text_of(stored) + " but " + text_of(expected) + " follows from the stored data");
  }
  void expect_text(const std::string& what, const std::string& stored, const std::string& expected) const {
    if (stored != expected) fail(what + " is '" + stored + "' but '" + expected + "' follows from the stored data");
  }
  // A count: finite, whole and not negative.
  int count(const std::string& what, double x) const {
    if (!(std::isfinite(x) && x >= 0 && x == std::floor(x) && x <= 1e9)) fail(what + " is " + text_of(x) + ", not a count");
    return static_cast<int>(x);
  }
  void at_most(const std::string& what, double x, const std::string& bound_what, double bound) const {
    if (!(x <= bound)) fail(what + " (" + text_of(x) + ") exceeds " + bound_what + " (" + text_of(bound) + ")");
  }
  void non_negative(const std::string& what, double x) const {
    if (!(std::isfinite(x) && x >= 0)) fail(what + " is " + text_of(x) + ", not a finite value ≥ 0");
  }
  std::vector<double> column(const Table& t, const std::string& table, const std::string& name) const {
    if (!t.has_column(name))
      fail("table '" + table + "' has no column '" + name + "'");
    return t.column(name);
  }

 private:
  const Record& r_;
};

// The stored summary table as the aggregates the rules take (failures' texts are not needed by
// the rules), each row checked against what its counts imply.
std::vector<GridSummary> stored_summaries(const Record& g, const Checker& ck, int kept) {
  const auto& families = g.strings("families");
  const Table& t = g.table("summary");
  auto col = [&](const char* name) { return ck.column(t, "summary", name); };
  const auto family = col("family"), setting = col("setting"), agreeing = col("agreeing"), n = col("n"),
             agreement = col("agreement"), lo = col("wilson_lo"), hi = col("wilson_hi"), timed = col("timed"),
             median = col("median_contact_time_error_s"), largest = col("max_contact_time_error_s"),
             rhs = col("mean_rhs_evaluations"), cpu = col("mean_cpu_s"), failed = col("failed"),
             forced = col("forced_step_fraction"), ratio = col("max_error_ratio");
  std::vector<GridSummary> out;
  for (std::size_t i = 0; i < t.rows(); ++i) {
    const std::string row = "summary row " + std::to_string(i + 1);
    GridSummary s;
    const int f = ck.count(row + " family", family[i]);
    if (f >= static_cast<int>(families.size()))
      ck.fail(row + " family is " + std::to_string(f) + ", beyond the " + std::to_string(families.size()) + " families");
    s.family = families[static_cast<std::size_t>(f)];
    s.setting = setting[i];
    if (!(std::isfinite(s.setting) && s.setting > 0)) ck.fail(row + " setting is " + text_of(s.setting) + ", not > 0");
    s.n = ck.count(row + " n", n[i]);
    s.agreeing = ck.count(row + " agreeing", agreeing[i]);
    s.timed = ck.count(row + " timed", timed[i]);
    s.failed = ck.count(row + " failed", failed[i]);
    ck.expect(row + " n (every family runs on every kept throw)", s.n, kept);
    ck.at_most(row + " agreeing + failed (a failed run does not agree)", s.agreeing + s.failed, "n", s.n);
    ck.at_most(row + " timed (a failed run has no contact list)", s.timed + s.failed, "n", s.n);
    s.agreement = wilson_interval(s.agreeing, s.n);
    ck.expect(row + " agreement", agreement[i], s.agreement.estimate);
    ck.expect(row + " wilson_lo", lo[i], s.agreement.low);
    ck.expect(row + " wilson_hi", hi[i], s.agreement.high);
    s.median_contact_time_error_s = median[i];
    s.max_contact_time_error_s = largest[i];
    if (s.timed == 0) {
      ck.expect(row + " median contact-time error (no contact list matched)", median[i], NAN);
      ck.expect(row + " largest contact-time error (no contact list matched)", largest[i], NAN);
    } else {
      ck.non_negative(row + " median contact-time error", median[i]);
      ck.at_most(row + " median contact-time error", median[i], "the largest", largest[i]);
    }
    s.mean_rhs_evaluations = rhs[i];
    s.mean_cpu_s = cpu[i];
    ck.non_negative(row + " right-hand sides per throw", rhs[i]);
    ck.non_negative(row + " CPU per throw", cpu[i]);
    s.forced_step_fraction = forced[i];
    if (!(forced[i] >= 0 && forced[i] <= 1)) ck.fail(row + " forced-step share is " + text_of(forced[i]) + ", not in [0, 1]");
    s.max_error_ratio = ratio[i];
    ck.non_negative(row + " largest error ratio", ratio[i]);
    out.push_back(s);
  }
  return out;
}

// The throws table against the tallies and the set-aside list; returns the kept count.
int check_throws(const Record& g, const Checker& ck) {
  const Table& t = g.table("throws");
  const auto aside = ck.column(t, "throws", "set_aside");
  const int spins = static_cast<int>(g.table("spins").rows()), angles = static_cast<int>(g.table("attack_angles").rows());
  ck.expect("throw_count (spins × attack angles)", g.number("throw_count"), double(spins) * angles);
  ck.expect("the throws table's rows", double(t.rows()), g.number("throw_count"));
  int set_aside = 0;
  for (std::size_t i = 0; i < aside.size(); ++i) {
    if (aside[i] != 0 && aside[i] != 1) ck.fail("throws row " + std::to_string(i + 1) + " set_aside is " + text_of(aside[i]) + ", not 0 or 1");
    set_aside += aside[i] != 0;
  }
  const int kept = static_cast<int>(t.rows()) - set_aside;
  ck.expect("kept", g.number("kept"), kept);
  ck.expect("chaotic + truth_failed (the throws set aside)", g.number("chaotic") + g.number("truth_failed"), set_aside);
  ck.count("chaotic", g.number("chaotic"));
  ck.count("truth_failed", g.number("truth_failed"));
  ck.expect("the set_aside list's length", double(g.strings("set_aside").size()), set_aside);
  return kept;
}

GridDefaultRule stored_rule(const Record& choice, const Checker& ck) {
  GridDefaultRule rule;
  rule.family = choice.text("family");
  rule.agreement_target = choice.number("agreement_target");
  if (!parse_agreement_bound(choice.text("agreement_bound"), rule.bound))
    ck.fail("agreement_bound '" + choice.text("agreement_bound") + "' is not point_estimate or wilson_lower");
  rule.contact_time_threshold_s = choice.number("contact_time_threshold_s");
  return rule;
}

// The values a choice prints about the summary it picked.
void expect_at(const Checker& ck, const Record& stored, const GridSummary& at) {
  ck.expect("agreeing", stored.number("agreeing"), at.agreeing);
  ck.expect("n", stored.number("n"), at.n);
  ck.expect("wilson_lo", stored.number("wilson_lo"), at.agreement.low);
  ck.expect("wilson_hi", stored.number("wilson_hi"), at.agreement.high);
  ck.expect("median_contact_time_error_s", stored.number("median_contact_time_error_s"), at.median_contact_time_error_s);
}

void check_default_choice(const Record& ch, const std::vector<GridSummary>& summaries) {
  const Checker ck(ch);
  const GridDefaultRule rule = stored_rule(ch, ck);
  const GridDefaultChoice c = choose_grid_default(summaries, rule, ch.number("default_tolerance"));
  ck.expect("found", ch.number("found"), c.found ? 1 : 0);
  ck.expect("tolerance", ch.number("tolerance"), c.tolerance);
  ck.expect_text("beside_default", ch.text("beside_default"), to_string(c.agreement));
  ck.expect_text("beside_default_phrase", ch.text("beside_default_phrase"), phrase(c.agreement));
  expect_at(ck, ch, c.at);
  ck.expect("mean_rhs_evaluations", ch.number("mean_rhs_evaluations"), c.at.mean_rhs_evaluations);
  ck.expect("mean_cpu_s", ch.number("mean_cpu_s"), c.at.mean_cpu_s);
  ck.expect("throws_to_show_target", ch.number("throws_to_show_target"), c.throws_to_show_target);
  ck.expect_text("reason", ch.text("reason"), c.reason);
  const Table& per = ch.table("per_tolerance");
  ck.expect("per_tolerance's rows", double(per.rows()), double(c.tolerances.size()));
  const auto tol = ck.column(per, "per_tolerance", "tolerance"), meets = ck.column(per, "per_tolerance", "meets");
  for (std::size_t i = 0; i < c.tolerances.size(); ++i) {
    ck.expect("per_tolerance row " + std::to_string(i + 1) + " tolerance", tol[i], c.tolerances[i]);
    ck.expect("per_tolerance row " + std::to_string(i + 1) + " meets", meets[i], c.meets[i] ? 1 : 0);
  }
}

void check_budget_choice(const Record& bc, const Record& default_choice, const std::vector<GridSummary>& summaries) {
  const Checker ck(bc);
  GridDefaultRule rule = stored_rule(default_choice, Checker(default_choice));  // the same rule, the budget's family
  rule.family = bc.text("family");
  const GridBudgetChoice c = choose_grid_budget(summaries, rule);
  ck.expect("found", bc.number("found"), c.found ? 1 : 0);
  ck.expect("rhs_per_frame", bc.number("rhs_per_frame"), c.rhs_per_frame);
  expect_at(ck, bc, c.at);
  ck.expect_text("reason", bc.text("reason"), c.reason);
  const double frame_s = bc.number("frame_dt_s");
  if (!(std::isfinite(frame_s) && frame_s > 0)) ck.fail("frame_dt_s is " + text_of(frame_s) + ", not > 0");
  const Table& per = bc.table("per_budget");
  ck.expect("per_budget's rows", double(per.rows()), double(c.budgets.size()));
  auto col = [&](const char* name) { return ck.column(per, "per_budget", name); };
  const auto budget = col("rhs_per_frame"), meets = col("meets"), per_rhs = col("cpu_per_rhs_s"),
             bound = col("cpu_per_frame_bound_s"), share = col("frame_fraction"), forced = col("forced_step_fraction"),
             ratio = col("max_error_ratio");
  for (std::size_t i = 0; i < c.budgets.size(); ++i) {
    const std::string row = "per_budget row " + std::to_string(i + 1);
    const auto s = std::find_if(summaries.begin(), summaries.end(),
                                [&](const GridSummary& x) { return x.family == rule.family && x.setting == c.budgets[i]; });
    const double rhs_cpu = s->mean_rhs_evaluations > 0 ? s->mean_cpu_s / s->mean_rhs_evaluations : 0;
    ck.expect(row + " rhs_per_frame", budget[i], c.budgets[i]);
    ck.expect(row + " meets", meets[i], c.meets[i] ? 1 : 0);
    ck.expect(row + " cpu_per_rhs_s", per_rhs[i], rhs_cpu);
    ck.expect(row + " cpu_per_frame_bound_s", bound[i], s->setting * rhs_cpu);
    ck.expect(row + " frame_fraction", share[i], s->setting * rhs_cpu / frame_s);
    ck.expect(row + " forced_step_fraction", forced[i], s->forced_step_fraction);
    ck.expect(row + " max_error_ratio", ratio[i], s->max_error_ratio);
  }
}

}  // namespace

void check_work_precision_grid_record(const Record& g) {
  const Checker ck(g);
  const int kept = check_throws(g, ck);
  const std::vector<GridSummary> summaries = stored_summaries(g, ck, kept);
  // Every failure is listed, and every finished run of the adaptive family with another count.
  int failed = 0, adaptive_missed = 0;
  const std::string adaptive = g.at("default_choice").text("family");
  for (const GridSummary& s : summaries) {
    failed += s.failed;
    if (s.family == adaptive) adaptive_missed += s.n - s.agreeing - s.failed;
  }
  ck.expect("the failures list's length (the summary's failed runs)", double(g.strings("failures").size()), failed);
  ck.expect("the adaptive_disagreements list's length (its finished runs with another count)",
            double(g.strings("adaptive_disagreements").size()), adaptive_missed);
  check_default_choice(g.at("default_choice"), summaries);
  if (g.flag("budget_run")) check_budget_choice(g.at("budget_choice"), g.at("default_choice"), summaries);
}

}  // namespace stoneskip
