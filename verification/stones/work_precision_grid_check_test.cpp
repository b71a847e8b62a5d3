// The work-precision grid's record checked as `report render` reads it back
// (work_precision_grid_check.hpp): a record made by the study's own findings from a hand-built grid
// passes, and each edit of a value that follows from others is refused, naming that value.
#include "verification/stones/work_precision_grid_check.hpp"

#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

#include "verification/stones/work_precision_grid.hpp"

namespace stoneskip {
namespace {

GridRun run(const std::string& family, double setting, const std::string& label, bool ok, int bounces,
            double time_error_s, long rhs, double cpu_s) {
  GridRun r;
  r.family = family;
  r.setting = setting;
  r.throw_label = label;
  r.ok = ok;
  r.problem = ok ? "" : "step size underflow";
  r.bounces = bounces;
  r.truth_bounces = 4;
  r.same_count = ok && bounces == 4;
  r.same_contacts = ok && !std::isnan(time_error_s);
  r.contact_time_error_s = time_error_s;
  r.rhs_evaluations = rhs;
  r.cpu_s = cpu_s;
  r.steps = rhs / 3;
  return r;
}

// A 2 × 2 grid, the last throw set aside as chaotic, three kept; bs32 at two tolerances (the looser
// one misses a count), a frame budget at two sizes (the smaller forces steps and fails once), rk4
// at one step (one failure). The summaries and both choices come from the study's own functions.
struct HandGrid {
  WorkPrecisionGridOptions o;
  WorkPrecisionGridResult r;
  Record findings;

  HandGrid() {
    o.spins_rev_s = {0, 40};
    o.attack_angles_deg = {10, 20};
    o.adaptive_rtol = {1e-6, 1e-8};
    o.fixed_schemes = {Scheme::rk4};
    o.dt_s = {1e-3};
    o.cvode_rtol = {};
    o.budget_rhs_per_frame = {64, 1024};
    r.base_label = "hand-built";
    for (double spin : o.spins_rev_s)
      for (double attack : o.attack_angles_deg) {
        GridThrow t;
        t.spin_rev_s = spin;
        t.attack_angle_deg = attack;
        t.label = std::to_string(int(spin)) + " rev/s, " + std::to_string(int(attack)) + "°";
        t.truth_bounces = t.check_bounces = 4;
        r.throws.push_back(t);
      }
    r.throws.back().check_bounces = 5;
    r.throws.back().set_aside = true;
    r.throws.back().set_aside_reason = "chaotic: 4 and 5 bounces";
    r.chaotic = 1;
    r.adaptive_family = adaptive_family_name(Scheme::bs32);
    r.budget_family = budget_family_name(Scheme::bs32, o.budget_frame_dt_s);
    const std::string rk4 = fixed_family_name(Scheme::rk4, o.contact_ratio);
    const std::string a = r.adaptive_family, b = r.budget_family;
    r.runs = {run(a, 1e-6, "t1", true, 4, 2e-5, 3000, 0.003),   run(a, 1e-6, "t2", true, 3, NAN, 3300, 0.0033),
              run(a, 1e-6, "t3", true, 4, 6e-5, 2900, 0.0029),  run(a, 1e-8, "t1", true, 4, 1e-6, 9000, 0.009),
              run(a, 1e-8, "t2", true, 4, 2e-6, 9900, 0.0099),  run(a, 1e-8, "t3", true, 4, 4e-7, 8700, 0.0087),
              run(b, 64, "t1", false, 0, NAN, 700, 0.0007),     run(b, 64, "t2", true, 4, 3e-4, 800, 0.0008),
              run(b, 64, "t3", true, 4, 1e-4, 750, 0.00075),    run(b, 1024, "t1", true, 4, 1e-6, 9000, 0.009),
              run(b, 1024, "t2", true, 4, 2e-6, 9900, 0.0099),  run(b, 1024, "t3", true, 4, 4e-7, 8700, 0.0087),
              run(rk4, 1e-3, "t1", true, 4, 3e-5, 20000, 0.02), run(rk4, 1e-3, "t2", true, 4, NAN, 21000, 0.021),
              run(rk4, 1e-3, "t3", false, 0, NAN, 500, 0.0005)};
    for (GridRun& g : r.runs)
      if (g.family == b && g.setting == 64) {
        g.forced_steps = g.steps / 4;
        g.max_error_ratio = 7.5;
      }
    r.summaries = summarise_grid_runs(r.runs);
    GridDefaultRule rule;
    rule.family = a;
    rule.agreement_target = o.agreement_target;
    rule.bound = o.agreement_bound;
    rule.contact_time_threshold_s = o.contact_time_threshold_s;
    r.choice = choose_grid_default(r.summaries, rule, 1e-9);
    rule.family = b;
    r.budget_choice = choose_grid_budget(r.summaries, rule);
    findings = work_precision_grid_findings(r, o);
  }
};

// The refusal's message, or "" when the record passes.
std::string refusal(const Record& g) {
  try {
    check_work_precision_grid_record(g);
  } catch (const RecordError& e) {
    return e.what();
  }
  return "";
}

void set_cell(Record& parent, const std::string& table, std::size_t row, const std::string& column, double value) {
  Table t = parent.table(table);
  const std::size_t c = std::find(t.columns.begin(), t.columns.end(), column) - t.columns.begin();
  t.values.at(row * t.columns.size() + c) = value;
  parent.set_table(table, t);
}

double cell(const Record& parent, const std::string& table, std::size_t row, const std::string& column) {
  return parent.table(table).column(column).at(row);
}

BOOST_AUTO_TEST_SUITE(work_precision_grid_check)

BOOST_AUTO_TEST_CASE(the_studys_own_record_passes_and_its_choices_are_the_hand_worked_ones) {
  // Oracle: the record is made by the functions the check derives its values with, so it must pass;
  // and the grid was built so that its choices are known by hand — bs32 keeps every count only at
  // 1e-8 (1e-6 misses t2: 2 of 3, below 0.98), so the grid supports 1e-8, looser than the cases'
  // 1e-9 given here; the budget 64 fails on t1, so 1024 is the smallest that meets the rule.
  const HandGrid h;
  BOOST_TEST(refusal(h.findings) == "");
  BOOST_TEST(h.r.choice.found);
  BOOST_TEST(h.r.choice.tolerance == 1e-8);
  BOOST_TEST(h.findings.at("default_choice").text("beside_default") == "default_tighter");
  BOOST_TEST(h.r.budget_choice.rhs_per_frame == 1024.0);
  BOOST_TEST(h.findings.number("kept") == 3.0);
  BOOST_TEST(h.findings.strings("failures").size() == 2u);
  BOOST_TEST(h.findings.strings("adaptive_disagreements").size() == 1u);
}

BOOST_AUTO_TEST_CASE(each_value_that_follows_from_others_is_refused_when_edited_naming_it) {
  // Oracle: each edit below changes one stored value away from what the other stored values imply
  // (an interval, a count, a rule's choice, its reason, a tally, a per-budget bound); the check must
  // refuse every one, and its message must name the value edited.
  struct Edit {
    std::string what;
    std::function<void(Record&)> apply;
    std::string named;  // a part of the message
  };
  const std::vector<Edit> edits{
      {"a Wilson bound", [](Record& g) { set_cell(g, "summary", 0, "wilson_lo", cell(g, "summary", 0, "wilson_lo") + 0.01); },
       "summary row 1 wilson_lo"},
      {"a count of agreeing throws", [](Record& g) { set_cell(g, "summary", 0, "agreeing", 3); }, "summary row 1 agreement"},
      {"a count made fractional", [](Record& g) { set_cell(g, "summary", 1, "n", 2.5); }, "summary row 2 n is 2.5, not a count"},
      {"n beyond the kept throws", [](Record& g) { set_cell(g, "summary", 1, "n", 4); }, "every family runs on every kept throw"},
      {"a family index beyond the list", [](Record& g) { set_cell(g, "summary", 2, "family", 9); }, "beyond the 3 families"},
      {"a median above the largest", [](Record& g) { set_cell(g, "summary", 1, "median_contact_time_error_s", 1.0); },
       "summary row 2 median contact-time error"},
      {"a median where no contact list matched",
       [](Record& g) {
         Table t = g.table("summary");  // the rk4 row has two contact lists matched; say none
         set_cell(g, "summary", t.rows() - 1, "timed", 0);
       },
       "no contact list matched"},
      {"negative work", [](Record& g) { set_cell(g, "summary", 0, "mean_rhs_evaluations", -1); }, "right-hand sides per throw"},
      {"a forced share above 1", [](Record& g) { set_cell(g, "summary", 2, "forced_step_fraction", 1.5); }, "forced-step share"},
      {"a column missing",
       [](Record& g) {
         Table t = g.table("summary");
         t.columns.back() = "renamed";
         g.set_table("summary", t);
       },
       "has no column 'max_error_ratio'"},
      {"the tolerance chosen", [](Record& g) { g.child("default_choice").set("tolerance", 1e-6); }, "/default_choice: tolerance"},
      {"the choice's found flag", [](Record& g) { g.child("default_choice").set("found", false); }, "/default_choice: found"},
      {"the rule's target (the choice no longer follows)",
       [](Record& g) { g.child("default_choice").set("agreement_target", 0.5); }, "/default_choice: tolerance is 1e-08 but "},
      {"the reason's text", [](Record& g) { g.child("default_choice").set("reason", "rule: trust me"); }, "/default_choice: reason"},
      {"the phrase beside the default",
       [](Record& g) { g.child("default_choice").set("beside_default_phrase", "the grid agrees with the default"); },
       "beside_default_phrase"},
      {"an unknown bound", [](Record& g) { g.child("default_choice").set("agreement_bound", "upper"); }, "agreement_bound 'upper'"},
      {"a per-tolerance verdict", [](Record& g) { set_cell(g.child("default_choice"), "per_tolerance", 1, "meets", 1); },
       "per_tolerance row 2 meets"},
      {"the budget chosen", [](Record& g) { g.child("budget_choice").set("rhs_per_frame", 64.0); }, "/budget_choice: rhs_per_frame"},
      {"a frame's CPU share", [](Record& g) { set_cell(g.child("budget_choice"), "per_budget", 1, "frame_fraction", 0.001); },
       "per_budget row 2 frame_fraction"},
      {"the kept tally", [](Record& g) { g.set("kept", 4); }, "kept is 4 but 3"},
      {"a set-aside flag", [](Record& g) { set_cell(g, "throws", 0, "set_aside", 0.5); }, "throws row 1 set_aside is 0.5"},
      {"a failure dropped from the list", [](Record& g) { g.set_strings("failures", {"rk4: only one"}); }, "failures list's length"},
      {"a disagreement dropped from the list", [](Record& g) { g.set_strings("adaptive_disagreements", {}); },
       "adaptive_disagreements list's length"},
  };
  const HandGrid h;
  for (const Edit& e : edits) {
    Record g = h.findings;
    e.apply(g);
    const std::string m = refusal(g);
    BOOST_TEST(m.find(e.named) != std::string::npos, e.what << ": '" << m << "' does not name '" << e.named << "'");
  }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
}  // namespace stoneskip
