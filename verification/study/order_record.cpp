#include "verification/study/order_record.hpp"

#include "verification/study/stored_values.hpp"
#include "verification/study/verdict_rules.hpp"
#include "verification/study/words.hpp"

namespace stoneskip {


Record& store_order_fit(Record& parent, const std::string& key, const OrderFit& fit, const OrderJudgement& j) {
  Record& r = parent.child(key);
  r.set("valid", fit.valid);
  r.set("order", fit.order);
  r.set("order_low", fit.order_low);
  r.set("order_high", fit.order_high);
  r.set("points", fit.points);
  r.set("r_squared", fit.r_squared);
  r.set("constant", fit.constant);
  if (!fit.problem.empty()) r.set("problem", fit.problem);
  r.set("failed_points", fit.failed_points);
  r.set("nonpositive_points", fit.nonpositive_points);
  if (fit.shape_tested) {  // whether one power describes the points (order_fit.hpp)
    r.set("shape_tested", true);
    r.set("curved", fit.curved);
    r.set("curvature_f", fit.curvature_f);
    r.set("curvature_f_critical", fit.curvature_f_critical);
    r.set("local_order_coarse", fit.local_order_coarse);
    r.set("local_order_fine", fit.local_order_fine);
  }
  r.set_table("pairwise", value_list(fit.pairwise, "order"));
  if (fit.f_critical > 0) {  // the correction term was tested (order_fit.hpp, OrderFitOptions)
    r.set("correction_tested", true);
    r.set("corrected", fit.corrected);
    r.set("f_statistic", fit.f_statistic);
    r.set("f_critical", fit.f_critical);
    if (fit.corrected) {
      r.set("correction", fit.correction);
      r.set("single_order", fit.single_order);
      r.set("single_low", fit.single_low);
      r.set("single_high", fit.single_high);
    }
  }
  Record in;
  in.set("valid", fit.valid);
  in.set("order", fit.order);
  in.set("order_low", fit.order_low);
  in.set("order_high", fit.order_high);
  in.set("points", fit.points);
  in.set("expected_order", j.expected_order);
  in.set("tolerance", j.tolerance);
  in.set("minimum_order", j.minimum_order);
  // The refinements at which the error grew (pairwise order ≤ 0): judge_order claims no order then.
  in.set("refinements", static_cast<long>(fit.pairwise.size()));
  in.set("growing_refinements", fit.growing_refinements());
  // Failed runs and a drifting local order: no order claimed either (records written before these
  // were inputs have none, and are judged as before).
  in.set("failed_points", fit.failed_points);
  in.set("corrected", fit.corrected);
  in.set("shape_tested", fit.shape_tested);
  in.set("curved", fit.curved);
  in.set("local_order_coarse", fit.local_order_coarse);
  in.set("local_order_fine", fit.local_order_fine);
  decide_verdict(r, "verdict", "order_fit", in, judge_order(fit, j).reason);
  return r;
}

OrderFit stored_order_fit(const Record& r) {
  OrderFit f;
  f.valid = r.flag("valid");
  f.order = r.number("order");
  f.order_low = r.number("order_low");
  f.order_high = r.number("order_high");
  f.points = static_cast<int>(stored_count(r, "points", kMostFitPoints));
  f.r_squared = r.number("r_squared");
  f.constant = r.number("constant");
  if (r.has_text("problem")) f.problem = r.text("problem");
  if (r.has_number("failed_points")) f.failed_points = static_cast<int>(stored_count(r, "failed_points", kMostFitPoints));
  if (r.has_number("nonpositive_points")) f.nonpositive_points = static_cast<int>(stored_count(r, "nonpositive_points", kMostFitPoints));
  read_order_shape(r, f);
  if (r.has("shape_tested")) {
    f.curvature_f = r.number("curvature_f");
    f.curvature_f_critical = r.number("curvature_f_critical");
  }
  f.pairwise = list_values(r.table("pairwise"));
  if (r.has("correction_tested")) {
    f.corrected = r.flag("corrected");
    f.f_statistic = r.number("f_statistic");
    f.f_critical = r.number("f_critical");
    if (f.corrected) {
      f.correction = r.number("correction");
      f.single_order = r.number("single_order");
      f.single_low = r.number("single_low");
      f.single_high = r.number("single_high");
    }
  }
  return f;
}

void read_order_shape(const Record& r, OrderFit& f) {
  if (!r.has("shape_tested")) return;
  f.shape_tested = r.flag("shape_tested");
  f.curved = r.flag("curved");
  f.local_order_coarse = r.number("local_order_coarse");
  f.local_order_fine = r.number("local_order_fine");
}

OrderJudgement stored_judgement(const Record& v) {
  OrderJudgement j;
  j.expected_order = v.number("expected_order");
  j.tolerance = v.number("tolerance");
  j.minimum_order = v.number("minimum_order");
  return j;
}

Table value_list(const std::vector<double>& values, const std::string& column) {
  Table t;
  t.columns = {column};
  t.values = values;
  // Lists under the default name are the studies' grid sizes, step counts and σ fractions:
  // dimensionless. A named column ("dt_s") carries its unit in its name.
  if (column == "value") t.units = {"1"};
  return t;
}

std::vector<double> list_values(const Table& t) { return t.values; }

}  // namespace stoneskip
